// The `effects:` mapping of an object, actee or measurement file: each
// effect by its registered name, its parameters with units and bounds, and
// `enabled` (optional, default true, so that one can be switched off without
// deleting it).
#include <cmath>

#include "effects.h"
#include "load.h"

namespace afford {
namespace {

double read_param(const Node& v, const EffectParam& p) {
  const double x = p.dimension == dim::none ? read_number(v) : read_quantity(v, p.dimension);
  const bool above_min = p.min_included ? x >= p.min : x > p.min;
  if (!above_min || x > p.max) {
    v.fail(std::string("a value ") + (p.min_included ? "from " : "above ") + format_quantity(p.min, p.dimension) +
           " to " + format_quantity(p.max, p.dimension) + " (" + p.doc + ")");
  }
  return x;
}

}  // namespace

std::vector<EffectSpec> read_effects(const Node& node, EffectHome home) {
  // An effect of another kind of file gets its own message: a typo gets
  // "did you mean" from the MapReader below.
  if (node.is_map()) {
    for (const auto& kv : node.yaml()) {
      const EffectManifest* e = find_effect(kv.first.Scalar());
      if (e != nullptr && home != EffectHome::measurement && e->home != home) {
        node.child(kv.first).fail(std::string("an effect of an ") + home_name(home) + " file",
                                  std::string("'") + e->name + "', which belongs in " +
                                      (e->home == EffectHome::actee ? "an " : "a ") + home_name(e->home) +
                                      " file");
      }
    }
  }
  MapReader m(node, "the effects", effect_names_for(home));
  std::vector<EffectSpec> effects;
  for (const auto& [name, value] : m.entries()) {
    const EffectManifest* manifest = find_effect(name);
    if (manifest == nullptr) throw LogicError("an effect passed MapReader but is not registered: " + name);
    (void)m.required(name);  // reports an effect with no value
    std::vector<std::string> keys{"enabled"};
    for (const EffectParam& p : manifest->params) keys.emplace_back(p.key);
    MapReader params(value, "the effect " + name, keys);
    EffectSpec effect;
    effect.name = name;
    effect.kind = manifest->kind;
    effect.loc = value.loc();
    for (size_t i = 0; i < manifest->params.size(); ++i) {
      effect.param[i] = read_param(params.required(manifest->params[i].key), manifest->params[i]);
    }
    if (std::optional<Node> enabled = params.optional("enabled")) effect.enabled = read_bool(*enabled);
    effects.push_back(effect);
  }
  return effects;
}

}  // namespace afford
