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

TEST(Derivatives, ALinesBendOverTenMillisecondsPassesTheNoiseWorkedOutByHand) {
  // Degree 2 over j = -10..10 samples of 1 ms: the rate is sum(j y_j) /
  // (dt sum j^2), sum j^2 = 770, its noise gain 1 / (1e-3 sqrt 770) =
  // 36.04 s^-1; the acceleration is 2 c2 / dt^2 with c2 = sum((j^2 -
  // 770/21) y_j) / sum((j^2 - 770/21)^2), that sum 2 * 25333 - 770^2 / 21
  // = 22433.3, its gain 2 / (1e-6 sqrt 22433.3) = 13353 s^-2. A parabola
  // it follows exactly: y = 1 + 2 t - 5 t^2, y' = 2 - 10 t, y'' = -10.
  const std::vector<double> t = times(200, 1e-3);
  std::vector<double> y;
  for (double s : t) y.push_back(1 + 2 * s - 5 * s * s);
  const Derivatives d = local_derivatives(t, y, 0.01, 2);
  EXPECT_EQ(d.half_width, 10u);
  EXPECT_EQ(d.degree, 2);
  EXPECT_NEAR(d.rate_noise_gain, 1 / (1e-3 * std::sqrt(770.0)), 1e-9);
  EXPECT_NEAR(d.accel_noise_gain, 2 / (1e-6 * std::sqrt(2 * 25333.0 - 770.0 * 770.0 / 21)), 1e-6);
  for (size_t i = 0; i < t.size(); i += 13) {
    EXPECT_NEAR(d.rate[i], 2 - 10 * t[i], 1e-9) << t[i];
    EXPECT_NEAR(d.accel[i], -10, 1e-6) << t[i];
    EXPECT_NEAR(d.misfit[i], 0, 1e-12) << t[i];
  }
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

TEST(Derivatives, TheNoiseIsTheSmallerHalfsMeanOfTheSecondDifferences) {
  // Of 0, 3, 1, 2 the smaller half is 0 and 1, mean 0.5; a normal law's
  // |X| below its median has mean 0.324663 of its deviation, and second
  // differences have sqrt(6) times the noise's: 0.5 / (0.324663 sqrt 6).
  std::vector<double> d2 = {0, 3, 1, 2};
  EXPECT_NEAR(white_noise_of_second_differences(d2), 0.5 / (0.324663 * std::sqrt(6.0)), 1e-12);
  std::vector<double> none;
  EXPECT_EQ(white_noise_of_second_differences(none), 0.0);
}

// 20000 samples of a slow sine under white noise of `noise`, 5 higher
// in every other stretch of `flip_every` samples (0: never), read in
// counts of `count` (0: as it is).
std::vector<double> noisy_signal(double noise, double count, int flip_every = 0) {
  std::mt19937 random(11);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<double> y;
  for (int i = 0; i < 20000; ++i) {
    double v = std::sin(i * 1e-3) + noise * unit(random);
    if (flip_every > 0 && (i / flip_every) % 2 == 1) v += 5;
    y.push_back(count > 0 ? count * std::round(v / count) : v);
  }
  return y;
}

TEST(Derivatives, ASignalCountedInStepsHasItsWholeNoise) {
  // White noise of 0.06 N read by a converter in 0.0234 N steps: the
  // noise the residual carries is sqrt(0.06^2 + 0.0234^2 / 12) = 0.06038
  // N. Every second difference is a whole number of steps, and their
  // median falls on one: 4 steps give 0.0567 N, 6 % short, which made
  // an effect-free trace's residual read 1.16 times its noise
  // (development seed 6005, both engines).
  const double whole = std::sqrt(0.06 * 0.06 + 0.0234 * 0.0234 / 12);
  EXPECT_NEAR(white_noise(noisy_signal(0.06, 0.0234)), whole, 0.02 * whole);
  EXPECT_NEAR(white_noise(noisy_signal(0.06, 0)), 0.06, 0.02 * 0.06);
}

TEST(Derivatives, AFewJumpsDoNotMoveTheNoise) {
  // A jump of 5 every 250 samples (a friction's flip at each reversal of
  // strokes of 0.5 s) gives two large second differences each, 0.8 % of
  // them; the smaller half does not hold them.
  EXPECT_NEAR(white_noise(noisy_signal(0.06, 0, 250)), 0.06, 0.02 * 0.06);
}

}  // namespace
}  // namespace afford::test
