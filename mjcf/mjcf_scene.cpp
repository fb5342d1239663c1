// The MJCF writer. The scene's world is the session's world (z up, SI
// units, radians); the tool is fixed at its functional pose, so what the
// script's hand does to carry it is not in the scene, only its squeeze.
#include "mjcf_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "grasps.h"
#include "stages.h"

namespace afford {
namespace {

// The actee's contacts: a constant impedance close to MuJoCo's hardest, so
// that the contact force is the solver's stiffness and not the impedance's
// ramp.
constexpr double kContactImpedance = 0.99;
// The hinge's limits: a constant impedance as for the contacts; with the
// smallest time constant MuJoCo takes (two steps, for the limits and the
// pivot's friction loss) the stops and the stiction hold.
constexpr double kLimitImpedance = 0.99;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v == 0 ? 0.0 : v);  // no "-0"
  return buf;
}

std::string vec(const Eigen::Vector3d& v) { return num(v.x()) + " " + num(v.y()) + " " + num(v.z()); }

// MuJoCo's quaternion order (w x y z), w >= 0 so that one rotation has one text.
std::string quat(const Eigen::Matrix3d& r) {
  Eigen::Quaterniond q(r);
  q.normalize();
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return num(q.w()) + " " + num(q.x()) + " " + num(q.y()) + " " + num(q.z());
}

std::string attr(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// Text inside an XML comment may hold neither "--" nor a '-' at its end.
std::string comment_text(std::string text) {
  for (size_t i = text.find("--"); i != std::string::npos; i = text.find("--", i)) text.replace(i, 2, "- ");
  return text;
}

// Our capsules and cylinders lie along the part's x axis, MuJoCo's along z:
// a quarter turn about y takes z to x.
const Eigen::Matrix3d kZToX = Eigen::AngleAxisd(0.5 * 3.14159265358979323846, Eigen::Vector3d::UnitY()).toRotationMatrix();

// A geom of `shape` placed at `pose` in its body, with its mass and its
// contact bits. Convex shapes refer to the mesh asset `mesh_name`.
std::string geom(const std::string& name, const ShapeSpec& shape, const Eigen::Isometry3d& pose, double mass,
                 int contype, int conaffinity, const std::string& mesh_name) {
  Eigen::Matrix3d rotation = pose.linear();
  std::string type, size;
  switch (shape.kind) {
    case ShapeKind::sphere:
      type = "sphere";
      size = num(shape.radius);
      break;
    case ShapeKind::box:
      type = "box";
      size = vec(0.5 * shape.size);
      break;
    case ShapeKind::capsule:
    case ShapeKind::cylinder:
      type = shape.kind == ShapeKind::capsule ? "capsule" : "cylinder";
      size = num(shape.radius) + " " + num(0.5 * shape.length);
      rotation = rotation * kZToX;
      break;
    case ShapeKind::ellipsoid:
      type = "ellipsoid";
      size = vec(shape.radii);
      break;
    case ShapeKind::convex:
      type = "mesh";
      break;
  }
  std::string out = "<geom name=\"" + attr(name) + "\" type=\"" + type + "\"";
  out += shape.kind == ShapeKind::convex ? " mesh=\"" + attr(mesh_name) + "\"" : " size=\"" + size + "\"";
  out += " pos=\"" + vec(pose.translation()) + "\" quat=\"" + quat(rotation) + "\" mass=\"" + num(mass) +
         "\" contype=\"" + std::to_string(contype) + "\" conaffinity=\"" + std::to_string(conaffinity) + "\"/>";
  return out;
}

std::string mesh_asset(const std::string& name, const ShapeSpec& shape) {
  std::string vertices;
  for (const Eigen::Vector3d& v : shape.vertices) vertices += (vertices.empty() ? "" : "  ") + vec(v);
  return "<mesh name=\"" + attr(name) + "\" vertex=\"" + vertices + "\"/>";
}

std::string numeric(const std::string& name, const std::vector<double>& data) {
  std::string text;
  for (const double v : data) text += (text.empty() ? "" : " ") + num(v);
  return "<numeric name=\"" + name + "\" size=\"" + std::to_string(data.size()) + "\" data=\"" + text + "\"/>";
}

// The first grip keyframe that holds the tool, or nullptr.
const Keyframe* first_holding_grip(const Script& script) {
  for (const Keyframe& k : script.keyframes) {
    if (k.grip && k.grasps) return &k;
  }
  return nullptr;
}

// m: the actee's extent across the jaws (the object's y axis) where the
// session places it; 0 without an actee.
double actee_thickness(const Model& m) {
  return m.has_actee ? thickness_across_jaws(m, m.object_start.inverse() * m.actee_start) : 0.0;
}

// A lower bound of the moving arm's inertia about the hinge: its mass at its
// centre, plus the arm_inertia effect (kg*m^2).
double arm_inertia_bound(const Model& m) {
  return m.arm_mass * (m.arm_centre.x() * m.arm_centre.x() + m.arm_centre.y() * m.arm_centre.y()) + m.arm_inertia;
}

}  // namespace

