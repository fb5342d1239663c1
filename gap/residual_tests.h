// Tests of a residual's structure, over the fitted samples of replays:
// whiteness (Ljung-Box), what it moves with, and whether one set of
// held-out errors is significantly worse than another.
#pragma once

#include <string>
#include <vector>

#include "replay.h"

namespace afford {

// The whiteness of the held-out residual (Ljung-Box over 20 lags) and what
// it moves with.
struct ResidualTest {
  double q = 0;          // the Ljung-Box statistic
  double threshold = 0;  // its 99 % point for white noise
  bool white = false;
  std::string follows;   // the signal it correlates with most ("the direction of motion", ...)
  double correlation = 0;
};

// Ljung-Box over 20 lags of the residuals of the replays `which`, within
// their fitted stretches. `noise`, where given: the noise the model's
// prediction carries by itself, sample by sample, whose autocorrelation is
// taken off the residual's (noise that is not white is not structure).
// Sets q, threshold and white.
ResidualTest whiteness(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& residual,
                       const std::vector<size_t>& which, const std::vector<std::vector<double>>* noise = nullptr);

// What a residual moves with most: direction, speed, acceleration, angle
// (or displacement), over the fitted samples of the replays.
void what_it_follows(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& residual,
                     std::string* name, double* corr);

// How many standard errors worse `b` predicts the held-out samples than
// `a` (squared errors, sample by sample, the same samples in the same
// order), from the means of consecutive batches.
double paired_t(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace afford
