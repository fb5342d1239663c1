// What the turns of the motion say of an arm's inertia. An arm's inertia
// pushes hardest where the motion turns about, and there friction turns
// over (sticks, creeps, breaks away), which no term models: those samples
// are left out of every fit (replay.h, Phase::reversal), and where the
// strokes between the turns run at an even speed the fits never see the
// inertia. Over a stretch of motion the momentum theorem needs no
// acceleration: the torque the model leaves over, averaged over the
// stretch, is the missing inertia times the change of speed over the
// stretch's duration, the speeds read at its ends. Each turn, from the
// last fitted sample before it to the first after it, is taken in its
// stretches in motion, each on its own: while the arm stands still
// friction holds any value up to its limit, and in motion it slides on
// the side the rate says.
#pragma once

#include <vector>

#include "replay.h"

namespace afford {

struct TurnImpulse {
  // The turns' stretches in motion, between fitted samples, free of the
  // actee, a limit, the break and a time gap.
  size_t stretches = 0;
  double inertia = 0;  // kg*m^2 beyond the model's, least squares over the stretches
  double sigma = 0;    // kg*m^2, its standard error, from the stretches' scatter about the fit
};

// From every lever replay's torque left over by a model (`left_over[i]`,
// N*m at every sample of replay i, unfitted samples too). Fewer than three
// stretches: counted, nothing estimated.
TurnImpulse turn_impulse(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& left_over);

}  // namespace afford
