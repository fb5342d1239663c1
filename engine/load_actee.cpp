// actees/*.yaml -> ActeeSpec.
#include "load.h"

namespace afford {

const MapSchema& actee_schema() {
  using namespace schema;
  static const MapSchema kActee{
      "an actee file: what a tool acts on (actees/README.md)",
      {required_key("actee", name(), "the actee's name"),
       required_key("description", text(), "what it is, in a sentence"),
       required_key("shape", mapping(shape_schema()), "its collision shape"),
       required_key("mass", quantity(dim::mass), "its mass"),
       required_key("force_direction", plain_vector(),
                    "A_d: the direction (actee frame) along which force counts against the limit"),
       required_key("limit", quantity(dim::force),
                    "A_pv: the force along force_direction above which it breaks (or counts as squeezed)"),
       required_key("stiffness", quantity(dim::stiffness), "its contact stiffness at small deflections"),
       required_key("breaks", boolean(), "true: brittle, breaks above the limit; false: compliant, never breaks"),
       required_key("friction", mapping(friction_schema()),
                    "its static friction on the jaws: the grip must carry its weight for it to count as held"),
       optional_key("effects", mapping(effects_schema(EffectHome::actee)), "optional effects of the actee")}};
  return kActee;
}

ActeeSpec read_actee(const Node& root) {
  MapReader m(root, "an actee file", actee_schema());
  ActeeSpec a;
  a.loc = root.loc();
  a.file = root.loc().file;
  a.name = read_name(m.required("actee"));
  a.description = read_string(m.required("description"));
  a.shape = read_shape(m.required("shape"));
  a.mass = read_positive(m.required("mass"), dim::mass);
  a.force_direction = read_direction(m.required("force_direction"));
  const Node limit = m.required("limit");
  a.limit_loc = limit.loc();
  a.limit = read_positive(limit, dim::force);
  a.stiffness = read_positive(m.required("stiffness"), dim::stiffness);
  a.breaks = read_bool(m.required("breaks"));
  a.friction = read_friction(m.required("friction"), &a.friction_source);
  if (std::optional<Node> effects = m.optional("effects")) a.effects = read_effects(*effects, EffectHome::actee);
  return a;
}

ActeeSpec load_actee(const std::string& path) { return read_actee(load_yaml_file(path)); }

}  // namespace afford
