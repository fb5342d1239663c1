// Specimens that differ: five nuts of one kind are five stiffnesses. When
// one model cannot fit such traces together, the shape of the actee's law
// can still be judged on traces its fit never saw: each trace keeps a
// stiffness of its own (a factor fitted on that trace, for the nominal law
// and the power law alike: the specimen's, not the model's), and the power
// law's exponent is fitted on the other traces, then judged on each in turn.
//
// A soft toe has two readings: the law's shape (a power above 1), or a
// specimen that seats after the trace's zero (a rough shell crushed before
// it bears; testing machines' "toe compensation" moves the zero to where
// the load builds). The second judging gives each trace a zero of its own
// too, for both laws, and says what the exponent is then.
#pragma once

#include <vector>

#include "fit.h"
#include "replay.h"

namespace afford {

// One way of judging the power law's exponent held out.
struct ShapeJudged {
  double exponent = 0;        // the power law's, fitted on every trace
  double exponent_sigma = 0;  // its standard error: the jackknife over the leave-one-out fits
  std::vector<double> stiffness_factor;  // per trace: its own stiffness over the nominal's (nominal law)
  std::vector<double> zero;  // m, per trace: where its power law starts (held-out exponent; 0 without own zeros)
  // N, held out, weighted as in the fits: the nominal law and the power law
  // of the other traces' exponent, each with the judged trace's own
  // stiffness (and zero).
  double rmse_before = 0, rmse_after = 0;
  double shrink = 0;  // 1 - after / before
};

struct SpecimenShape {
  bool computed = false;
  ShapeJudged own_stiffness;  // each trace its own stiffness
  ShapeJudged own_zero;       // each trace its own stiffness and zero
  // N, measured - nominal law with each trace's own stiffness, the weighted
  // mean over the first and over the last third of each trace's deflection:
  // a soft toe is negative in the first, a stiffening law positive in the last.
  double first_third = 0, last_third = 0;
};

// Needs two or more replays with the actee deflected; `fitter` may be any
// fitter of these replays (its training split is not used).
SpecimenShape specimen_shape(const Fitter& fitter, const std::vector<Replay>& replays);

}  // namespace afford
