// The rate or the acceleration from the widest window the motion allows.
// The degree-6 polynomial over +-25 ms (derivatives.h) follows a 20 Hz
// ringing, but at 1 kHz it multiplies the angle's white noise by about
// 1.2e4 s^-2 in the acceleration and 42 s^-1 in the rate: 3e-4 rad of
// noise becomes 3.5 rad/s^2, more than a slow drive's whole acceleration,
// and an arm's inertia is then fitted to noise (held out it cuts little);
// 5e-4 rad becomes 0.021 rad/s, which a damping of 1.9 N*m*s/rad passes
// on as 0.04 N*m, five times the gap a friction alone leaves it to explain
// on strokes of one speed.
// The same polynomial over +-50, +-100 or +-200 ms passes 5.5, 31 and
// about 170 times less of the noise in the acceleration (2.8, 8 and 22
// times less in the rate), but smooths what changes faster than its
// window. Which window a sample gets is the data's choice (Lepski's
// rule): from the narrow window outwards it takes the next wider one
// while the two differ, beyond what their noises alone would (known from
// the angle's), by less than the noise the wider saves, averaged over
// +-0.4 s about it; a sample keeps the last window that passed, and the
// narrow one where no wider is centred and evenly spaced.
#pragma once

#include <vector>

#include "derivatives.h"

namespace afford {

struct SmoothDerivative {
  std::vector<double> value;       // dy/dt (order 1) or d2y/dt2 (order 2) at each sample
  std::vector<double> noise_gain;  // at each sample, its noise per unit of y's white noise, 1/s or 1/s^2
};

// `narrow` is local_derivatives(t, y); `noise` y's white noise (deviation,
// y's unit); `order` 1 (the rate) or 2 (the acceleration). With no noise
// (or too short a trace) every sample keeps the narrow window.
SmoothDerivative smooth_derivative(const std::vector<double>& t, const std::vector<double>& y, double noise,
                                   const Derivatives& narrow, int order);

}  // namespace afford
