#include "smooth_derivative.h"

#include <algorithm>
#include <cmath>

namespace afford {
namespace {

// s: the wider windows' half widths, each side, narrowest first; the
// polynomial's degree is the narrow window's.
constexpr double kWideWindows[] = {0.05, 0.1, 0.2};
// s, each side: the stretch over which a window's bias is averaged. The
// difference of two windows' derivatives is mostly their noise, whose
// own scatter hides a bias below it; over +-0.4 s (some 30 independent
// stretches of the narrow window) a bias as large as the noise saved
// stands four of that scatter's deviations clear.
constexpr double kBiasSpan = 0.4;

double norm(const std::vector<double>& w) {
  double s = 0;
  for (double v : w) s += v * v;
  return std::sqrt(s);
}

// One window's derivative at each sample where it is centred and evenly
// spaced (`usable`).
struct Window {
  std::vector<double> weights;
  std::vector<double> value;
  std::vector<bool> usable;
};

Window apply(const std::vector<double>& weights, const std::vector<double>& y, const std::vector<size_t>& uneven_before) {
  const size_t n = y.size(), m = weights.size() / 2;
  Window w{weights, std::vector<double>(n, 0.0), std::vector<bool>(n, false)};
  for (size_t i = m; i + m < n; ++i) {
    if (uneven_before[i + m] != uneven_before[i - m]) continue;
    double a = 0;
    for (size_t j = 0; j < weights.size(); ++j) a += weights[j] * y[i - m + j];
    w.value[i] = a;
    w.usable[i] = true;
  }
  return w;
}

}  // namespace

// Lepski's rule: from the narrow window outwards, each sample takes the
// next wider window while what the two differ by, beyond their noises,
// stays below the noise the wider one saves, and stops at the first that
// does not (a bias, once there, only grows with the window).
SmoothDerivative smooth_derivative(const std::vector<double>& t, const std::vector<double>& y, double noise,
                                   const Derivatives& narrow, int order) {
  const size_t n = t.size();
  const std::vector<double>& narrow_value = order == 1 ? narrow.rate : narrow.accel;
  SmoothDerivative out{narrow_value, std::vector<double>(n, 0.0)};
  if (n < 2 || narrow.degree < order) return out;
  const double dt = sample_step(t);
  const size_t m0 = narrow.half_width;
  Window current{derivative_weights(m0, narrow.degree, order, dt), narrow_value, std::vector<bool>(n, true)};
  std::fill(out.noise_gain.begin(), out.noise_gain.end(), norm(current.weights));
  if (!(noise > 0)) return out;

  // Steps off the even spacing: a window holding one keeps the narrow fit.
  std::vector<size_t> uneven_before(n, 0);  // uneven steps among the first i + 1 samples' steps
  for (size_t i = 0; i + 1 < n; ++i)
    uneven_before[i + 1] = uneven_before[i] + (std::abs(t[i + 1] - t[i] - dt) > 1e-6 * dt ? 1 : 0);

  std::vector<bool> widening(n, true);  // not yet stopped
  std::vector<double> excess_before(n + 1), usable_before(n + 1);
  const size_t span = static_cast<size_t>(std::lround(kBiasSpan / dt));
  for (double window : kWideWindows) {
    const size_t m = static_cast<size_t>(std::lround(window / dt));
    if (m * 2 <= current.weights.size() - 1 || 2 * m + 1 > n) break;
    Window wider = apply(derivative_weights(m, narrow.degree, order, dt), y, uneven_before);
    // The noise the two windows' difference passes: the narrower's weights
    // sit in the middle of the wider's.
    std::vector<double> difference = wider.weights;
    const size_t shift = m - current.weights.size() / 2;
    for (size_t j = 0; j < current.weights.size(); ++j) difference[shift + j] -= current.weights[j];
    const double difference_variance = std::pow(norm(difference) * noise, 2);
    const double wider_gain = norm(wider.weights);
    const double saved = (std::pow(norm(current.weights), 2) - wider_gain * wider_gain) * noise * noise;
    excess_before[0] = usable_before[0] = 0;
    for (size_t i = 0; i < n; ++i) {
      const bool both = wider.usable[i] && current.usable[i];
      const double d = both ? wider.value[i] - current.value[i] : 0.0;
      excess_before[i + 1] = excess_before[i] + (both ? d * d - difference_variance : 0.0);
      usable_before[i + 1] = usable_before[i] + (both ? 1 : 0);
    }
    const size_t reach = std::max(span, m);
    for (size_t i = 0; i < n; ++i) {
      if (!widening[i] || !wider.usable[i] || !current.usable[i]) {
        widening[i] = false;
        continue;
      }
      const size_t from = i >= reach ? i - reach : 0, to = std::min(n, i + reach + 1);
      const double count = usable_before[to] - usable_before[from];
      const double bias2 = (excess_before[to] - excess_before[from]) / count;
      if (bias2 >= saved) {
        widening[i] = false;
        continue;
      }
      out.value[i] = wider.value[i];
      out.noise_gain[i] = wider_gain;
    }
    current = std::move(wider);
  }
  return out;
}

}  // namespace afford
