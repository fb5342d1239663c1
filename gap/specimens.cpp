#include "specimens.h"

#include <algorithm>
#include <cmath>

namespace afford {
namespace {

// The exponent judged held out on the `loaded` replays, each with its own
// stiffness, and its own zero where `own_zeros`.
ShapeJudged judge_shape(const Fitter& fitter, const std::vector<size_t>& loaded, bool own_zeros) {
  ShapeJudged out;
  double sq_before = 0, sq_after = 0, weights = 0;
  std::vector<double> left_out;  // each trace's exponent fitted without it
  for (size_t i : loaded) {
    std::vector<size_t> others;
    for (size_t j : loaded) {
      if (j != i) others.push_back(j);
    }
    const double n = fitter.shared_exponent(others, own_zeros);
    left_out.push_back(n);
    const double zero_before = own_zeros ? fitter.own_zero(i, 0.0) : 0.0;
    const double zero_after = own_zeros ? fitter.own_zero(i, n) : 0.0;
    double factor = 0, w = 0;
    sq_before += fitter.scaled_actee_rss(i, 0.0, &factor, &w, nullptr, zero_before);
    out.stiffness_factor.push_back(factor);
    out.zero.push_back(zero_after);
    weights += w;
    sq_after += fitter.scaled_actee_rss(i, n, &factor, &w, nullptr, zero_after);
  }
  out.exponent = fitter.shared_exponent(loaded, own_zeros);
  // Jackknife: sqrt((k - 1) / k * sum (n_i - mean)^2) over the k left-out fits.
  const double k = static_cast<double>(left_out.size());
  double mean = 0;
  for (double n : left_out) mean += n / k;
  double spread = 0;
  for (double n : left_out) spread += (n - mean) * (n - mean);
  out.exponent_sigma = std::sqrt((k - 1) / k * spread);
  out.rmse_before = weights > 0 ? std::sqrt(sq_before / weights) : 0.0;
  out.rmse_after = weights > 0 ? std::sqrt(sq_after / weights) : 0.0;
  out.shrink = out.rmse_before > 0 ? 1 - out.rmse_after / out.rmse_before : 0.0;
  return out;
}

}  // namespace

SpecimenShape specimen_shape(const Fitter& fitter, const std::vector<Replay>& replays) {
  SpecimenShape out;
  std::vector<size_t> loaded;  // the replays with the actee deflected where fitted
  for (size_t i = 0; i < replays.size(); ++i) {
    const Replay& r = replays[i];
    bool any = false;
    for (size_t s = 0; s < r.t.size(); ++s) any = any || (r.fitted[s] && r.deflection[s] > 0);
    if (any) loaded.push_back(i);
  }
  if (loaded.size() < 2) return out;
  out.own_stiffness = judge_shape(fitter, loaded, false);
  out.own_zero = judge_shape(fitter, loaded, true);

  // Where the nominal law misses, with each trace's own stiffness.
  double sum_toe = 0, w_toe = 0, sum_top = 0, w_top = 0;
  std::vector<double> residual;
  for (size_t i : loaded) {
    double factor = 0, w = 0;
    fitter.scaled_actee_rss(i, 0.0, &factor, &w, &residual);
    const Replay& r = replays[i];
    double most = 0;
    for (size_t s = 0; s < r.t.size(); ++s) {
      if (r.fitted[s]) most = std::max(most, r.deflection[s]);
    }
    for (size_t s = 0; s < r.t.size(); ++s) {
      if (!r.fitted[s] || !(r.deflection[s] > 0)) continue;
      if (r.deflection[s] <= most / 3) {
        sum_toe += r.weight[s] * residual[s];
        w_toe += r.weight[s];
      } else if (r.deflection[s] >= 2 * most / 3) {
        sum_top += r.weight[s] * residual[s];
        w_top += r.weight[s];
      }
    }
  }
  out.first_third = w_toe > 0 ? sum_toe / w_toe : 0.0;
  out.last_third = w_top > 0 ? sum_top / w_top : 0.0;
  out.computed = true;
  return out;
}

}  // namespace afford
