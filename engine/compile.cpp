// Spec -> Model, as a list of passes (MuJoCo's compiler style).
#include <cmath>

#include "model.h"
#include "stages.h"
#include "units.h"

namespace afford {
namespace {

Eigen::Isometry3d to_isometry(const PoseSpec& pose) {
  Eigen::Isometry3d iso = Eigen::Isometry3d::Identity();
  iso.linear() = pose.rotation;
  iso.translation() = pose.position;
  return iso;
}

void compile_lever(const ObjectSpec& o, Model& m) {
  m.object_name = o.name;
  m.pattern = o.lever.pattern;
  m.arm_from = o.lever.arm.from;
  m.arm_to = o.lever.arm.to;
  m.theta_min = o.lever.theta_min;
  m.theta_max = o.lever.theta_max;
  m.theta_rest = o.lever.theta_rest;
  m.spring_constant = o.spring.constant;
  m.spring_position = o.spring.position;
  m.spring_rest_length = o.spring.rest_length;
  m.emphasis_from = o.emphasis.from;
  m.emphasis_to = o.emphasis.to;
  m.application_from = o.application.from;
  m.application_to = o.application.to;
  m.object_mass = o.mass;
  m.object_start = to_isometry(o.functional_pose);
  m.symmetry_point = o.symmetry_plane.point;
  m.symmetry_normal = o.symmetry_plane.normal;
}

void compile_parts(const ObjectSpec& o, Model& m) {
  for (const PartSpec& p : o.parts) {
    m.parts.push_back(ModelPart{p.name, p.arm, Geometry::compile(p.shape), to_isometry(p.pose)});
  }
}

void compile_effects(const ObjectSpec& o, Model& m) {
  for (const EffectSpec& e : o.effects) {
    const EffectManifest* manifest = find_effect(e.name);
    if (manifest == nullptr) throw LogicError("effect passed validation but is not registered: " + e.name);
    m.effects.push_back(ModelEffect{manifest->kind, e.name, e.enabled, e.param[0]});
  }
}

void compile_actee(const ActeeSpec& a, const ModelOptions& options, Model& m) {
  m.has_actee = true;
  m.actee_name = a.name;
  m.actee_geometry.push_back(Geometry::compile(a.shape));
  m.actee_direction = a.force_direction;
  m.actee_limit = a.limit;
  m.actee_stiffness = a.stiffness;
  m.actee_breaks = a.breaks;
  m.actee_mass = a.mass;
  if (!options.actee.in_jaws) {
    m.actee_start = options.actee.world;
    return;
  }
  // Resting on the fixed jaw's inner face (y = 0) at the given distance.
  const double r = options.actee.distance;
  if (r < m.arm_from || r > m.arm_to) {
    fail(options.actee.loc,
         "a distance on the arm, between " + format_quantity(m.arm_from, dim::length) + " and " +
             format_quantity(m.arm_to, dim::length),
         format_quantity(r, dim::length));
  }
  const double lift = m.actee().support(-Eigen::Vector3d::UnitY());
  Eigen::Isometry3d in_object = Eigen::Isometry3d::Identity();
  in_object.translation() = Eigen::Vector3d(r, lift, 0);
  m.actee_start = m.object_start * in_object;
  // An actee placed in the jaws must be one they can close on.
  ContactQuery query;
  double theta_c = 0;
  const JawFit fit = find_contact_angle(m, in_object, query, &theta_c, nullptr);
  const std::string where = "at " + format_quantity(r, dim::length);
  const double thickness = m.actee().support(Eigen::Vector3d::UnitY()) + lift;
  if (fit == JawFit::too_large) {
    fail(options.actee.loc,
         "an actee that fits between the jaws " + where + " (opening " +
             format_quantity(std::abs(r) * std::sin(m.theta_max), dim::length) + " at theta_max)",
         a.name + ", " + format_quantity(thickness, dim::length) + " thick");
  }
  if (fit != JawFit::fits) {
    fail(options.actee.loc, "an actee the jaws can close on " + where,
         a.name + ", which the moving jaw " + (fit == JawFit::out_of_reach ? "never reaches" : "would push off the fixed jaw"));
  }
}

void compile_agent(const AgentSpec& a, Model& m) {
  m.has_agent = true;
  m.agent_name = a.name;
  m.force_gain = a.force_gain;
  m.max_force = a.max_force;
  for (int i = 0; i < kFingers; ++i) {
    const FingerSpec& f = a.fingers[static_cast<size_t>(i)];
    m.tip_radius[static_cast<size_t>(i)] = f.tip_radius;
    m.joint_min[static_cast<size_t>(i)] = f.joint_min;
    m.joint_max[static_cast<size_t>(i)] = f.joint_max;
    ShapeSpec tip;
    tip.kind = ShapeKind::sphere;
    tip.radius = f.tip_radius;
    tip.loc = a.loc;
    m.fingertip.push_back(Geometry::compile(tip));
  }
}

}  // namespace

Model compile(const ObjectSpec& object, const ActeeSpec* actee, const AgentSpec* agent,
              const ModelOptions& options) {
  Model m;
  m.timestep = options.timestep;                    // frame period
  m.contact_tolerance = options.contact_tolerance;  // touching distance
  compile_lever(object, m);                         // lever, spring, regions, pose
  compile_parts(object, m);                         // FCL shapes of the arms
  compile_effects(object, m);                       // optional torque terms
  if (actee != nullptr) compile_actee(*actee, options, m);  // shape, limit, placement
  if (agent != nullptr) compile_agent(*agent, m);   // fingertips, joint ranges, f_a
  compile_grasps(options.grasps, m);                // taxonomy: flat joint ranges
  return m;
}

Model compile_agent_only(const AgentSpec& agent) {
  Model m;
  compile_agent(agent, m);
  return m;
}

Eigen::Isometry3d moving_arm_pose(double theta_rad) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(theta_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

double spring_compression(const Model& m, double theta_rad) {
  return m.spring_rest_length - std::abs(m.spring_position) * theta_rad;
}

}  // namespace afford
