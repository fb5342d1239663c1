// A force sensor's gain error is outside the library, yet what it leaves
// (the effort scaled by a few per cent) is what some named effects fit
// over a short travel: one way up a weight's cosine, a preload or an
// actee's stiffer law. Before an effect is named, the data is asked
// whether one gain on the effort explains it as well (gap/README.md).
#pragma once

#include <vector>

#include "judge.h"
#include "replay.h"

namespace afford {

// The nominal model's effort scaled by (1 + gain), one gain fitted on the
// training blocks of each fold and judged on the fold's own, by weighted
// least squares on the nominal residual (its column the nominal effort).
struct GainFit {
  double gain = 0;         // fitted on every block, dimensionless
  std::vector<double> sq;  // weighted squared errors (N^2) of the held-out fitted samples, fold by fold
  double weights = 0;      // the held-out samples' weights
};

// `residual[i]`: the nominal model's residual of replay i (N, 0 where not
// fitted); `judged[f]`: the replays fold f judges, the others training it.
// The squared errors are listed as the diagnosis scores a set: fold by
// fold, each judged replay's fitted samples in order.
GainFit held_out_gain(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& residual,
                      const std::vector<std::vector<size_t>>& judged);

// Whether one gain explains the gap as well as `set`, judged as a
// runner-up is judged: it cuts the held-out error of the nominal model
// nearly as far, and the held-out samples do not tell it from the set.
// Where the set is judged (the actee's contact, `contact`, for an actee's
// law) and, since a gain scales every reading, over every sample too.
// A gain beyond what a calibration may be off by is no look-alike.
struct GainAlike {
  double gain = 0;  // the relative error of the reading (+0.06: 6 % high)
  bool as_good = false;
};
GainAlike gain_alike_of(const Judge& judge, const Scored& nominal, const Scored& set, bool contact);

}  // namespace afford
