#include "sensor_readout.h"

#include <cmath>

namespace gapcheck {
namespace {

double quantise(double x, double q) { return q > 0 ? q * std::round(x / q) : x; }

}  // namespace

double at_sample(const std::vector<double>& f, double at) {
  if (at <= 0) return f.front();
  const auto i = static_cast<size_t>(at);
  if (i + 1 >= f.size()) return f.back();
  const double w = at - static_cast<double>(i);
  return (1 - w) * f[i] + w * f[i + 1];
}

SensorReadout::SensorReadout(const Case& c, unsigned noise_seed) : case_(c), random_(noise_seed) {}

Measured SensorReadout::read(int k, double angle, double effort_now, double load, bool broken) {
  const double t = k * 1e-3;
  history_.push_back(effort_now);
  // The effort of `latency` ago, linear between samples; the first sample
  // until then.
  double effort = at_sample(history_, k - case_.truth.latency * 1000);
  effort = (1 + case_.outside.gain_error) * effort + case_.outside.offset_drift * t;
  // Three draws a sample, always, so that one signal's noise does not
  // shift another's.
  const Sensors& s = case_.sensors;
  const double n_angle = unit_(random_), n_effort = unit_(random_), n_load = unit_(random_);
  Measured m;
  m.t = t;
  m.angle = quantise(angle + s.angle_noise * n_angle, s.angle_quantum);
  m.effort = quantise(effort + s.effort_noise * n_effort, s.effort_quantum);
  m.actee = case_.tool.actee ? quantise(load + s.actee_noise * n_load, s.actee_quantum) : 0.0;
  m.broken = broken;
  return m;
}

}  // namespace gapcheck
