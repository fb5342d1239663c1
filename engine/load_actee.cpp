// actees/*.yaml -> ActeeSpec.
#include "load.h"

namespace afford {

ActeeSpec read_actee(const Node& root) {
  MapReader m(root, "an actee file",
              {"actee", "description", "shape", "mass", "force_direction", "limit", "stiffness", "breaks"});
  ActeeSpec a;
  a.loc = root.loc();
  a.file = root.loc().file;
  a.name = read_name(m.required("actee"));
  a.description = read_string(m.required("description"));
  a.shape = read_shape(m.required("shape"));
  const Node mass = m.required("mass");
  a.mass = require_positive(mass, read_quantity(mass, dim::mass));
  a.force_direction = read_direction(m.required("force_direction"));
  const Node limit = m.required("limit");
  a.limit_loc = limit.loc();
  a.limit = require_positive(limit, read_quantity(limit, dim::force));
  const Node k = m.required("stiffness");
  a.stiffness = require_positive(k, read_quantity(k, dim::stiffness));
  a.breaks = read_bool(m.required("breaks"));
  return a;
}

ActeeSpec load_actee(const std::string& path) { return read_actee(load_yaml_file(path)); }

}  // namespace afford
