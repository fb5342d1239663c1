// The rate and the acceleration from the widest window the motion allows
// (gap/smooth_derivative.h): a slow motion under white angle noise gets
// the wide window and its far smaller noise, inside each stroke of a
// trace recorded in strokes; a ringing the wide window would smear keeps
// the narrow one; with no noise nothing changes.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "derivatives.h"
#include "smooth_derivative.h"
#include "test_util.h"

namespace afford::test {
namespace {


double norm(const std::vector<double>& w) {
  double s = 0;
  for (double v : w) s += v * v;
  return std::sqrt(s);
}

TEST(SmoothDerivative, TheWeightsDifferentiateAParabola) {
  // On y = a + b t + c t^2 sampled 1 ms apart about the middle, the rate's
  // weights must give b and the acceleration's 2c: sum w t^k / k! is 1 for
  // k the derivative's order, 0 for the other k up to 2.
  for (int order : {1, 2}) {
    for (size_t m : {25u, 100u}) {
      const std::vector<double> w = derivative_weights(m, 6, order, 1e-3);
      ASSERT_EQ(w.size(), 2 * m + 1);
      std::array<double, 3> moment{};  // sum w t^k / k!
      for (size_t j = 0; j < w.size(); ++j) {
        const double t = (static_cast<double>(j) - static_cast<double>(m)) * 1e-3;
        moment[0] += w[j];
        moment[1] += w[j] * t;
        moment[2] += w[j] * t * t / 2;
      }
      for (int k = 0; k <= 2; ++k) {
        // The sums of +-1 weights times t^k cancel to rounding: relative to
        // the weights' norm times the window's reach to the power k.
        const double rounding = 1e-9 * norm(w) * std::pow(static_cast<double>(m) * 1e-3, k);
        EXPECT_NEAR(moment[static_cast<size_t>(k)], k == order ? 1.0 : 0.0, k == order ? 1e-9 : rounding)
            << "order " << order << ", m " << m << ", k " << k;
      }
    }
  }
}

// A 0.5 Hz sine of 0.3 rad, 10 s at 1 kHz, under white noise of deviation
// `noise` (rad) drawn from `seed`: the RMS errors of the narrow window's
// derivative of `order` and of the smooth one, 0.4 s and more from the
// ends, and the share of those samples that took the +-200 ms window.
struct SlowSine {
  double narrow_error = 0, smooth_error = 0, wide_share = 0;
};
SlowSine slow_sine(int order, double noise, unsigned seed) {
  const int n = 10000;
  std::vector<double> t(n), y(n), truth(n);
  std::mt19937 random(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    t[i] = i * 1e-3;
    y[i] = 0.3 * std::sin(kPi * t[i]) + noise * unit(random);
    truth[i] = order == 1 ? 0.3 * kPi * std::cos(kPi * t[i]) : -0.3 * kPi * kPi * std::sin(kPi * t[i]);
  }
  const Derivatives narrow = local_derivatives(t, y);
  const std::vector<double>& narrow_value = order == 1 ? narrow.rate : narrow.accel;
  const SmoothDerivative smooth = smooth_derivative(t, y, noise, narrow, order);
  const double wide_gain = norm(derivative_weights(200, 6, order, 1e-3));
  SlowSine out;
  int inside = 0, wide = 0;
  for (int i = 400; i < n - 400; ++i, ++inside) {
    out.narrow_error += std::pow(narrow_value[i] - truth[i], 2);
    out.smooth_error += std::pow(smooth.value[i] - truth[i], 2);
    if (smooth.noise_gain[i] == wide_gain) ++wide;
  }
  out.narrow_error = std::sqrt(out.narrow_error / inside);
  out.smooth_error = std::sqrt(out.smooth_error / inside);
  out.wide_share = static_cast<double>(wide) / inside;
  return out;
}

TEST(SmoothDerivative, ASlowMotionGetsTheRatesWideWindowAndItsSmallNoise) {
  // The rate of the slow sine under 5e-4 rad of white noise: the +-25 ms
  // window passes 5e-4 * 42 = 0.021 rad/s of it (a damping of 1.9
  // N*m*s/rad makes that 0.04 N*m), the +-200 ms one 22 times less, and
  // its degree-6 polynomial misses (pi 0.2)^6 / 6! of the rate, 3e-6 of it.
  const double narrow_gain = norm(derivative_weights(25, 6, 1, 1e-3)), wide_gain = norm(derivative_weights(200, 6, 1, 1e-3));
  EXPECT_NEAR(narrow_gain, 41.76, 0.01);  // s^-1
  EXPECT_NEAR(narrow_gain / wide_gain, 22.6, 0.6);  // about (200 / 25)^1.5
  const SlowSine e = slow_sine(1, 5e-4, 17);
  EXPECT_GT(e.wide_share, 0.95);
  EXPECT_NEAR(e.narrow_error, 5e-4 * narrow_gain, 0.1 * e.narrow_error);
  EXPECT_LT(e.smooth_error, 1.5 * 5e-4 * wide_gain);
  EXPECT_LT(e.smooth_error, e.narrow_error / 10);
}

TEST(SmoothDerivative, ASlowMotionGetsTheWideWindowAndItsSmallNoise) {
  // The slow sine's acceleration, 0.3 (pi)^2 = 2.96 rad/s^2 at most, under
  // 3e-4 rad of white noise, is below what the +-25 ms window passes of
  // the noise (about 3.5 rad/s^2); the +-200 ms window passes some 170
  // times less and follows the sine (its degree-6 polynomial misses
  // (pi 0.2)^7 / 7! of it, 1e-5).
  const SlowSine e = slow_sine(2, 3e-4, 7);
  EXPECT_GT(e.wide_share, 0.95);
  EXPECT_NEAR(e.narrow_error, 3e-4 * norm(derivative_weights(25, 6, 2, 1e-3)), 0.1 * e.narrow_error);
  EXPECT_LT(e.smooth_error, 1.5 * 3e-4 * norm(derivative_weights(200, 6, 2, 1e-3)));
  EXPECT_LT(e.smooth_error, e.narrow_error / 50);
}

TEST(SmoothDerivative, StrokesRecordedApartGetTheWideWindowInsideEachStroke) {
  // Closing-only strokes: three stretches of 2.5 s at 1 kHz, the 0.6 s
  // between them not recorded (a mean step 5 % over 1 ms). The same slow
  // sine and noise as above: inside each stretch, 0.2 s and more from its
  // ends, the +-200 ms window is taken; no window reaches across a gap.
  std::vector<double> t, y;
  std::mt19937 random(5);
  std::normal_distribution<double> noise(0.0, 3e-4);
  for (int stroke = 0; stroke < 3; ++stroke) {
    for (int i = 0; i < 2500; ++i) {
      t.push_back(stroke * 3.1 + i * 1e-3);
      y.push_back(0.3 * std::sin(kPi * t.back()) + noise(random));
    }
  }
  EXPECT_DOUBLE_EQ(sample_step(t), 1e-3);
  const Derivatives narrow = local_derivatives(t, y);
  const SmoothDerivative smooth = smooth_derivative(t, y, 3e-4, narrow, 2);
  const double wide_gain = norm(derivative_weights(200, 6, 2, 1e-3));
  const double narrow_gain = norm(derivative_weights(25, 6, 2, 1e-3));
  int inside = 0, wide = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    const double into = std::fmod(t[i] + 1e-9, 3.1);  // s into its stretch
    if (into < 0.2 - 1e-9 && into > 0.025) {
      EXPECT_GT(smooth.noise_gain[i], wide_gain) << t[i];
    }
    if (into < 0.2 || into > 2.3) continue;
    ++inside;
    if (std::abs(smooth.noise_gain[i] - wide_gain) < 1e-9 * wide_gain) ++wide;  // its step: 1 ms to rounding
  }
  EXPECT_GT(wide, inside * 9 / 10);
  EXPECT_NEAR(smooth.noise_gain[10], narrow_gain, 1e-9 * narrow_gain);  // the window shifted inside: the narrow fit
}

TEST(SmoothDerivative, ARingingKeepsTheNarrowWindow) {
  // A 20 Hz ringing of 2e-3 rad (acceleration 2e-3 (40 pi)^2 = 32 rad/s^2)
  // from 2 s to 3 s on a still arm, noise 1e-4 rad: a wide window would
  // average it away; the narrow one follows it within 1 % (derivatives.h)
  // and its noise, 1.2 rad/s^2, is far below the ringing's.
  const int n = 5000;
  std::vector<double> t(n), y(n), truth(n);
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 1e-4);
  const double w = 40 * kPi;
  for (int i = 0; i < n; ++i) {
    t[i] = i * 1e-3;
    const bool ringing = t[i] >= 2 && t[i] < 3;
    y[i] = (ringing ? 2e-3 * std::sin(w * (t[i] - 2)) : 0.0) + noise(random);
    truth[i] = ringing ? -2e-3 * w * w * std::sin(w * (t[i] - 2)) : 0.0;
  }
  const Derivatives narrow = local_derivatives(t, y);
  const SmoothDerivative smooth = smooth_derivative(t, y, 1e-4, narrow, 2);
  double error = 0;
  int count = 0;
  for (int i = 2100; i < 2900; ++i, ++count) {
    EXPECT_EQ(smooth.value[i], narrow.accel[i]) << t[i];
    error += std::pow(smooth.value[i] - truth[i], 2);
  }
  EXPECT_LT(std::sqrt(error / count), 0.1 * 32);
  // Well away from it the arm is still, and the wide window is taken.
  EXPECT_LT(smooth.noise_gain[4000], smooth.noise_gain[2500] / 50);
}

TEST(SmoothDerivative, WithNoNoiseEverySampleKeepsTheNarrowWindow) {
  std::vector<double> t(1000), y(1000);
  for (int i = 0; i < 1000; ++i) {
    t[i] = i * 1e-3;
    y[i] = std::sin(3 * t[i]);
  }
  const Derivatives narrow = local_derivatives(t, y);
  const SmoothDerivative smooth = smooth_derivative(t, y, 0.0, narrow, 2);
  EXPECT_EQ(smooth.value, narrow.accel);
  const double gain = norm(derivative_weights(25, 6, 2, 1e-3));
  for (double g : smooth.noise_gain) EXPECT_DOUBLE_EQ(g, gain);
}

}  // namespace
}  // namespace afford::test
