#include "tool_model.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "mass_properties.h"
#include "primitive_meshes.h"
#include "units.h"

namespace afford::modelling {
namespace {

using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;

// Within this of horizontal a plane of symmetry counts as upright (a
// smooth body's hull is facets).
constexpr double kUprightDeg = 3;

// The inertia about the z axis through the origin of a body of `mass` (kg)
// centred at `centre` (m) with `about_centre` (kg*m^2), all in one frame.
double inertia_about_z(double mass, const Vector3d& centre, const Matrix3d& about_centre) {
  return about_centre(2, 2) + mass * (centre.x() * centre.x() + centre.y() * centre.y());
}

struct PartMass {
  double mass = 0;
  Vector3d centre = Vector3d::Zero();
  Matrix3d inertia = Matrix3d::Zero();  // about the centre
};

PartMass moved(const PartMass& p, const Isometry3d& t) {
  return {p.mass, t * p.centre, t.linear() * p.inertia * t.linear().transpose()};
}

// The two parts' masses from the options (shared by volume) or the URDF's
// <inertial> elements.
void masses(const UrdfTool& tool, const ToolModelOptions& o, PartMass& fixed, PartMass& moving, std::string& from) {
  if (o.mass || o.density) {
    const MassProperties pf = mass_properties(tool.fixed), pm = mass_properties(tool.moving);
    const double volume = pf.volume + pm.volume;
    const double density = o.mass ? *o.mass / volume : *o.density;
    fixed = {density * pf.volume, pf.centroid, density * pf.inertia_per_density};
    moving = {density * pm.volume, pm.centroid, density * pm.inertia_per_density};
    from = o.mass ? "--mass, shared by volume" : "--density";
    if (!pf.exact || !pm.exact) from += " (volumes from voxels: a part's mesh is not closed)";
    return;
  }
  if (tool.fixed_inertial.given && tool.moving_inertial.given) {
    fixed = {tool.fixed_inertial.mass, tool.fixed_inertial.centre, tool.fixed_inertial.inertia};
    moving = {tool.moving_inertial.mass, tool.moving_inertial.centre, tool.moving_inertial.inertia};
    from = "the links' <inertial>";
    return;
  }
  throw std::invalid_argument("--mass G or --density KG_M3: the tool's mass (" + tool.file +
                              " gives no <inertial> for both links)");
}

ModelSpring spring_of(const SpringGiven& s, const LeverGeometry& lever, double* rest) {
  const double position = s.position ? *s.position : lever.emphasis.middle();
  if (position == 0 || position < lever.arm.from || position > lever.arm.to) {
    throw std::invalid_argument("--spring-at: a distance on the arm away from the pivot, between " +
                                format_quantity(lever.arm.from, dim::length) + " and " +
                                format_quantity(lever.arm.to, dim::length) + ", found " +
                                format_quantity(position, dim::length));
  }
  // A torsion K about the hinge is a spring of K / S_p^2 at S_p; free at
  // the angle `free_angle`, it holds the tool at the nearest limit.
  ModelSpring out;
  out.position = position;
  const double arm = std::abs(position);
  out.constant = s.torsion / (arm * arm);
  *rest = std::clamp(s.free_angle, lever.theta_min, lever.theta_max);
  if (s.free_angle > lever.theta_max) out.preload = out.constant * arm * (s.free_angle - lever.theta_max);
  if (s.free_angle < lever.theta_min) out.rest_length = arm * s.free_angle;
  return out;
}

// Gravity along the plane of symmetry: the rotation (about world x, then
// y, then z) that turns its normal horizontal, the moving arm above where
// the normal is the pivot axis.
Vector3d upright(const Vector3d& normal) {
  const double across = std::sin(kUprightDeg * std::numbers::pi / 180);
  if (std::abs(normal.z()) <= across) return Vector3d::Zero();  // the pivot axis up: already upright
  return Vector3d(std::numbers::pi / 2, 0, 0);  // on edge: object y up, the moving arm above
}

}  // namespace

ToolModel model_tool(const UrdfTool& tool, const ToolModelOptions& o) {
  ToolModel m;
  m.source = tool.file;
  m.name = o.name;
  PartMass fixed, moving;
  masses(tool, o, fixed, moving, m.mass_from);
  m.lever = lever_geometry(tool, o.regions);
  const LeverGeometry& lever = m.lever;
  fixed = moved(fixed, lever.fixed_to_object);
  moving = moved(moving, lever.moving_to_arm);
  m.fixed_mass = fixed.mass;
  m.moving_mass = moving.mass;
  m.fixed_centre = fixed.centre;
  m.moving_centre = moving.centre;
  m.arm_inertia = inertia_about_z(moving.mass, moving.centre, moving.inertia);
  m.arm_dynamics = o.arm_dynamics;

  m.rest = lever.theta_max;
  if (o.spring) m.spring = spring_of(*o.spring, lever, &m.rest);
  const Eigen::AngleAxisd at_rest(m.rest, Vector3d::UnitZ());
  m.centre_of_gravity = (fixed.mass * fixed.centre + moving.mass * (at_rest * moving.centre)) / m.mass();
  m.friction = tool.friction;
  m.damping = tool.damping;

  // The tool at rest, in the object frame: its symmetry and how it rests.
  TriangleMesh whole;
  whole.file = tool.file;
  append(whole, tool.fixed, lever.fixed_to_object);
  append(whole, tool.moving, Isometry3d(at_rest) * lever.moving_to_arm);
  const MassProperties props = mass_properties(whole);
  m.symmetry = symmetry_planes(whole, props, o.symmetry_tolerance);
  // The plane the tool turns in where it is one (each arm symmetric about
  // it), else the best: an open tool is also symmetric about the plane
  // between its arms, which its arms' swap gives and a hand does not hold.
  m.plane = m.symmetry.planes.empty() ? m.symmetry.best : m.symmetry.planes.front();
  for (const SymmetryPlane& s : m.symmetry.planes) {
    if (std::abs(s.normal.z()) > std::cos(kUprightDeg * std::numbers::pi / 180)) {
      m.plane = s;
      break;
    }
  }
  m.pose_rotation = o.rotation ? *o.rotation : upright(m.plane.normal);
  m.rotation_given = o.rotation.has_value();
  m.resting = resting_poses(whole, m.centre_of_gravity);
  TriangleMesh fixed_part, moving_part;
  append(fixed_part, tool.fixed, lever.fixed_to_object);
  append(moving_part, tool.moving, lever.moving_to_arm);
  m.jaws = jaw_gaps(moving_part, lever);
  m.faces = contact_planes(fixed_part, moving_part, lever);

  std::vector<std::string> taken;
  std::vector<NamedMesh> pieces;
  for (const auto* arm : {&tool.fixed_pieces, &tool.moving_pieces}) {
    const bool is_fixed = arm == &tool.fixed_pieces;
    pieces.clear();
    for (const NamedMesh& p : *arm) {
      NamedMesh placed{p.name, {}, p.mesh_file};
      placed.mesh.file = p.mesh.file;
      append(placed.mesh, p.mesh, is_fixed ? lever.fixed_to_object : lever.moving_to_arm);
      pieces.push_back(std::move(placed));
    }
    for (ConvexPart& part : convex_parts(pieces, is_fixed ? Arm::fixed : Arm::moving, taken)) {
      m.parts.push_back(std::move(part));
    }
  }
  return m;
}

}  // namespace afford::modelling
