#include "derivatives.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace afford {
namespace {

// The polynomial's design over an evenly spaced window of 2m + 1 samples,
// times scaled by the half width h = m dt for conditioning.
Eigen::MatrixXd even_design(size_t m, int degree) {
  const long w = static_cast<long>(2 * m + 1);
  Eigen::MatrixXd a(w, degree + 1);
  for (long j = 0; j < w; ++j) {
    const double u = static_cast<double>(j - static_cast<long>(m)) / static_cast<double>(m);
    double p = 1;
    for (int k = 0; k <= degree; ++k, p *= u) a(j, k) = p;
  }
  return a;
}

}  // namespace

std::vector<double> derivative_weights(size_t half_width, int degree, int order, double dt) {
  const Eigen::MatrixXd a = even_design(half_width, degree);
  const Eigen::MatrixXd even = (a.transpose() * a).inverse() * a.transpose();
  const double h = static_cast<double>(half_width) * dt;
  // The polynomial in u = t / h: its order-th derivative at the middle is
  // order! times the coefficient of u^order, over h^order.
  const double scale = order == 1 ? 1 / h : 2 / (h * h);
  std::vector<double> w(static_cast<size_t>(a.rows()));
  for (size_t j = 0; j < w.size(); ++j) w[j] = scale * even(order, static_cast<long>(j));
  return w;
}

double white_noise(const std::vector<double>& y) {
  std::vector<double> d2;
  for (size_t i = 0; i + 2 < y.size(); ++i) d2.push_back(std::abs(y[i] - 2 * y[i + 1] + y[i + 2]));
  return white_noise_of_second_differences(d2);
}

double white_noise_of_second_differences(std::vector<double>& abs_d2) {
  const size_t half = abs_d2.size() / 2;
  if (half == 0) return 0;
  std::nth_element(abs_d2.begin(), abs_d2.begin() + static_cast<long>(half), abs_d2.end());
  double sum = 0;
  for (size_t i = 0; i < half; ++i) sum += abs_d2[i];
  // |X| for X normal of deviation sd, below its median 0.67449 sd, has
  // mean 4 (phi(0) - phi(0.674490)) sd = 0.324663 sd; X = s sqrt(6).
  constexpr double kLowerHalfMean = 0.324663;
  return sum / static_cast<double>(half) / (kLowerHalfMean * std::sqrt(6.0));
}

double sample_step(const std::vector<double>& t) {
  if (t.size() < 2) return 0.0;
  std::vector<double> steps(t.size() - 1);
  for (size_t i = 0; i + 1 < t.size(); ++i) steps[i] = t[i + 1] - t[i];
  std::nth_element(steps.begin(), steps.begin() + static_cast<long>(steps.size() / 2), steps.end());
  const double median = steps[steps.size() / 2];
  // The mean of the steps but the gaps: on an evenly sampled trace the
  // mean itself, to the last bit (times like i * 1e-3 differ by rounding).
  double span = t.back() - t.front();
  size_t count = t.size() - 1;
  for (size_t i = 0; i + 1 < t.size(); ++i) {
    if (t[i + 1] - t[i] <= kRecordedApart * median) continue;
    span -= t[i + 1] - t[i];
    --count;
  }
  return span / static_cast<double>(count);
}

Derivatives local_derivatives(const std::vector<double>& t, const std::vector<double>& y, double window,
                              int wanted_degree) {
  const size_t n = t.size();
  const double dt = sample_step(t);
  // At least enough samples each side for the polynomial, at most the trace.
  const size_t wanted =
      std::max<size_t>(static_cast<size_t>(wanted_degree / 2 + 1), static_cast<size_t>(std::lround(window / dt)));
  const size_t m = std::min(wanted, (n - 1) / 2);
  const int degree = static_cast<int>(std::min<size_t>(static_cast<size_t>(wanted_degree), 2 * m));
  Derivatives d;
  d.rate.resize(n);
  d.accel.resize(n);
  d.misfit.resize(n);
  d.half_width = m;
  d.degree = degree;
  const long w = static_cast<long>(2 * m + 1);
  // The fit's coefficients as weights on the window's samples, for a
  // window of evenly spaced samples (most are): one dot product a sample.
  Eigen::MatrixXd a(w, degree + 1);
  auto design = [&](size_t from, size_t i, double h) {
    for (long j = 0; j < w; ++j) {
      const double u = (t[from + static_cast<size_t>(j)] - t[i]) / h;
      double p = 1;
      for (int k = 0; k <= degree; ++k, p *= u) a(j, k) = p;
    }
  };
  const double even_h = static_cast<double>(m) * dt;
  a = even_design(m, degree);
  const Eigen::MatrixXd cov = (a.transpose() * a).inverse();
  const Eigen::MatrixXd even = cov * a.transpose();  // coefficients = even * window
  d.rate_noise_gain = degree >= 1 ? std::sqrt(cov(1, 1)) / even_h : 0.0;
  d.accel_noise_gain = degree >= 2 ? 2 * std::sqrt(cov(2, 2)) / (even_h * even_h) : 0.0;
  // What the polynomial leaves of the window: (I - A (A'A)^-1 A') b; pure
  // noise leaves (w - degree - 1) / w of its variance.
  const Eigen::MatrixXd leaves = Eigen::MatrixXd::Identity(w, w) - a * even;
  d.misfit_noise_gain = std::sqrt(static_cast<double>(w - degree - 1) / static_cast<double>(w));
  Eigen::VectorXd b(w);
  for (size_t i = 0; i < n; ++i) {
    // The window keeps its width at the ends, shifted inside the trace.
    const size_t from = std::min(i >= m ? i - m : 0, n - 1 - 2 * m);
    for (long j = 0; j < w; ++j) b(j) = y[from + static_cast<size_t>(j)];
    bool evenly = from + m == i;
    for (long j = 0; evenly && j < w; ++j) {
      const double off = t[from + static_cast<size_t>(j)] - t[i] - static_cast<double>(j - static_cast<long>(m)) * dt;
      evenly = std::abs(off) <= 1e-6 * dt;
    }
    Eigen::VectorXd c;
    double h = even_h;
    if (evenly) {
      c = even.topRows(std::min(degree + 1, 3)) * b;
      d.misfit[i] = std::sqrt((leaves * b).squaredNorm() / static_cast<double>(w));
    } else {
      // Times relative to sample i, scaled by the window for conditioning.
      h = std::max(t[from + 2 * m] - t[from], 1e-300) / 2;
      design(from, i, h);
      c = a.colPivHouseholderQr().solve(b);
      d.misfit[i] = std::sqrt((b - a * c).squaredNorm() / static_cast<double>(w));
    }
    d.rate[i] = degree >= 1 ? c(1) / h : 0.0;
    d.accel[i] = degree >= 2 ? 2 * c(2) / (h * h) : 0.0;
  }
  return d;
}

}  // namespace afford
