// actees/*.yaml -> ActeeSpec.
#include "load.h"

namespace afford {

ActeeSpec read_actee(const Node& root) {
  MapReader m(root, "an actee file",
              {"actee", "description", "shape", "mass", "force_direction", "limit", "stiffness", "breaks",
               "effects"});
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
  if (std::optional<Node> effects = m.optional("effects")) a.effects = read_effects(*effects, EffectHome::actee);
  return a;
}

ActeeSpec load_actee(const std::string& path) { return read_actee(load_yaml_file(path)); }

}  // namespace afford
