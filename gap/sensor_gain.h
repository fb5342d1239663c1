// A force sensor's gain error is outside the library, yet what it leaves
// (the effort scaled by a few per cent) is what some named effects fit
// over a short travel: one way up a weight's cosine, a preload or an
// actee's stiffer law. Before an effect is named, the data is asked
// whether one gain on the effort explains it as well (gap/README.md).
#pragma once

#include <vector>

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

}  // namespace afford
