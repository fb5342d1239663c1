#include "derivatives.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace afford {
namespace {

constexpr double kWindow = 0.025;  // s, each side
constexpr int kDegree = 6;

}  // namespace

Derivatives local_derivatives(const std::vector<double>& t, const std::vector<double>& y) {
  const size_t n = t.size();
  const double dt = (t.back() - t.front()) / static_cast<double>(n - 1);
  // At least enough samples each side for the polynomial, at most the trace.
  const size_t wanted = std::max<size_t>(kDegree / 2 + 1, static_cast<size_t>(std::lround(kWindow / dt)));
  const size_t m = std::min(wanted, (n - 1) / 2);
  const int degree = static_cast<int>(std::min<size_t>(kDegree, 2 * m));
  Derivatives d;
  d.rate.resize(n);
  d.accel.resize(n);
  d.half_width = m;
  Eigen::MatrixXd a(2 * m + 1, degree + 1);
  Eigen::VectorXd b(2 * m + 1);
  for (size_t i = 0; i < n; ++i) {
    // The window keeps its width at the ends, shifted inside the trace.
    const size_t from = std::min(i >= m ? i - m : 0, n - 1 - 2 * m);
    // Times relative to sample i, scaled by the window for conditioning.
    const double h = std::max(t[from + 2 * m] - t[from], 1e-300) / 2;
    for (size_t j = 0; j <= 2 * m; ++j) {
      const double u = (t[from + j] - t[i]) / h;
      double p = 1;
      for (int k = 0; k <= degree; ++k, p *= u) a(static_cast<long>(j), k) = p;
      b(static_cast<long>(j)) = y[from + j];
    }
    const Eigen::VectorXd c = a.colPivHouseholderQr().solve(b);
    d.rate[i] = degree >= 1 ? c(1) / h : 0.0;
    d.accel[i] = degree >= 2 ? 2 * c(2) / (h * h) : 0.0;
    if (i == n / 2) {  // an inside sample: the rate's variance per unit noise
      const Eigen::MatrixXd cov = (a.transpose() * a).inverse();
      d.rate_noise_gain = std::sqrt(cov(1, 1)) / h;
      if (degree >= 2) d.accel_noise_gain = 2 * std::sqrt(cov(2, 2)) / (h * h);
    }
  }
  return d;
}

}  // namespace afford
