// The rate and acceleration of a measured signal, by a local polynomial
// (Savitzky-Golay's least squares, on the samples' own times): a degree-6
// polynomial over +-25 ms passes a 20 Hz oscillation's acceleration within
// 1 % (central differences of central differences over +-5 ms lose 13 %,
// with twice the noise), so an arm's inertia is seen in a servo's ringing.
#pragma once

#include <cstddef>
#include <vector>

namespace afford {

struct Derivatives {
  std::vector<double> rate;   // dy/dt
  std::vector<double> accel;  // d2y/dt2
  size_t half_width = 0;      // samples each side of the fit: nearer the ends it is one-sided
  int degree = 0;             // the polynomial's
  double rate_noise_gain = 0; // the rate's noise per unit of y's (white) noise, 1/s, inside
  double accel_noise_gain = 0;  // the acceleration's, 1/s^2, inside
  // The RMS of y about the polynomial over each sample's window, y's unit:
  // white noise of deviation s leaves about s * misfit_noise_gain; much
  // more is motion the polynomial cannot follow (a ringing faster than the
  // window resolves, a snap, a window across a break): there the rates
  // are not the motion's.
  std::vector<double> misfit;
  double misfit_noise_gain = 0;
};

// The deviation of a signal's white noise: white noise of deviation s
// gives second differences of deviation s * sqrt(6), which a smooth
// signal hardly adds to. The smaller half of their absolute values is not
// moved by a few jumps (a stop, a reversal, a crack). Its mean is taken,
// not its largest value (the median): a signal counted in steps makes
// every second difference a whole number of steps, and the median falls
// on one (0.0567 N for white noise of 0.0604 N counted in 0.0234 N
// steps).
double white_noise(const std::vector<double>& y);

// The same from the absolute second differences themselves (their order
// is changed): 0 where there are none.
double white_noise_of_second_differences(std::vector<double>& abs_d2);

// The weights on an evenly spaced window of 2 half_width + 1 samples, dt
// apart, that give the degree-`degree` polynomial's derivative of `order`
// (1: the rate, 1/s; 2: the acceleration, 1/s^2) at its middle.
std::vector<double> derivative_weights(size_t half_width, int degree, int order, double dt);

// A step this many times the median one is a time gap: a stretch not
// recorded (the returns of closing-only strokes).
constexpr double kRecordedApart = 10;

// s: the sampling interval of increasing times `t` (0 for fewer than
// two): the mean step, the time gaps left out. With them, a trace of strokes recorded
// apart had a mean step a tenth too long, and every step read as uneven.
double sample_step(const std::vector<double>& t);

// The window every rate starts from: +-25 ms, degree 6 (above).
constexpr double kNarrowWindow = 0.025;  // s, each side
constexpr int kNarrowDegree = 6;

// `t` increasing, the same length as `y`, at least 2 samples; `window`
// s each side, the polynomial of `degree` (at most twice the samples
// each side).
Derivatives local_derivatives(const std::vector<double>& t, const std::vector<double>& y,
                              double window = kNarrowWindow, int degree = kNarrowDegree);

}  // namespace afford