HingeSpring hinge_spring(const Model& m) {
  // terms.h: the linear and preload torques are S_k |S_p|^2 (rest - theta)
  // + preload |S_p| = S_k |S_p|^2 (rest + preload / (S_k |S_p|) - theta).
  const double arm = std::abs(m.spring_position);
  HingeSpring s;
  s.stiffness = m.spring_constant * arm * arm;
  s.springref = m.theta_rest + (s.stiffness > 0 ? m.spring_preload / (m.spring_constant * arm) : 0.0);
  return s;
}

HandServo hand_servo(const CompiledSession& session) {
  const Model& m = session.model;
  HandServo h;
  const Keyframe* grip = first_holding_grip(session.script);
  if (grip == nullptr) return h;
  h.present = true;
  // The thumb's point on the moving arm at rest: its x is the distance along
  // the arm, the engine's effort distance while the thumb is on the arm.
  h.lever_arm = std::abs(grip->thumb_rest.x());
  h.kp = m.force_gain * h.lever_arm * h.lever_arm;
  h.kv = m.hand_damping * h.lever_arm * h.lever_arm;
  h.max_force = m.max_force;
  const int type = classify_grasp(m, grip->joint);
  if (type >= 0) h.max_force = std::min(h.max_force, m.grasp_max_force[static_cast<size_t>(type)]);
  h.max_torque = h.max_force * h.lever_arm;
  for (const Keyframe& k : session.script.keyframes) {
    h.schedule.emplace_back(k.t, k.grip && k.grasps ? k.thumb_angle : m.theta_max);
  }
  return h;
}

ActeeContact actee_contact(const Model& m) {
  // MuJoCo's direct solref (-k, -b) is a stiffness and a damping of the
  // contact's reference acceleration (mj_makeImpedance), not of its force:
  // with a constant impedance d, at rest the contact penetrates
  // r = (1 - d) A f / k for a force f, A being the contact's
  // inverse effective mass (MuJoCo's diagApprox: the actee's 1 / mass
  // against the fixed jaw, a little more against the moving one). So a
  // contact of stiffness K_c (N/m) needs k = K_c (1 - d) / mass. The
  // actee's stiffness is across the jaws: two contacts in series, each
  // 2 K. The damping is critical for that spring and the actee's mass
  // (the engine's actee has none; this only settles the contact's ringing).
  ActeeContact c;
  c.impedance = kContactImpedance;
  const double per_contact = 2 * m.actee_stiffness;  // N/m
  c.stiffness = per_contact * (1 - c.impedance) / m.actee_mass;
  c.damping = 2 * std::sqrt(c.stiffness * (1 - c.impedance));
  return c;
}

int substeps_per_frame(const Model& m) {
  // Explicit in stiffness: keep omega * step <= 1 for the actee on its
  // contacts and for the arm on the hand and the spring.
  double omega = 0;  // rad/s
  if (m.has_actee) omega = std::sqrt(2 * m.actee_stiffness / m.actee_mass);
  const double inertia = arm_inertia_bound(m);
  if (inertia > 0) {
    const double arm = std::abs(m.spring_position);
    const double reach = std::max(std::abs(m.emphasis_from), std::abs(m.emphasis_to));
    const double stiffness = m.spring_constant * arm * arm + m.force_gain * reach * reach;  // N*m/rad
    omega = std::max(omega, std::sqrt(stiffness / inertia));
  }
  return std::max(1, static_cast<int>(std::ceil(omega * m.timestep)));
}

