// The acceleration from the widest window the motion allows
// (gap/smooth_acceleration.h): a slow motion under white angle noise gets
// the wide window and its far smaller noise, inside each stroke of a
// trace recorded in strokes; a ringing the wide window would smear keeps
// the narrow one; with no noise nothing changes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "derivatives.h"
#include "smooth_acceleration.h"
#include "test_util.h"

namespace afford::test {
namespace {


double norm(const std::vector<double>& w) {
  double s = 0;
  for (double v : w) s += v * v;
  return std::sqrt(s);
}

TEST(SmoothAcceleration, TheWeightsDifferentiateAParabolaTwice) {
  // On y = a + b t + c t^2 sampled 1 ms apart about the middle, the
  // weights must give 2c: sum w = 0, sum w t = 0, sum w t^2 / 2 = 1.
  for (size_t m : {25u, 100u}) {
    const std::vector<double> w = acceleration_weights(m, 6, 1e-3);
    ASSERT_EQ(w.size(), 2 * m + 1);
    double s0 = 0, s1 = 0, s2 = 0;
    for (size_t j = 0; j < w.size(); ++j) {
      const double t = (static_cast<double>(j) - static_cast<double>(m)) * 1e-3;
      s0 += w[j];
      s1 += w[j] * t;
      s2 += w[j] * t * t / 2;
    }
    EXPECT_NEAR(s0, 0, 1e-6 * norm(w)) << m;
    EXPECT_NEAR(s1, 0, 1e-9 * norm(w)) << m;
    EXPECT_NEAR(s2, 1, 1e-9) << m;
  }
}

TEST(SmoothAcceleration, ASlowMotionGetsTheWideWindowAndItsSmallNoise) {
  // A 0.5 Hz sine of 0.3 rad, 10 s at 1 kHz, with 3e-4 rad of white noise:
  // its acceleration, 0.3 (pi)^2 = 2.96 rad/s^2 at most, is below what
  // the +-25 ms window passes of the noise (about 3.5 rad/s^2); the
  // +-200 ms window passes some 170 times less and follows the sine
  // (its degree-6 polynomial misses (pi 0.2)^7 / 7! of it, 1e-5).
  const int n = 10000;
  std::vector<double> t(n), y(n), truth(n);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 3e-4);
  for (int i = 0; i < n; ++i) {
    t[i] = i * 1e-3;
    y[i] = 0.3 * std::sin(kPi * t[i]) + noise(random);
    truth[i] = -0.3 * kPi * kPi * std::sin(kPi * t[i]);
  }
  const Derivatives narrow = local_derivatives(t, y);
  const SmoothAcceleration smooth = smooth_acceleration(t, y, 3e-4, narrow);
  const double wide_gain = norm(acceleration_weights(200, 6, 1e-3));
  double narrow_error = 0, smooth_error = 0;
  int inside = 0, wide = 0;
  for (int i = 400; i < n - 400; ++i, ++inside) {
    narrow_error += std::pow(narrow.accel[i] - truth[i], 2);
    smooth_error += std::pow(smooth.accel[i] - truth[i], 2);
    if (smooth.noise_gain[i] == wide_gain) ++wide;
  }
  EXPECT_GT(wide, inside * 95 / 100);
  narrow_error = std::sqrt(narrow_error / inside);
  smooth_error = std::sqrt(smooth_error / inside);
  EXPECT_NEAR(narrow_error, 3e-4 * norm(acceleration_weights(25, 6, 1e-3)), 0.1 * narrow_error);
  EXPECT_LT(smooth_error, 1.5 * 3e-4 * wide_gain);
  EXPECT_LT(smooth_error, narrow_error / 50);
}

TEST(SmoothAcceleration, StrokesRecordedApartGetTheWideWindowInsideEachStroke) {
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
  const SmoothAcceleration smooth = smooth_acceleration(t, y, 3e-4, narrow);
  const double wide_gain = norm(acceleration_weights(200, 6, 1e-3));
  const double narrow_gain = norm(acceleration_weights(25, 6, 1e-3));
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

TEST(SmoothAcceleration, ARingingKeepsTheNarrowWindow) {
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
  const SmoothAcceleration smooth = smooth_acceleration(t, y, 1e-4, narrow);
  double error = 0;
  int count = 0;
  for (int i = 2100; i < 2900; ++i, ++count) {
    EXPECT_EQ(smooth.accel[i], narrow.accel[i]) << t[i];
    error += std::pow(smooth.accel[i] - truth[i], 2);
  }
  EXPECT_LT(std::sqrt(error / count), 0.1 * 32);
  // Well away from it the arm is still, and the wide window is taken.
  EXPECT_LT(smooth.noise_gain[4000], smooth.noise_gain[2500] / 50);
}

TEST(SmoothAcceleration, WithNoNoiseEverySampleKeepsTheNarrowWindow) {
  std::vector<double> t(1000), y(1000);
  for (int i = 0; i < 1000; ++i) {
    t[i] = i * 1e-3;
    y[i] = std::sin(3 * t[i]);
  }
  const Derivatives narrow = local_derivatives(t, y);
  const SmoothAcceleration smooth = smooth_acceleration(t, y, 0.0, narrow);
  EXPECT_EQ(smooth.accel, narrow.accel);
  const double gain = norm(acceleration_weights(25, 6, 1e-3));
  for (double g : smooth.noise_gain) EXPECT_DOUBLE_EQ(g, gain);
}

}  // namespace
}  // namespace afford::test
