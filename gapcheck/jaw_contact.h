// Where the jaws first touch an actee, found by MuJoCo's own collision
// detection (not afford's contact code): the tool and actee are exported
// as a MuJoCo scene and the hinge angle is bisected between touching and
// clear.
#pragma once

#include <string>
#include <vector>

namespace gapcheck {

struct JawContact {
  double angle = 0;      // rad: the largest hinge angle at which the actee overlaps a geom of the moving arm
  double thickness = 0;  // m: the actee's extent across the jaws (along the fixed jaw's normal)
  double lever = 0;      // m: the moment arm about the hinge of the moving jaw's push, along MuJoCo's contact normal
  // Where the moving jaw first touches the actee, in the tool's frame (m),
  // and the unit direction from there into the actee.
  double touch[3] = {0, 0, 0};
  double into[3] = {0, 0, 0};
};

// For the actee placed `at_m` along the fixed arm. Throws
// std::runtime_error when the jaws do not touch it even fully closed or
// touch it even fully open, or its shape is not a sphere, an ellipsoid or
// a box.
JawContact jaw_contact(const std::string& object_file, const std::string& actee_file, const std::string& agent_file,
                       double at_m);

// A geom as MuJoCo holds it (mjtGeom, its size, its pose in a frame).
struct SceneGeom {
  int type = 0;
  double size[3] = {0, 0, 0};
  double pos[3] = {0, 0, 0};    // m
  double quat[4] = {1, 0, 0, 0};
};

// The jaws and the actee as afford's exported scene places them: the
// moving arm's geoms in the arm's frame (the hinge is its z axis through
// its origin, at angle 0 the arm lies along the fixed one), the actee's in
// the tool's frame. The MuJoCo reality builds its jaws from these, and its
// plates press this actee (in the jaws it presses a point where
// jaw_contact finds the jaw first touches it).
struct JawScene {
  std::vector<SceneGeom> moving;
  SceneGeom actee;
};
JawScene jaw_scene(const std::string& object_file, const std::string& actee_file, const std::string& agent_file,
                   double at_m);

}  // namespace gapcheck
