#include "urdf_export.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "effects.h"
#include "geometry.h"
#include "mass_properties.h"
#include "primitive_meshes.h"

namespace afford::modelling {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;

std::string num(double x) {
  if (std::abs(x) < 1e-15) x = 0;  // no "-0"
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

std::string xyz(const Vector3d& v) { return num(v.x()) + " " + num(v.y()) + " " + num(v.z()); }

// The part's shape as a closed mesh in its own frame (capsules and
// cylinders along x, as the object format has them).
TriangleMesh shape_mesh(const ShapeSpec& s) {
  const Isometry3d z_to_x(Eigen::AngleAxisd(std::numbers::pi / 2, Vector3d::UnitY()));
  TriangleMesh out;
  switch (s.kind) {
    case ShapeKind::box:
      return box_mesh(s.size);
    case ShapeKind::sphere:
      return sphere_mesh(s.radius);
    case ShapeKind::ellipsoid:
      return ellipsoid_mesh(s.radii, 24, 48);
    case ShapeKind::cylinder:
      append(out, cylinder_mesh(s.radius, s.length), z_to_x);
      return out;
    case ShapeKind::capsule:
      append(out, capsule_mesh(s.radius, s.length), z_to_x);
      return out;
    case ShapeKind::convex: {
      const ConvexHull hull = convex_hull(s.vertices, s.loc);
      out.vertices = hull.vertices;
      out.triangles = hull.triangles;
      return out;
    }
  }
  return out;
}

// ASCII STL, metres: each triangle with its normal.
std::string stl(const std::string& name, const TriangleMesh& m) {
  std::ostringstream out;
  out << "solid " << name << "\n";
  for (const auto& t : m.triangles) {
    const Vector3d &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    out << "  facet normal " << xyz((b - a).cross(c - a).normalized()) << "\n    outer loop\n";
    for (const Vector3d* v : {&a, &b, &c}) out << "      vertex " << xyz(*v) << "\n";
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid " << name << "\n";
  return out.str();
}

double effect(const ObjectSpec& o, EffectKind kind) {
  for (const EffectSpec& e : o.effects) {
    if (e.kind == kind && e.enabled) return e.param[0];
  }
  return 0;
}

struct ArmBody {
  TriangleMesh mesh;  // its parts, in the arm's frame
  MassProperties props;
  double mass = 0;
  Vector3d centre = Vector3d::Zero();
};

std::string inertial(const ArmBody& a) {
  const Eigen::Matrix3d i = a.props.inertia_per_density * (a.mass / a.props.volume);
  return "    <inertial>\n      <origin xyz=\"" + xyz(a.centre) + "\" rpy=\"0 0 0\"/>\n      <mass value=\"" + num(a.mass) +
         "\"/>\n      <inertia ixx=\"" + num(i(0, 0)) + "\" ixy=\"" + num(i(0, 1)) + "\" ixz=\"" + num(i(0, 2)) +
         "\" iyy=\"" + num(i(1, 1)) + "\" iyz=\"" + num(i(1, 2)) + "\" izz=\"" + num(i(2, 2)) + "\"/>\n    </inertial>\n";
}

}  // namespace

std::vector<ExportedFile> urdf_export(const ObjectSpec& o) {
  std::vector<ExportedFile> meshes;
  ArmBody arms[2];
  std::string elements[2];
  for (const PartSpec& p : o.parts) {
    Isometry3d pose = Isometry3d::Identity();
    pose.linear() = p.pose.rotation;
    pose.translation() = p.pose.position;
    TriangleMesh placed;
    append(placed, shape_mesh(p.shape), pose);
    append(arms[static_cast<int>(p.arm)].mesh, placed, Isometry3d::Identity());
    const std::string file = "meshes/" + p.name + ".stl";
    meshes.push_back({file, stl(p.name, placed)});
    for (const char* tag : {"collision", "visual"}) {
      elements[static_cast<int>(p.arm)] += std::string("    <") + tag + " name=\"" + p.name +
                                           "\">\n      <origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n      <geometry><mesh "
                                           "filename=\"" + file + "\"/></geometry>\n    </" + tag + ">\n";
    }
  }

  // The mass shared by volume (as the engine shares it), each arm's centre
  // moved alike so that the tool's centre at rest is the file's.
  const double volume = mass_properties(arms[0].mesh).volume + mass_properties(arms[1].mesh).volume;
  for (ArmBody& a : arms) {
    a.props = mass_properties(a.mesh);
    a.mass = o.mass * a.props.volume / volume;
    a.centre = a.props.centroid;
  }
  const Eigen::AngleAxisd at_rest(o.lever.theta_rest, Vector3d::UnitZ());
  const Vector3d by_volume = (arms[0].mass * arms[0].centre + arms[1].mass * (at_rest * arms[1].centre)) / o.mass;
  const Vector3d shift = o.centre_of_gravity - by_volume;
  arms[0].centre += shift;
  arms[1].centre += at_rest.inverse() * shift;

  // The spring as `afford model --spring` takes it: its torsion about the
  // hinge and the opening at which it pushes nothing.
  const double sp = std::abs(o.spring.position);
  const double torsion = o.spring.constant * sp * sp;
  const double free_angle = o.lever.theta_rest + effect(o, EffectKind::spring_preload) / (o.spring.constant * sp);

  // The functional pose's rotation as the angles about x, then y, then z.
  const Vector3d angles = o.functional_pose.rotation.eulerAngles(2, 1, 0).reverse() * (180 / std::numbers::pi);
  std::ostringstream u;
  u << "<?xml version=\"1.0\"?>\n"
    << "<!-- Written by afford export --urdf from " << o.file << ": the fixed and the moving arm, the hinge along z at\n"
    << "     the origin (joint 0: the arms closed), limits theta_min and theta_max, the pivot's friction and damping.\n"
    << "     URDF has no spring: afford model " << o.name << ".urdf --spring " << num(torsion) << ","
    << num(free_angle * 180 / std::numbers::pi) << " --spring-at " << num(o.spring.position * 1e3)
    << " gives it back,\n"
    << "     --emphasis " << num(o.emphasis.from * 1e3) << "," << num(o.emphasis.to * 1e3) << " --application "
    << num(o.application.from * 1e3) << "," << num(o.application.to * 1e3) << " the file's regions (mm), and\n"
    << "     --rotation " << num(angles.x()) << "," << num(angles.y()) << "," << num(angles.z())
    << " its functional pose's rotation (deg). -->\n"
    << "<robot name=\"" << o.name << "\">\n";
  const char* names[2] = {"fixed_arm", "moving_arm"};
  for (int k = 0; k < 2; ++k) {
    u << "  <link name=\"" << names[k] << "\">\n" << inertial(arms[k]) << elements[k] << "  </link>\n";
  }
  u << "  <joint name=\"hinge\" type=\"revolute\">\n"
    << "    <origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n"
    << "    <parent link=\"fixed_arm\"/>\n"
    << "    <child link=\"moving_arm\"/>\n"
    << "    <axis xyz=\"0 0 1\"/>\n"
    // URDF requires an effort (N*m) and a velocity (rad/s) limit; afford
    // reads neither: a hand's squeeze, at most 10 rad/s.
    << "    <limit lower=\"" << num(o.lever.theta_min) << "\" upper=\"" << num(o.lever.theta_max)
    << "\" effort=\"100\" velocity=\"10\"/>\n"
    << "    <dynamics damping=\"" << num(effect(o, EffectKind::viscous_damping)) << "\" friction=\""
    << num(effect(o, EffectKind::pivot_friction)) << "\"/>\n"
    << "  </joint>\n"
    << "</robot>\n";
  std::vector<ExportedFile> out{{o.name + ".urdf", u.str()}};
  for (ExportedFile& m : meshes) out.push_back(std::move(m));
  return out;
}

}  // namespace afford::modelling
