// Tests of a residual's structure, over the fitted samples of replays:
// whiteness (Ljung-Box), what it moves with, and whether one set of
// held-out errors is significantly worse than another.
#pragma once

#include <string>
#include <vector>

#include "replay.h"

namespace afford {

// The whiteness of the held-out residual (a portmanteau test over 20
// lags, as Ljung-Box's) and what it moves with.
struct ResidualTest {
  double q = 0;          // the sum over lags of each lag's squared excess over its Bartlett variance
  double threshold = 0;  // chi-square's 99 % point for 20 lags
  bool white = false;
  double share = 0;      // the structured share of its variance: lags 1-20's excess correlation, root mean square
  std::string follows;   // the signal it correlates with most ("the direction of motion", ...)
  double correlation = 0;
  size_t samples = 0;    // the samples tested
};

// Which fitted samples a test of structure takes: every one, or only those
// out of the actee's contact (where the tool's own effects are all there
// is to misfit).
enum class Samples { every, out_of_contact };

// Over 20 lags, the residuals of the replays `which`, within their fitted
// stretches (those of `samples`). `noise`, where given: the noise the model's prediction
// carries by itself, sample by sample, whose autocovariance (scaled to the
// residual's) is taken off the residual's, each lag's excess weighed by
// Bartlett's variance for a noise of that colour (noise that is not white
// is not structure). Without it, the residual is tested against white
// noise (Box-Pierce). Sets q, threshold, white and samples.
ResidualTest whiteness(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& residual,
                       const std::vector<size_t>& which, const std::vector<std::vector<double>>* noise = nullptr,
                       Samples samples = Samples::every);

// What a residual moves with most: direction, speed, acceleration, angle
// (or displacement), over the fitted samples of the replays.
void what_it_follows(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& residual,
                     std::string* name, double* corr);

// How many standard errors worse `b` predicts the held-out samples than
// `a` (squared errors, sample by sample, the same samples in the same
// order), from the means of consecutive batches.
double paired_t(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace afford
