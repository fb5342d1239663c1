// A session as a MuJoCo scene (MJCF XML, for MuJoCo 2.2.2): the tool's
// hinge with its limits and torsion spring, the actee as a body in the
// jaws, the hand as a force-limited position servo on the hinge. What MJCF
// cannot say (the progressive spring, the actee's breaking, the hand's
// schedule) is written as <custom> numerics that a harness applies; the
// file's header comment says how. `afford export --mjcf` writes it; the
// benchmark and the tests load it in MuJoCo to check the physics.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "model.h"
#include "session.h"

namespace afford {

// The torsion spring of the hinge in MuJoCo's terms: the engine's linear
// spring S_k at S_p and its preload (terms.h) as one joint spring.
struct HingeSpring {
  double stiffness = 0;  // N*m/rad, S_k * S_p^2
  double springref = 0;  // rad, where it pushes nothing: rest + preload / (S_k * |S_p|)
};
HingeSpring hinge_spring(const Model& m);

// The hand as a servo on the hinge, from the script's first grip that
// holds the tool (lever_solver.cpp: the hand is a spring force_gain between
// the tracked thumb and the emphasis point, damped by hand_damping, its push
// capped by the agent's max_force and the grasp type's).
struct HandServo {
  bool present = false;   // false: the script never holds the tool
  double lever_arm = 0;   // m, b: the thumb's distance from the fulcrum
  double kp = 0;          // N*m/rad, force_gain * b^2
  double kv = 0;          // N*m*s/rad, hand_damping * b^2
  double max_force = 0;   // N, at the thumb
  double max_torque = 0;  // N*m, max_force * b: the servo closes with at most this
  // (t s, commanded angle rad) per keyframe: rest - squeeze / |thumb| while
  // a grip holds the tool, theta_max (the servo pushes nothing) otherwise.
  std::vector<std::pair<double, double>> schedule;
};
HandServo hand_servo(const CompiledSession& session);

// The actee's contact with each jaw as MuJoCo's direct solref (-stiffness,
// -damping), in MuJoCo's units (1/s^2, 1/s; see mjcf_scene.cpp), so that the
// two contacts in series give the actee's stiffness in N/m.
struct ActeeContact {
  double impedance = 0;  // solimp, constant: d0 = dmax
  double stiffness = 0;  // 1/s^2, -solref[0]
  double damping = 0;    // 1/s, -solref[1]
};
ActeeContact actee_contact(const Model& m);

// How many MuJoCo steps make one frame of the model (timestep): enough for
// the stiffest contact (the actee's) to stay stable.
int substeps_per_frame(const Model& m);

// The whole scene, deterministic text. The session's model must have its
// agent (every session has).
std::string mjcf_scene(const CompiledSession& session);

// `afford export --mjcf` as a library call (the Python package's
// export_mjcf): mjcf_scene() of a session with one actee or none; a session
// with several (`actees:`) throws std::runtime_error naming its file, since
// a scene holds the bodies of one moment.
std::string export_mjcf(const CompiledSession& session);

}  // namespace afford
