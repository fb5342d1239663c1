// Active modelling (paper Sec. 3.2, steps 5-7): a force pushed at the
// emphasis and the rotation observed give the tool's lever and spring:
// the angle limits, the rest angle, the torsion spring S_k * S_p^2 and its
// preload (and the pivot's friction, which the same motion shows).
#pragma once

#include <string>

#include "measurement.h"

namespace afford {

struct ProbeResult {
  double theta_min = 0, theta_max = 0, theta_rest = 0;  // rad
  double torsion = 0, torsion_sigma = 0;   // N*m/rad, S_k * S_p^2
  double preload_torque = 0, preload_sigma = 0;  // N*m, at the rest angle
  double friction = 0, friction_sigma = 0;       // N*m
  double spring_constant = 0;  // N/m, torsion / S_p^2 with the nominal file's S_p
  double preload = 0;          // N, preload_torque / |S_p|
  size_t free_samples = 0;     // samples between the limits, moving, used for the spring
  std::string object_file;     // the nominal object, whose S_p and geometry are kept
};

// From every trace of a lever measurement (its `object` gives S_p).
ProbeResult probe_lever(const Measurement& m);

// Text for people; and the nominal object file with its lever limits, rest,
// spring constant and preload replaced (and pivot_friction if the probe saw
// some), written to `path`.
std::string probe_text(const ProbeResult& p);
void write_probed_object(const ProbeResult& p, const std::string& path);

}  // namespace afford
