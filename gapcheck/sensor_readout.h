// What the sensors of a played drive read at 1 kHz, the same in every
// reality: the force sensor late by the case's latency, with its gain
// error and drifting offset (outside the library), then each signal's
// white noise and quantisation, from a fixed seed.
#pragma once

#include <random>
#include <vector>

#include "design.h"

namespace gapcheck {

// f at the fractional sample `at` (f's samples 1 ms apart), linear
// between samples; f's first sample before it starts, its last after.
double at_sample(const std::vector<double>& f, double at);

class SensorReadout {
 public:
  SensorReadout(const Case& c, unsigned noise_seed);
  // The k-th sample (t = k ms): the arm's angle (rad), the effort the
  // force sensor feels now (N, closing positive), the actee's load (N).
  Measured read(int k, double angle, double effort_now, double load, bool broken);

 private:
  const Case& case_;
  std::mt19937 random_;
  std::normal_distribution<double> unit_{0.0, 1.0};
  std::vector<double> history_;  // N, the effort felt at each sample, before the delay
};

}  // namespace gapcheck
