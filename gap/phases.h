// Where the gap lies: each phase of the motion's share of the squared
// residual, before and after the effects.
#pragma once

#include <vector>

#include "replay.h"

namespace afford {

struct PhaseShare {
  Phase phase = Phase::at_rest;
  size_t samples = 0;
  double before = 0, after = 0;  // share of the squared residual, 0..1
};

// Over every sample of `replays` past its history, each phase that has
// any, the largest share `before` first. `before`, `after`: the residuals
// of each replay, sample by sample.
std::vector<PhaseShare> phase_shares(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& before,
                                     const std::vector<std::vector<double>>& after);

}  // namespace afford
