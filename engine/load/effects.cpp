#include "effects.h"

#include <stdexcept>

namespace afford {

const char* home_name(EffectHome h) {
  switch (h) {
    case EffectHome::object: return "object";
    case EffectHome::actee: return "actee";
    case EffectHome::measurement: return "measurement";
  }
  return "?";
}

// The bounds are sanity bounds for hand tools and what they squeeze: a value
// outside them is a typo or a unit slip, never a tool (e.g. 100 N*m of
// friction would need a 600 N squeeze at a 160 mm handle just to move it).
const std::vector<EffectManifest>& effect_registry() {
  static const std::vector<EffectManifest> kRegistry = {
      {EffectKind::pivot_friction, "pivot_friction", EffectHome::object,
       "Coulomb friction at the pivot, with stiction: a torque against the motion; at rest the arm "
       "stays while the net torque on it is below the friction torque",
       {{"torque", dim::torque, 0, true, 100, "friction torque, N*m", false}}},
      {EffectKind::viscous_damping, "viscous_damping", EffectHome::object,
       "viscous damping at the pivot: a torque against the angular speed, proportional to it",
       {{"coefficient", dim::rotational_damping, 0, true, 100, "damping coefficient, N*m*s/rad", false}}},
      {EffectKind::spring_preload, "spring_preload", EffectHome::object,
       "the spring's preload: a constant torque, the force the spring pushes with at the rest angle "
       "times its distance from the fulcrum (the spring section's `preload` key sets it)",
       {{"force", dim::force, -1e4, true, 1e4,
         "the spring's push at the rest angle (negative: it pulls the tool closed; a measured tool's keeps "
         "the file's sign, as a spring that pushes cannot pull), N", true}}},
      {EffectKind::progressive_spring, "progressive_spring", EffectHome::object,
       "a stiffening spring: adds cubic * d^3 to the spring's force (d its compression)",
       {{"cubic", dim::cubic_stiffness, 0, true, 1e15, "cubic coefficient, N/m^3", false}}},
      {EffectKind::actee_compliance, "actee_compliance", EffectHome::actee,
       "the actee's stiffness law as a power of its deflection, as in Hertzian contact: "
       "F = stiffness * reference * (deflection / reference)^exponent (exponent 1 is linear, 1.5 "
       "Hertz); like every actee it stiffens without bound as it nears zero thickness",
       {{"exponent", dim::none, 0.1, true, 10, "power of the deflection, plain number", false},
        {"reference", dim::length, 0, false, 1, "deflection at which the law's secant stiffness is the "
                                                "actee's `stiffness`, m", false}}},
      {EffectKind::arm_inertia, "arm_inertia", EffectHome::object,
       "the moving arm's inertia about the pivot: the arm has dynamics, torque = inertia * angular "
       "acceleration, integrated implicitly (stable at any step)",
       {{"inertia", dim::inertia, 0, false, 10, "moment of inertia about the pivot, kg*m^2", false}}},
      {EffectKind::gravity, "gravity", EffectHome::object,
       "the moving arm's weight about the pivot, from the tool's mass shared by the parts' volumes, "
       "their centroids and the tool's orientation in the world; a torque that follows the cosine of "
       "the arm's angle from the horizontal",
       {{"extra_torque", dim::torque, -100, true, 100,
         "torque amplitude added to the computed one (a measured tool's unmodelled weight), N*m", false}}},
      {EffectKind::sensor_latency, "sensor_latency", EffectHome::measurement,
       "a delay of the measured effort channel: the sensor reports the effort of `delay` ago",
       {{"delay", dim::time, 0, true, 1, "delay, s", false}}},
  };
  return kRegistry;
}

const EffectManifest* find_effect(std::string_view name) {
  for (const EffectManifest& m : effect_registry()) {
    if (name == m.name) return &m;
  }
  return nullptr;
}

const EffectManifest& manifest_of(EffectKind kind) {
  for (const EffectManifest& m : effect_registry()) {
    if (m.kind == kind) return m;
  }
  throw std::logic_error("an effect kind without a manifest");
}

std::vector<std::string> effect_names_for(EffectHome home) {
  std::vector<std::string> names;
  for (const EffectManifest& m : effect_registry()) {
    if (home == EffectHome::measurement || m.home == home) names.emplace_back(m.name);
  }
  return names;
}

}  // namespace afford
