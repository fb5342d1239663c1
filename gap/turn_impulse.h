// What the turns of the motion say of an arm's inertia. An arm's inertia
// pushes hardest where the motion turns about, and there friction turns
// over (sticks, creeps, breaks away), which no term models: those samples
// are left out of every fit (replay.h, Phase::reversal), and where the
// strokes between the turns run at an even speed the fits never see the
// inertia. Across a whole turn the momentum theorem needs no acceleration:
// the torque the model leaves over, averaged over the turn, is the missing
// inertia times the change of speed over the turn's duration, with the
// speeds read where they are resolved, on either side. Friction, turning
// over from one side to the other inside it, adds only what its turn-over
// is off centre.
#pragma once

#include <vector>

#include "replay.h"

namespace afford {

struct TurnImpulse {
  size_t turns = 0;    // turns between fitted samples, free of the actee, a limit, a break and a time gap
  double inertia = 0;  // kg*m^2 beyond the model's, least squares over the turns
  double sigma = 0;    // kg*m^2, its standard error, from the turns' scatter about the fit
};

// From every lever replay's torque left over by a model (`left_over[i]`,
// N*m at every sample of replay i, unfitted samples too). Fewer than three
// turns: turns counted, nothing estimated.
TurnImpulse turn_impulse(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& left_over);

}  // namespace afford