std::string mjcf_scene(const CompiledSession& session) {
  const Model& m = session.model;
  const HingeSpring spring = hinge_spring(m);
  const HandServo hand = hand_servo(session);
  const int substeps = substeps_per_frame(m);
  const double step = m.timestep / substeps;
  const double hard = 2 * step;  // s, the smallest time constant MuJoCo takes

  std::ostringstream x;
  x << "<!--\n"
    << "  MuJoCo scene of the afford session " << comment_text(session.name) << " ("
    << comment_text(session.description) << ")\n"
    << "  written by afford export (MJCF) from " << comment_text(session.file) << "; for MuJoCo 2.2.2.\n"
    << "  World z up, SI units, angles in radians. The tool is fixed at its functional\n"
    << "  pose (the script's carrying of the tool is not in the scene): the fixed arm's\n"
    << "  parts are geoms (named part:NAME) of body 'tool', the moving arm a body turning\n"
    << "  about +z through the object origin on joint 'hinge', whose angle is theta (opening\n"
    << "  positive).\n"
    << "  Hinge: limits [theta_min, theta_max]; the spring S_k = " << num(m.spring_constant) << " N/m at S_p = "
    << num(m.spring_position) << " m with its preload " << num(m.spring_preload) << " N\n"
    << "  is the torsion spring stiffness = S_k S_p^2 = " << num(spring.stiffness)
    << " N*m/rad, springref = rest + preload / (S_k |S_p|) = " << num(spring.springref) << " rad;\n"
    << "  pivot friction is frictionloss, viscous damping damping, the arm's extra inertia armature.\n"
    << "  The arms' masses are the object's, shared by volume; gravity is on only when the\n"
    << "  object's gravity effect is.\n";
  if (m.has_actee) {
    const ActeeContact contact = actee_contact(m);
    x << "  Actee (body 'actee', free): its contacts with the jaws have solimp d = " << num(contact.impedance)
      << " and the direct\n"
      << "  solref (-k, -b): a contact penetrates (1 - d) f / (k mass) for a force f, so k = 2 K (1 - d) / mass\n"
      << "  makes the two contacts in series as stiff as the actee, K = " << num(m.actee_stiffness)
      << " N/m (against the moving jaw\n"
      << "  a little softer: the arm adds to the contact's effective mass). Friction: elliptic cones,\n"
      << "  impratio 100 and MuJoCo's noslip pass, so that the squeezed actee does not creep out of\n"
      << "  the jaws, as it does not in the engine: with soft friction it creeps (about 10 mm/s at\n"
      << "  100 N), and the jaws' push on it, which needs that friction where the jaws are not\n"
      << "  parallel, fell 4 to 9 % short of the contacts' stiffness.\n";
  }
  if (hand.present) {
    x << "  Hand: actuator 'hand', a position servo on the hinge standing for the hand's impedance at\n"
      << "  the thumb, b = " << num(hand.lever_arm) << " m from the fulcrum: kp = force_gain b^2 = " << num(hand.kp)
      << " N*m/rad, kv = hand_damping b^2 = " << num(hand.kv) << ",\n"
      << "  forcerange [-max_force b, 0] with max_force = " << num(hand.max_force)
      << " N (the agent's, capped by the grasp type of the first grip):\n"
      << "  the thumb pushes the arm closed, never pulls it open. Its control is the commanded angle.\n";
  } else {
    x << "  Hand: the script never holds the tool, so there is no hand servo.\n";
  }
  x << "  What the harness must do (the <custom> numerics below):\n"
    << "  - reset to key 'start'; run frames of frame_time s, each of 'substeps' mj_step calls;\n";
  if (hand.present) {
    x << "  - before each step, set ctrl[hand] to hand_schedule (pairs t s, angle rad) interpolated\n"
      << "    linearly in time, at the step's end;\n"
      << "    a keyframe where the hand does not hold the tool commands theta_max (no push);\n";
  }
  x << "  - add the progressive spring to qfrc_applied of the hinge before each step:\n"
    << "    d = spring_arm (springref - theta); if d > 0, torque = spring_cubic d^3 spring_arm (opening);\n"
    << "  - add gravity_extra: torque = -gravity_extra cos(theta) (0 unless the gravity effect is on);\n";
  if (m.has_actee) {
    x << "  - before each step, set the solref of every geom to the actee's law's secant stiffness at\n"
      << "    the deflection d across the jaws (the penetrations of its contacts at the last step):\n"
      << "    solref (-k s, -b sqrt(s)), s = (d / actee_reference)^(actee_exponent - 1) h / (h - d),\n"
      << "    h = actee_thickness, so that the contacts push with the law F = K d_r (d/d_r)^n h/(h - d)\n"
      << "    (actees/README.md) and not the linear K d;\n"
      << "  - the actee's load is the normal force of its contacts with the moving arm (mj_contactForce);\n"
      << "    when actee_breaks is 1 and the load passes actee_limit N, it breaks: set the conaffinity of\n"
      << "    geom 'actee' to 0 (no more contacts), as the engine's broken actee resists no more;\n"
      << "    with actee_breaks 0 it never breaks. actee_exponent and actee_reference are the\n"
      << "    actee_compliance effect's (1 and 0 when it is off).\n";
  }
  x << "-->\n";

  x << "<mujoco model=\"" << attr(session.name) << "\">\n"
    << "  <compiler angle=\"radian\"/>\n"
    << "  <option timestep=\"" << num(step) << "\" gravity=\"0 0 " << (m.gravity ? "-9.80665" : "0")
    << "\" integrator=\"implicit\" cone=\"elliptic\" impratio=\"100\" noslip_iterations=\"10\"/>\n";

  x << "  <custom>\n"
    << "    " << numeric("frame_time", {m.timestep}) << "\n"
    << "    " << numeric("substeps", {static_cast<double>(substeps)}) << "\n"
    << "    " << numeric("theta_rest", {m.theta_rest}) << "\n"
    << "    " << numeric("springref", {spring.springref}) << "\n"
    << "    " << numeric("spring_arm", {std::abs(m.spring_position)}) << "\n"
    << "    " << numeric("spring_cubic", {m.spring_cubic}) << "\n"
    << "    " << numeric("gravity_extra", {m.gravity ? m.gravity_extra : 0.0}) << "\n";
  if (hand.present) {
    std::vector<double> schedule;
    for (const auto& [t, angle] : hand.schedule) {
      schedule.push_back(t);
      schedule.push_back(angle);
    }
    x << "    " << numeric("hand_lever_arm", {hand.lever_arm}) << "\n"
      << "    " << numeric("hand_max_force", {hand.max_force}) << "\n"
      << "    " << numeric("hand_schedule", schedule) << "\n";
  }
  if (m.has_actee) {
    x << "    " << numeric("actee_limit", {m.actee_limit}) << "\n"
      << "    " << numeric("actee_breaks", {m.actee_breaks ? 1.0 : 0.0}) << "\n"
      << "    " << numeric("actee_stiffness", {m.actee_stiffness}) << "\n"
      << "    " << numeric("actee_thickness", {actee_thickness(m)}) << "\n"
      << "    " << numeric("actee_exponent", {m.actee_exponent}) << "\n"
      << "    " << numeric("actee_reference", {m.actee_reference}) << "\n";
  }
  x << "  </custom>\n";

  std::vector<std::string> meshes;
  for (const ModelPart& p : m.parts) {
    if (p.geometry.spec().kind == ShapeKind::convex) meshes.push_back(mesh_asset("mesh:" + p.name, p.geometry.spec()));
  }
  if (m.has_actee && m.actee().spec().kind == ShapeKind::convex) meshes.push_back(mesh_asset("mesh:actee", m.actee().spec()));
  if (!meshes.empty()) {
    x << "  <asset>\n";
    for (const std::string& mesh : meshes) x << "    " << mesh << "\n";
    x << "  </asset>\n";
  }

  if (m.has_actee) {
    const ActeeContact contact = actee_contact(m);
    x << "  <default>\n"
      << "    <geom solref=\"" << num(-contact.stiffness) << " " << num(-contact.damping) << "\" solimp=\""
      << num(contact.impedance) << " " << num(contact.impedance) << " 0.001\"/>\n"
      << "  </default>\n";
  }

  // The arms' masses, shared by volume as the engine shares them (compile.cpp).
  double fixed_volume = 0, moving_volume = 0;
  for (const ModelPart& p : m.parts) (p.arm == Arm::moving ? moving_volume : fixed_volume) += p.geometry.volume();
  const double fixed_mass = m.object_mass - m.arm_mass;
  // Contact bits: fixed arm 1, moving arm 2; the actee takes both, the
  // arms not each other (the hinge's limits stop them).
  x << "  <worldbody>\n"
    << "    <body name=\"tool\" pos=\"" << vec(m.object_start.translation()) << "\" quat=\""
    << quat(m.object_start.linear()) << "\">\n";
  for (const ModelPart& p : m.parts) {
    if (p.arm != Arm::fixed) continue;
    x << "      "
      << geom("part:" + p.name, p.geometry.spec(), p.in_arm, fixed_mass * p.geometry.volume() / fixed_volume, 1, 0, "mesh:" + p.name)
      << "\n";
  }
  x << "      <body name=\"moving_arm\" quat=\"" << quat(moving_arm_pose(m.theta_rest).linear()) << "\">\n"
    << "        <joint name=\"hinge\" type=\"hinge\" pos=\"0 0 0\" axis=\"0 0 1\" ref=\"" << num(m.theta_rest)
    << "\" limited=\"true\" range=\"" << num(m.theta_min) << " " << num(m.theta_max) << "\"\n"
    << "               stiffness=\"" << num(spring.stiffness) << "\" springref=\"" << num(spring.springref)
    << "\" frictionloss=\"" << num(m.friction_torque) << "\" damping=\"" << num(m.damping) << "\" armature=\""
    << num(m.arm_inertia) << "\"\n"
    << "               solreflimit=\"" << num(hard) << " 1\" solimplimit=\"" << num(kLimitImpedance) << " "
    << num(kLimitImpedance) << " 0.001\" solreffriction=\"" << num(hard) << " 1\"/>\n";
  for (const ModelPart& p : m.parts) {
    if (p.arm != Arm::moving) continue;
    x << "        "
      << geom("part:" + p.name, p.geometry.spec(), p.in_arm, m.arm_mass * p.geometry.volume() / moving_volume, 2, 0,
              "mesh:" + p.name)
      << "\n";
  }
  x << "      </body>\n"
    << "    </body>\n";
  if (m.has_actee) {
    x << "    <body name=\"actee\" pos=\"" << vec(m.actee_start.translation()) << "\" quat=\""
      << quat(m.actee_start.linear()) << "\">\n"
      << "      <freejoint name=\"actee\"/>\n"
      << "      " << geom("actee", m.actee().spec(), Eigen::Isometry3d::Identity(), m.actee_mass, 0, 3, "mesh:actee")
      << "\n"
      << "    </body>\n";
  }
  x << "  </worldbody>\n";

  if (hand.present) {
    x << "  <actuator>\n"
      << "    <general name=\"hand\" joint=\"hinge\" gaintype=\"fixed\" gainprm=\"" << num(hand.kp)
      << "\" biastype=\"affine\" biasprm=\"0 " << num(-hand.kp) << " " << num(-hand.kv) << "\"\n"
      << "             forcelimited=\"true\" forcerange=\"" << num(-hand.max_torque) << " 0\"/>\n"
      << "  </actuator>\n";
  }

  // The start: the arm at rest, the actee where the session puts it, the
  // hand pushing nothing.
  x << "  <keyframe>\n"
    << "    <key name=\"start\" qpos=\"" << num(m.theta_rest);
  if (m.has_actee) {
    x << "  " << vec(m.actee_start.translation()) << "  " << quat(m.actee_start.linear());
  }
  x << "\"";
  if (hand.present) x << " ctrl=\"" << num(m.theta_max) << "\"";
  x << "/>\n"
    << "  </keyframe>\n"
    << "</mujoco>\n";
  return x.str();
}

std::string export_mjcf(const CompiledSession& session) {
  if (!session.actee_models.empty()) {
    throw std::runtime_error(session.file + ": export --mjcf takes a session with one actee; this one lists " +
                             std::to_string(session.actee_models.size()) +
                             " ('actees:'): export a session with each alone");
  }
  return mjcf_scene(session);
}

}  // namespace afford
