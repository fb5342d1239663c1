// A two-part tool from a robot description (URDF, as in PartNet-Mobility
// and SAPIEN): the fixed and the moving link joined by a revolute joint,
// each link's collision geometry (its visual where it has none) gathered
// into one mesh in the fixed link's frame with the joint at zero, and the
// hinge's point, axis and limits in that frame. Read with urdfdom; URDF
// lengths are metres, and so are the meshes it names (times their scale).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "triangle_mesh.h"

namespace afford::modelling {

// One collision (or visual) element of a link: its name ("" where it has
// none) and its closed or open surface, in the fixed link's frame.
struct NamedMesh {
  std::string name;
  TriangleMesh mesh;
  std::string mesh_file;  // the mesh file it was read from; "" for a box, sphere or cylinder
};

// A link's <inertial>, in the fixed link's frame with the joint at zero.
struct LinkInertial {
  bool given = false;
  double mass = 0;                                      // kg
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();     // m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();    // kg*m^2, about the centre
};

struct UrdfTool {
  std::string file;
  std::string joint, fixed_link, moving_link;
  Eigen::Vector3d hinge_point = Eigen::Vector3d::Zero();  // m, fixed link frame
  Eigen::Vector3d hinge_axis = Eigen::Vector3d::UnitZ();  // unit, fixed link frame
  bool limited = false;  // a revolute joint (true) or a continuous one
  double lower = 0, upper = 0;  // rad, when limited
  TriangleMesh fixed, moving;   // m, fixed link frame, the joint at zero
  std::vector<NamedMesh> fixed_pieces, moving_pieces;  // the same, element by element
  LinkInertial fixed_inertial, moving_inertial;
  double friction = 0;  // N*m, the joint's <dynamics friction>
  double damping = 0;   // N*m*s/rad, the joint's <dynamics damping>
};

// `fixed` and `moving` name the links; both empty: the one revolute (or
// continuous) joint's parent and child. DataError at the element's line and
// column (the document's start where no one element is at fault) when
// urdfdom cannot read it, when there is no such joint or more than one and
// no names, when a named link is missing or the two are not joined by one,
// when an axis has no length, when a link has no geometry, or when a mesh
// it names cannot be read.
UrdfTool read_urdf_tool(const std::string& path, const std::string& fixed = "", const std::string& moving = "");

}  // namespace afford::modelling
