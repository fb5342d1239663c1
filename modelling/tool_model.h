// A two-part tool modelled from its shape into what an object file holds
// (objects/README.md): the lever found from the geometry (lever_geometry.h),
// the parts' mass, centre of gravity and the moving part's inertia about
// the hinge, the plane of symmetry and the poses, the convex parts, and the
// spring where one is given (a URDF or a mesh has none).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "contact_planes.h"
#include "convex_parts.h"
#include "jaw_gaps.h"
#include "lever_geometry.h"
#include "stable_poses.h"
#include "symmetry_planes.h"
#include "urdf_tool.h"

namespace afford::modelling {

// A spring as a user knows it from the tool: its torsional stiffness about
// the hinge and the opening at which it pushes nothing.
struct SpringGiven {
  double torsion = 0;     // N*m/rad, > 0
  double free_angle = 0;  // rad, > 0
  std::optional<double> position;  // m, signed distance on the arm; default: the middle of the emphasis
};

struct ToolModelOptions {
  std::string name;                // the object's name
  std::optional<double> mass;      // kg, the whole tool, shared by volume
  std::optional<double> density;   // kg/m^3
  std::optional<SpringGiven> spring;
  RegionsGiven regions;
  bool arm_dynamics = false;  // arm_inertia enabled (the shipped tools run quasi-static, without it)
  std::optional<Eigen::Vector3d> rotation;  // rad about world x, y, z: the functional pose's, instead of upright
  double symmetry_tolerance = kSymmetryTolerance;
};

// The object file's spring section.
struct ModelSpring {
  double constant = 0;   // N/m
  double position = 0;   // m, signed, on the arm
  double preload = 0;    // N, >= 0: the push at the rest angle (rest at theta_max)
  double rest_length = 0;  // m, > 0 when the spring pulls (rest at theta_min); else 0
};

struct ToolModel {
  std::string source;  // the file(s) modelled, for the header
  std::string name;
  LeverGeometry lever;
  std::string mass_from;  // where the mass came from
  double fixed_mass = 0, moving_mass = 0;  // kg
  Eigen::Vector3d fixed_centre = Eigen::Vector3d::Zero();   // m, object frame
  Eigen::Vector3d moving_centre = Eigen::Vector3d::Zero();  // m, the moving arm's frame
  double arm_inertia = 0;  // kg*m^2, the moving part about the hinge
  bool arm_dynamics = false;  // the arm_inertia effect enabled
  double rest = 0;         // rad: where the spring holds the tool; theta_max without one
  Eigen::Vector3d centre_of_gravity = Eigen::Vector3d::Zero();  // m, object frame, at rest
  std::optional<ModelSpring> spring;
  Symmetry symmetry;              // of the tool at rest, object frame
  SymmetryPlane plane;            // the one written (the best tried)
  Eigen::Vector3d pose_rotation = Eigen::Vector3d::Zero();  // rad about world x, y, z: the plane upright
  bool rotation_given = false;    // pose_rotation from the options
  RestingPoses resting;           // of the tool at rest, object frame
  std::vector<ConvexPart> parts;
  JawGaps jaws;  // the interaction space from the shape
  ContactPlanes faces;  // the contact planes (handles) and the support plane (fixed jaw)
  double friction = 0;  // N*m, pivot
  double damping = 0;   // N*m*s/rad
  double mass() const { return fixed_mass + moving_mass; }
};

// DataError (at the tool's file) where the shape says no lever; a
// std::invalid_argument naming the option where neither a mass nor a
// density is given and the tool has no <inertial>, or a spring option is
// out of its range.
ToolModel model_tool(const UrdfTool& tool, const ToolModelOptions& options);

// The object file, in the object format's units (mm, g, deg), with a header
// that says where each figure came from. Without a spring the file has no
// spring section and `afford check` says what to do.
std::string object_yaml(const ToolModel& model);

}  // namespace afford::modelling
