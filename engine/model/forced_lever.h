// The lever under a given effort (a measured force, not a hand): the same
// implicit balance as a frame's, with every enabled term, friction and the
// limits, for replaying a measurement by force (gap/).
#pragma once

#include <Eigen/Core>

#include "model.h"

namespace afford {

struct ForcedLever {
  double effort_distance = 0;  // m, where the effort pushes along the moving arm (> 0)
  bool actee = false;          // an actee between the jaws, unbroken
  double load_distance = 0;    // m, its lever arm about the fulcrum (> 0), as State::load_distance
  double contact_angle = 0;    // rad, where the jaws touch it
  double thickness = 0;        // m, its extent across the jaws
  Eigen::Matrix3d object_rotation = Eigen::Matrix3d::Identity();  // the tool in the world, for gravity
  double turn = 0;             // rad, the tool turned further about its hinge (gravity_coefficients)
};

struct ForcedStep {
  double theta = 0;        // rad, at the end of the step
  double omega = 0;        // rad/s
  double actee_force = 0;  // N
};

// One step of dt seconds from (theta0, omega0) under effort_n newtons.
ForcedStep step_forced_lever(const Model& m, const ForcedLever& lever, double theta0, double omega0,
                             double effort_n, double dt);

}  // namespace afford
