// Specimens that differ: five nuts of one kind are five stiffnesses. When
// one model cannot fit such traces together, the shape of the actee's law
// can still be judged on traces its fit never saw: each trace keeps a
// stiffness of its own (a factor fitted on that trace, for the nominal law
// and the power law alike: the specimen's, not the model's), and the power
// law's exponent is fitted on the other traces, then judged on each in turn.
#pragma once

#include <vector>

#include "fit.h"
#include "replay.h"

namespace afford {

struct SpecimenShape {
  bool computed = false;
  double exponent = 0;        // the power law's, fitted on every trace
  double exponent_sigma = 0;  // its standard error: the jackknife over the leave-one-out fits
  std::vector<double> stiffness_factor;  // per trace: its own stiffness over the nominal's (nominal law)
  // N, held out, weighted as in the fits: the nominal law and the power law
  // of the other traces' exponent, each with the judged trace's own stiffness.
  double rmse_before = 0, rmse_after = 0;
  double shrink = 0;  // 1 - after / before
  // N, measured - nominal law with each trace's own stiffness, the weighted
  // mean over the first and over the last third of each trace's deflection:
  // a soft toe is negative in the first, a stiffening law positive in the last.
  double first_third = 0, last_third = 0;
};

// Needs two or more replays with the actee deflected; `fitter` may be any
// fitter of these replays (its training split is not used).
SpecimenShape specimen_shape(const Fitter& fitter, const std::vector<Replay>& replays);

}  // namespace afford
