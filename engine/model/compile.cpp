// Spec -> Model, as a list of passes (MuJoCo's compiler style).
#include <algorithm>
#include <cmath>

#include "model.h"
#include "reach.h"
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
  m.emphasis_from = o.emphasis.from;
  m.emphasis_to = o.emphasis.to;
  m.application_from = o.application.from;
  m.application_to = o.application.to;
  m.space_distances = o.interaction_space.distances;
  m.space_gaps = o.interaction_space.gaps;
  m.object_mass = o.mass;
  m.object_start = to_isometry(o.functional_pose);
  m.symmetry_point = o.symmetry_plane.point;
  m.symmetry_normal = o.symmetry_plane.normal;
}

void compile_parts(const ObjectSpec& o, Model& m) {
  double total = 0, moving = 0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // m^4: volume times centroid, moving arm frame
  for (const PartSpec& p : o.parts) {
    m.parts.push_back(ModelPart{p.name, p.arm, Geometry::compile(p.shape), to_isometry(p.pose), p.friction});
    const ModelPart& part = m.parts.back();
    const double v = part.geometry.volume();
    total += v;
    if (part.arm == Arm::moving) {
      moving += v;
      moment += v * (part.in_arm * part.geometry.centroid());
    }
  }
  // The tool's mass shared by volume: the arms are of one material.
  m.arm_mass = total > 0 ? o.mass * moving / total : 0.0;
  m.arm_centre = moving > 0 ? Eigen::Vector3d(moment / moving) : Eigen::Vector3d::Zero();
}

// The effects of the object, then the actee's, then those a measurement
// gives, which replace one of the same name; then their numbers, resolved
// for the solver.
void compile_effects(const ObjectSpec* o, const ActeeSpec* a, const ModelOptions& options, Model& m) {
  auto add = [&m](const std::vector<EffectSpec>& list) {
    for (const EffectSpec& e : list) {
      const ModelEffect effect{e.kind, e.name, e.enabled, e.param, e.loc};
      auto same = std::find_if(m.effects.begin(), m.effects.end(), [&](const ModelEffect& x) { return x.kind == e.kind; });
      if (same != m.effects.end()) {
        *same = effect;
      } else {
        m.effects.push_back(effect);
      }
    }
  };
  if (o != nullptr) add(o->effects);
  if (a != nullptr) add(a->effects);
  add(options.effects);
  for (const ModelEffect& e : m.effects) {
    if (!e.enabled) continue;
    switch (e.kind) {
      case EffectKind::pivot_friction: m.friction_torque = e.param[0]; break;
      case EffectKind::viscous_damping: m.damping = e.param[0]; break;
      case EffectKind::spring_preload: m.spring_preload = e.param[0]; break;
      case EffectKind::progressive_spring: m.spring_cubic = e.param[0]; break;
      case EffectKind::actee_compliance:
        m.actee_exponent = e.param[0];
        m.actee_reference = e.param[1];
        break;
      case EffectKind::arm_inertia: m.arm_inertia = e.param[0]; break;
      case EffectKind::gravity:
        m.gravity = true;
        m.gravity_extra = e.param[0];
        break;
      case EffectKind::sensor_latency: m.sensor_latency = e.param[0]; break;
    }
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
  m.actee_friction = a.friction;
  m.actee_look = a.look;
  if (!options.actee.in_jaws) {
    m.actee_start = options.actee.world;
    return;
  }
  // Resting on the fixed jaw's inner face (y = 0) at the given distance.
  m.actee_on_jaw = true;
  const double r = options.actee.distance;
  if (r < m.arm_from || r > m.arm_to) {
    fail(options.actee.loc,
         "a distance on the arm, between " + format_quantity(m.arm_from, dim::length) + " and " +
             format_quantity(m.arm_to, dim::length),
         format_quantity(r, dim::length));
  }
  // Only the application region is jaw: elsewhere the arms are handles.
  if (r < m.application_from || r > m.application_to) {
    fail(options.actee.loc,
         "a distance in the application region, between " + format_quantity(m.application_from, dim::length) +
             " and " + format_quantity(m.application_to, dim::length),
         format_quantity(r, dim::length));
  }
  const double lift = m.actee().support(-Eigen::Vector3d::UnitY());
  Eigen::Isometry3d in_object = Eigen::Isometry3d::Identity();
  in_object.translation() = Eigen::Vector3d(r, lift, 0);
  m.actee_start = m.object_start * in_object;
  // An actee placed in the jaws must be one they can close on.
  ContactQuery query;
  double theta_c = 0, load_distance = 0;
  const JawFit fit = find_contact_angle(m, in_object, query, &theta_c, &load_distance, nullptr);
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
  m.hand_damping = a.damping;
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
  compile_reach(a, m);  // the fingers' chains (reach.h)
}

}  // namespace

Model compile(const ObjectSpec& object, const ActeeSpec* actee, const AgentSpec* agent,
              const ModelOptions& options) {
  Model m;
  m.timestep = options.timestep;                    // frame period
  m.contact_tolerance = options.contact_tolerance;  // touching distance
  compile_lever(object, m);                         // lever, spring, regions, pose
  compile_parts(object, m);                         // FCL shapes of the arms
  if (actee != nullptr) compile_actee(*actee, options, m);  // shape, limit, placement
  compile_effects(&object, actee, options, m);      // optional terms, resolved
  if (agent != nullptr) compile_agent(*agent, m);   // fingertips, joint ranges, f_a
  compile_grasps(options.grasps, m);                // taxonomy: flat joint ranges
  return m;
}

Model compile_actee_only(const ActeeSpec& actee, const ModelOptions& options) {
  Model m;
  ModelOptions free = options;
  free.actee.in_jaws = false;  // no jaws to rest in
  compile_actee(actee, free, m);
  compile_effects(nullptr, &actee, options, m);
  return m;
}

Model compile_agent_only(const AgentSpec& agent) {
  Model m;
  compile_agent(agent, m);
  return m;
}

Eigen::Isometry3d moving_arm_pose(double theta_rad) {
  // A turn about z written out: AngleAxis's general formula cost three
  // times as much, several times a frame.
  const double c = std::cos(theta_rad), s = std::sin(theta_rad);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() << c, -s, 0,  //
      s, c, 0,                //
      0, 0, 1;
  return pose;
}

const ModelEffect* enabled_effect(const Model& m, EffectKind kind) {
  for (const ModelEffect& e : m.effects) {
    if (e.kind == kind && e.enabled) return &e;
  }
  return nullptr;
}

}  // namespace afford
