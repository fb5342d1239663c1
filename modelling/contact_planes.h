// The contact and support planes of a two-part tool from its shape (paper
// Sec. 3.2 step 4; objects/README.md): the contact plane L_cp is each arm's
// outer face over the handle (emphasis), where the hand pushes to close the
// jaws; the support plane is the fixed jaw's face over the application,
// where the actee rests. Each is the line that the face's edge of the part's
// outline (outline.h) makes in the plane the tool turns in, fitted by least
// squares at 9 places along the stretch, taken across that plane (its
// normal has no z).
#pragma once

#include <Eigen/Core>

#include "lever_geometry.h"
#include "triangle_mesh.h"

namespace afford::modelling {

struct FacePlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      // m, on the face at the stretch's middle
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();    // unit, out of the part, z = 0
  double from = 0, to = 0;  // m, along the arm: the stretch
  double rms = 0;           // m, of the outline's edge about the fitted line (0: flat)
  bool found = false;       // false: the part has no outline over the stretch
};

struct ContactPlanes {
  FacePlane fixed_contact;   // object frame
  FacePlane moving_contact;  // the moving arm's frame
  FacePlane support;         // object frame
};

// `fixed` in the object frame, `moving` in its arm's frame (closed). The
// outer side of each handle is the side away from the other's; the
// support face is the fixed jaw's side toward the moving jaw.
ContactPlanes contact_planes(const TriangleMesh& fixed, const TriangleMesh& moving, const LeverGeometry& lever);

}  // namespace afford::modelling
