#include "effects.h"

namespace afford {

const std::vector<EffectManifest>& effect_registry() {
  static const std::vector<EffectManifest> kRegistry = {
      {EffectKind::pivot_friction, "pivot_friction",
       "Coulomb friction at the pivot: a constant torque against the motion",
       {{"torque", dim::torque, true, "friction torque, N*m"}}},
      {EffectKind::viscous_damping, "viscous_damping",
       "viscous damping at the pivot: a torque against the angular speed, proportional to it",
       {{"coefficient", dim::rotational_damping, true, "damping coefficient, N*m*s/rad"}}},
      {EffectKind::progressive_spring, "progressive_spring",
       "a stiffening spring: adds cubic * d^3 to the spring's force",
       {{"cubic", dim::cubic_stiffness, true, "cubic coefficient, N/m^3"}}},
      {EffectKind::arm_inertia, "arm_inertia",
       "the moving arm's inertia about the pivot: torque = inertia * angular acceleration",
       {{"inertia", dim::inertia, false, "moment of inertia about the pivot, kg*m^2"}}},
  };
  return kRegistry;
}

const EffectManifest* find_effect(std::string_view name) {
  for (const EffectManifest& m : effect_registry()) {
    if (name == m.name) return &m;
  }
  return nullptr;
}

}  // namespace afford
