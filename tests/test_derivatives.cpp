// The rate and acceleration of a measured signal (gap/derivatives.h),
// against polynomials and sines worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "derivatives.h"
#include "test_util.h"

namespace afford::test {
namespace {


std::vector<double> times(int n, double dt) {
  std::vector<double> t(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) t[static_cast<size_t>(i)] = i * dt;
  return t;
}

TEST(Derivatives, APolynomialOfTheFitsDegreeIsDifferentiatedExactly) {
  // y = 2 + t - 3 t^3 + 0.5 t^6: y' = 1 - 9 t^2 + 3 t^5, y'' = -18 t + 15 t^4.
  const std::vector<double> t = times(400, 1e-3);
  std::vector<double> y;
  for (double s : t) y.push_back(2 + s - 3 * s * s * s + 0.5 * std::pow(s, 6));
  const Derivatives d = local_derivatives(t, y);
  EXPECT_EQ(d.half_width, 25u);  // +-25 ms at 1 kHz
  for (size_t i = 0; i < t.size(); i += 37) {  // the ends too: the window shifts inside
    const double s = t[i];
    EXPECT_NEAR(d.rate[i], 1 - 9 * s * s + 3 * std::pow(s, 5), 1e-7) << s;
    EXPECT_NEAR(d.accel[i], -18 * s + 15 * std::pow(s, 4), 1e-4) << s;
  }
}

TEST(Derivatives, UnevenSamplesAreFittedOnTheirOwnTimes) {
  // A logger that drifts: 1 ms steps with a slow 0.2 ms wobble; y = t^3,
  // y' = 3 t^2, y'' = 6 t, exact for the degree-6 fit on any times.
  std::vector<double> t, y;
  for (int i = 0; i < 300; ++i) {
    t.push_back(i * 1e-3 + 2e-4 * std::sin(i * 0.1));
    y.push_back(t.back() * t.back() * t.back());
  }
  const Derivatives d = local_derivatives(t, y);
  for (size_t i = 0; i < t.size(); i += 23) {
    EXPECT_NEAR(d.rate[i], 3 * t[i] * t[i], 1e-8) << t[i];
    EXPECT_NEAR(d.accel[i], 6 * t[i], 1e-5) << t[i];
  }
}

TEST(Derivatives, ARingingAt20HzKeepsItsAcceleration) {
  // 0.01 rad at 20 Hz: the acceleration is -0.01 (2 pi 20)^2 sin(w t),
  // 157.9 rad/s^2 at its peak; the fit passes it within 1 % (the filter's
  // response there is 0.992; a double central difference over +-5 ms
  // would lose 13 %).
  const std::vector<double> t = times(1000, 1e-3);
  const double w = 2 * kPi * 20;
  std::vector<double> y;
  for (double s : t) y.push_back(0.01 * std::sin(w * s));
  const Derivatives d = local_derivatives(t, y);
  for (size_t i = 100; i < 900; ++i) {
    EXPECT_NEAR(d.accel[i], -0.01 * w * w * std::sin(w * t[i]), 0.01 * 0.01 * w * w) << t[i];
  }
}

TEST(Derivatives, TheRatesNoiseIsTheReportedGainTimesTheSignals) {
  // White noise of 1e-4 alone: the rate's deviation over the inside
  // samples is rate_noise_gain * 1e-4 (within the spread of 20,000 samples).
  const std::vector<double> t = times(20000, 1e-3);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 1e-4);
  std::vector<double> y;
  for (size_t i = 0; i < t.size(); ++i) y.push_back(noise(random));
  const Derivatives d = local_derivatives(t, y);
  double sq = 0;
  size_t n = 0;
  for (size_t i = d.half_width; i + d.half_width < t.size(); ++i, ++n) sq += d.rate[i] * d.rate[i];
  EXPECT_NEAR(std::sqrt(sq / static_cast<double>(n)), d.rate_noise_gain * 1e-4, 0.05 * d.rate_noise_gain * 1e-4);
}

TEST(Derivatives, AShortOrCoarseTraceStillGetsAFit) {
  // 100 Hz: +-25 ms is under 4 samples, so the fit takes 4 each side.
  const std::vector<double> t = times(60, 1e-2);
  std::vector<double> y;
  for (double s : t) y.push_back(3 * s * s);
  const Derivatives d = local_derivatives(t, y);
  EXPECT_EQ(d.half_width, 4u);
  EXPECT_NEAR(d.rate[30], 6 * t[30], 1e-9);
  EXPECT_NEAR(d.accel[30], 6, 1e-6);
}

}  // namespace
}  // namespace afford::test
