// The registry of optional effects: terms of the lever's dynamics (and one
// of the measurement) that a data file can switch on, each with a manifest
// (BehaviorTree.CPP-style: checked before anything is built). The names are
// fixed: measurements and gap reports refer to them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "units.h"

namespace afford {

enum class EffectKind {
  pivot_friction,
  viscous_damping,
  spring_preload,
  progressive_spring,
  actee_compliance,
  arm_inertia,
  gravity,
  sensor_latency,
};
inline constexpr int kEffectKinds = 8;

// Which kind of file an effect is written in: it describes that thing.
enum class EffectHome { object, actee, measurement };
const char* home_name(EffectHome h);  // "object", "actee", "measurement"

struct EffectParam {
  const char* key;
  Dimension dimension;
  double min;         // SI, smallest value allowed
  bool min_included;  // false: the value must be strictly above min
  double max;         // SI, largest value allowed (a sanity bound, inclusive)
  const char* doc;    // with its unit
  // A measured tool's value may not cross zero from its file's: the sign
  // is the part's kind (a spring that pushes the tool open cannot pull it
  // shut). Where the file's value is zero, either sign.
  bool keeps_sign;
};

struct EffectManifest {
  EffectKind kind;
  const char* name;
  EffectHome home;
  const char* doc;  // what it does, in one sentence
  std::vector<EffectParam> params;
};

const std::vector<EffectManifest>& effect_registry();
const EffectManifest* find_effect(std::string_view name);  // nullptr if unknown
const EffectManifest& manifest_of(EffectKind kind);

// The names of the effects a file of this kind may switch on (a measurement
// may switch on any of them).
std::vector<std::string> effect_names_for(EffectHome home);

}  // namespace afford
