// The registry of optional torque terms that an object file can switch on
// (BehaviorTree.CPP-style: one manifest per kind, checked before building).
#pragma once

#include <string_view>
#include <vector>

#include "units.h"

namespace afford {

enum class EffectKind { pivot_friction, viscous_damping, progressive_spring, arm_inertia };

struct EffectParam {
  const char* key;
  Dimension dimension;
  bool zero_allowed;  // false: must be > 0; true: must be >= 0
  const char* doc;
};

struct EffectManifest {
  EffectKind kind;
  const char* name;
  const char* doc;
  std::vector<EffectParam> params;
};

const std::vector<EffectManifest>& effect_registry();
const EffectManifest* find_effect(std::string_view name);  // nullptr if unknown

}  // namespace afford
