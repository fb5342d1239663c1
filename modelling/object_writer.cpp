// object_yaml (tool_model.h): the object file of a modelled tool, in the
// object format's units, every figure from the model.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "lever.h"
#include "tool_model.h"

namespace afford::modelling {
namespace {

std::string num(double x, int digits = 6) {
  if (std::abs(x) < 1e-12) x = 0;  // no "-0"
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string in_mm(double m) { return num(m * 1e3) + " mm"; }
std::string in_deg(double rad) { return num(rad * 180 / std::numbers::pi) + " deg"; }
std::string mm3(const Eigen::Vector3d& v) { return "[" + in_mm(v.x()) + ", " + in_mm(v.y()) + ", " + in_mm(v.z()) + "]"; }
std::string mm_list(const std::vector<double>& m) {
  std::string out = "[";
  for (size_t i = 0; i < m.size(); ++i) out += (i > 0 ? ", " : "") + in_mm(m[i]);
  return out + "]";
}
std::string range(const RangeSpec& r) { return "{from: " + in_mm(r.from) + ", to: " + in_mm(r.to) + "}"; }

std::string found(bool from_shape) { return from_shape ? "from the gap between the parts" : "as given"; }

}  // namespace

std::string object_yaml(const ToolModel& m) {
  const LeverGeometry& l = m.lever;
  std::ostringstream out;
  out << "# Written by afford model from " << m.source << " (paper Sec. 3.2).\n"
      << "# Mass, centre of gravity and the moving arm's inertia about the hinge: from " << m.mass_from << ".\n"
      << "# Hinge and limits: from the joint; 0 deg is where the parts meet"
      << (l.closes_on_contact ? " (the joint's lower limit closes them further: theta_min is their contact)" : "")
      << ".\n"
      << "# Jaws (application) " << found(l.application_found) << "; handle (emphasis) " << found(l.emphasis_found)
      << ".\n"
      << "# Parts: convex hulls of the collision elements (long concave ones cut in slabs).\n"
      << "# Interaction space (L_is): the shape's jaws fully open are " << in_mm(m.jaws.gap_from()) << " to "
      << in_mm(m.jaws.gap_to()) << " apart (interaction_space, below;\n"
      << "# afford model reports the gap at each opening); the wedge |r| sin theta_max would be "
      << in_mm(m.jaws.wedge_from) << " to " << in_mm(m.jaws.wedge_to) << ".\n";
  if (!m.spring) {
    out << "# No spring: a URDF or a mesh has none. Add it with afford model ... --spring K_N_M_PER_RAD,REST_DEG,\n"
        << "# or write a guess and fit it to a probing trace with afford gap --probe (gap/README.md).\n";
  }
  out << "object: " << m.name << "\n"
      << "description: " << m.name << ", modelled from " << m.source << ".\n"
      << "mass: " << num(m.mass() * 1e3) << " g\n"
      << "centre_of_gravity: " << mm3(m.centre_of_gravity) << "   # at the rest angle\n"
      << (m.rotation_given ? "# The pose for functioning: its rotation as given,\n"
                           : "# The paper's pose for functioning (Sec. 4.4): the plane of symmetry parallel to gravity,\n")
      << "# held 100 mm above the table as the shipped tools are.\n"
      << "functional_pose:\n"
      << "  position: [0 mm, 0 mm, 100 mm]\n"
      << "  rotation: [" << in_deg(m.pose_rotation.x()) << ", " << in_deg(m.pose_rotation.y()) << ", "
      << in_deg(m.pose_rotation.z()) << "]\n"
      << "symmetry_plane:   # the reflection lies " << num(m.plane.score * 1e3, 3) << " mm RMS from the surface"
      << (m.symmetry.planes.empty() ? " (no plane within the tolerance: the nearest)" : "") << "\n"
      << "  point: " << mm3(m.plane.point) << "\n"
      << "  normal: [" << num(m.plane.normal.x()) << ", " << num(m.plane.normal.y()) << ", " << num(m.plane.normal.z())
      << "]\n"
      << "lever:\n"
      << "  pattern: " << pattern_name(l.pattern) << "\n"
      << "  arm: " << range(l.arm) << "\n"
      << "  theta_min: " << in_deg(l.theta_min) << "\n"
      << "  theta_max: " << in_deg(l.theta_max) << "\n";
  // A rest on a limit is that limit's very text (the loader compares them).
  out << "  rest: "
      << (m.rest == l.theta_max ? in_deg(l.theta_max) : m.rest == l.theta_min ? in_deg(l.theta_min) : in_deg(m.rest)) << "\n";
  if (m.spring) {
    out << "spring:\n"
        << "  constant: " << num(m.spring->constant, 9) << " N/m\n"
        << "  position: " << num(m.spring->position * 1e3, 9) << " mm\n";
    if (m.spring->rest_length > 0) {
      out << "  rest_length: " << num(m.spring->rest_length * 1e3, 9) << " mm\n";
    } else {
      out << "  preload: " << num(m.spring->preload, 9) << " N\n";
    }
  }
  out << "emphasis: " << range(l.emphasis) << "\n"
      << "application: " << range(l.application) << "\n"
      << "interaction_space:   # the gap between the jaws fully open, from the fixed jaw's face\n"
      << "  distances: " << mm_list(m.jaws.distances) << "\n"
      << "  gap_at_theta_max: " << mm_list(m.jaws.gap.back()) << "\n"
      << "parts:\n";
  for (const ConvexPart& p : m.parts) {
    out << "  - name: " << p.name << "\n"
        << "    arm: " << (p.arm == Arm::fixed ? "fixed" : "moving") << "\n"
        << "    position: " << mm3(p.position) << "\n"
        << "    shape:\n"
        << "      convex:\n"
        << "        unit: mm\n"
        << "        vertices:\n";
    for (const Eigen::Vector3d& v : p.corners) {
      out << "          - [" << num(v.x() * 1e3) << ", " << num(v.y() * 1e3) << ", " << num(v.z() * 1e3) << "]\n";
    }
  }
  out << "effects:\n";
  if (m.friction > 0) out << "  pivot_friction: {torque: " << num(m.friction) << " N*m}   # the joint's <dynamics friction>\n";
  if (m.damping > 0) {
    out << "  viscous_damping: {coefficient: " << num(m.damping) << " N*m*s/rad}   # the joint's <dynamics damping>\n";
  }
  out << "  arm_inertia: {inertia: " << num(m.arm_inertia) << " kg*m^2"
      << (m.arm_dynamics ? "}   # the moving part about the hinge\n"
                         : ", enabled: false}   # the moving part about the hinge; on: the arm's own dynamics\n")
      << "  gravity: {extra_torque: 0 N*m}   # the arm's own weight, from mass and shape\n";
  return out.str();
}

}  // namespace afford::modelling
