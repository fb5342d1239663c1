// The withheld check of `afford gap`: a physics engine plays the real tool
// (reality.h). This folder's code never calls afford's solver, its torque
// terms, its actee law or the gap library while it makes data; it reads the
// nominal tool and actee files for their numbers only. Labels are written
// apart from the traces and read by the scorer after the diagnosis.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace gapcheck {

// The hidden truth of one case: what the real tool has beyond its file.
struct Truth {
  double friction = 0;     // N*m, added to the file's pivot friction
  double damping = 0;      // N*m*s/rad
  double preload = 0;      // N*m, added to the spring's preload torque
  double cubic = 0;        // N/m^3, a progressive spring
  double inertia = 0;      // kg*m^2, the arm's inertia about the pivot
  double weight = 0;       // N*m, the arm's weight torque amplitude (pivot axis level)
  double latency = 0;      // s, the effort sensor's delay
  // The specimen in the jaws stiffens as a power n of its contact's
  // depth, in each engine's own terms (ODE: Hunt and Crossley's k d^n;
  // MuJoCo plays Case::actee_impedance instead and n is the label's),
  // where the specimen the plates measured did not. 0: of the plates' kind.
  // Never afford's actee law: each engine's contact is its own, and the
  // actee file holds what the plates rig measured of it.
  double actee_exponent = 0;
  std::vector<std::string> names() const;  // the afford effect names of what is non-zero
};

// An actee in the tool's jaws, by its numbers (from its actee file), and
// where the jaws touch it (MuJoCo's collision, jaw_contact.h).
struct ToolActee {
  std::string file;
  double at = 0;             // m, its distance from the fulcrum along the arm
  double lever = 0;          // m, the moment arm of the moving jaw's push on it (MuJoCo's contact)
  double contact_angle = 0;  // rad
  double touch[3] = {0, 0, 0};  // m, where the moving jaw first touches it, in the tool's frame
  double into[3] = {0, 0, 0};   // the unit direction from there into it
  double thickness = 0;      // m, across the jaws
  double stiffness = 0;      // N/m, the file's linear law
  double limit = 0;          // N
  bool breaks = false;
};

// A nominal tool, by its numbers (from its object file).
struct Tool {
  std::string name, file;
  double theta_min = 0, theta_max = 0, rest = 0;  // rad
  double torsion = 0;        // N*m/rad, S_k * S_p^2
  double preload_torque = 0; // N*m, at rest
  double friction = 0;       // N*m, the file's pivot friction (0 if off)
  double spring_position = 0;  // m, |S_p|
  double spring_constant = 0;  // N/m
  double effort_at = 0;      // m, where the effort is applied and measured (its distance from the fulcrum)
  int effort_sign = 1;       // -1: on the handle side of a type 1 lever
  std::optional<ToolActee> actee;  // measured with an actee in its jaws
};

}  // namespace gapcheck
