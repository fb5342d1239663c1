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

// Fewer stretches than this are counted, and nothing is estimated from them.
constexpr size_t kLeastStretches = 3;

struct InertiaEstimate {
  size_t stretches = 0;
  double inertia = 0;  // kg*m^2 beyond the model's, least squares over the stretches
  double sigma = 0;    // kg*m^2, its standard error, from the stretches' scatter about the fit
};

struct TurnImpulse : InertiaEstimate {
  // The turns' stretches in motion, between fitted samples, free of the
  // actee, a limit, the break and a time gap, all together (the fields
  // above) and in two halves: where the arm slows into a turn and where
  // it speeds out of one. An inertia shows in both alike. Friction's turn
  // over biases one: a rate read over a window lags where the
  // acceleration jumps at the turn, and the model's friction keeps the old
  // side a few samples after the arm has turned (a weight and a damping
  // in closing-only strokes written by formula: 0.00057 kg*m^2 asked for
  // slowing, 0.00001 +- 0.00011 speeding, none in the truth).
  InertiaEstimate slowing, speeding;
  // N at the effort: the force the inertia asked for (all the stretches')
  // takes across a turn, RMS over the stretches of their mean
  // acceleration. Under the sensor's noise it is no gap however many
  // stretches know it (3.1e-5 kg*m^2 asked for at 6.1 standard errors,
  // 0.24 times the noise, by a MuJoCo nutcracker whose one effect was a
  // weight, development seed 6755, and named beside it).
  double force = 0;
  // Named in the verdict: asked for at over kTurnsAsk standard errors by
  // both halves alike, where the fits named no inertia (diagnose.cpp).
  bool adopted = false;
};

// Standard errors at which the turns' inertia is real: on development
// seeds no effect-free case reached 5 (none of 89 in ODE, 77 in MuJoCo;
// over 3, one and two), and four of five inertias the fits missed did.
constexpr double kTurnsAsk = 5;

// Both halves alike: they differ by under this many standard errors of
// their difference, or by under kHalvesNear of their mean. Where the
// halves are known to a hundredth, an effect outside the model biases
// them apart by a shade of what they share: an inertia with a damping or
// friction the adopted set lacks or misplaces, written by formula, asks
// for halves 2 to 14 % apart at over 3 standard errors, while a bias
// without an inertia leaves one half near nothing (the halves above
// differ by 1.9 and 6.5 times their mean).
constexpr double kHalvesAgree = 3;
constexpr double kHalvesNear = 0.5;
bool halves_agree(const TurnImpulse& t);

// From every lever replay's torque left over by a model (`left_over[i]`,
// N*m at every sample of replay i, unfitted samples too). Fewer than three
// stretches: counted, nothing estimated.
TurnImpulse turn_impulse(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& left_over);

}  // namespace afford
