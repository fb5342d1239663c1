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

// An effect's parameters, from its manifest in the registry.
const MapSchema& effect_schema(const EffectManifest& e) {
  static const std::vector<MapSchema> kEffects = [] {
    std::vector<MapSchema> all;
    for (const EffectManifest& m : effect_registry()) {
      MapSchema s{m.doc, {schema::optional_key("enabled", schema::boolean(), "false switches the effect off")}};
      for (const EffectParam& p : m.params) {
        s.keys.push_back(schema::required_key(
            p.key, p.dimension == dim::none ? schema::number() : schema::quantity(p.dimension), p.doc));
      }
      all.push_back(std::move(s));
    }
    return all;
  }();
  // Every manifest is the registry's own (find_effect, manifest_of).
  return kEffects[static_cast<size_t>(&e - effect_registry().data())];
}

}  // namespace

const MapSchema& effects_schema(EffectHome home) {
  static const std::vector<MapSchema> kHomes = [] {
    std::vector<MapSchema> all;
    for (EffectHome h : {EffectHome::object, EffectHome::actee, EffectHome::measurement}) {
      MapSchema s{std::string("the effects of ") + home_name(h) + " files (afford describe --effects)"};
      for (const std::string& name : effect_names_for(h)) {
        const EffectManifest& e = *find_effect(name);
        s.keys.push_back(schema::optional_key(name, schema::mapping(effect_schema(e)), e.doc));
      }
      all.push_back(std::move(s));
    }
    return all;
  }();
  return kHomes[static_cast<size_t>(home)];
}

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
  MapReader m(node, "the effects", effects_schema(home));
  std::vector<EffectSpec> effects;
  for (const auto& [name, value] : m.entries()) {
    const EffectManifest* manifest = find_effect(name);
    if (manifest == nullptr) throw LogicError("an effect passed MapReader but is not registered: " + name);
    (void)m.required(name);  // reports an effect with no value
    MapReader params(value, "the effect " + name, effect_schema(*manifest));
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
