#include "validate.h"

#include "did_you_mean.h"
#include "grasps.h"
#include "load.h"
#include "model.h"
#include "rules.h"
#include "session.h"

namespace afford {

std::vector<std::string> file_kinds() { return {"object", "actee", "agent", "functions", "grasps", "session"}; }

std::string validate_file(const std::string& path) {
  const Node root = load_yaml_file(path);
  const std::string kind = file_kind(root);
  if (kind == "object") {
    const ObjectSpec o = read_object(root);
    (void)compile(o, nullptr, nullptr, ModelOptions{});  // builds every shape
    return "object " + o.name;
  }
  if (kind == "actee") {
    const ActeeSpec a = read_actee(root);
    (void)Geometry::compile(a.shape);
    return "actee " + a.name;
  }
  if (kind == "agent") return "agent " + read_agent(root).name;
  if (kind == "functions") {
    const auto rules = load_rules(path);
    return "function models, " + std::to_string(function_count(*rules)) + " functions";
  }
  if (kind == "session") {
    const CompiledSession session = read_session(root);
    return "session " + session.name + ", " + std::to_string(session.files.size()) + " files";
  }
  if (kind == "grasps") return "grasp taxonomy, " + std::to_string(read_grasps(root).size()) + " types";
  const std::vector<std::string> kinds = file_kinds();
  std::string expected = "a file whose first key names its kind (";
  for (size_t i = 0; i < kinds.size(); ++i) expected += (i ? ", " : "") + kinds[i];
  root.child(root.yaml().begin()->first).fail(expected + ")", "'" + kind + "'" + did_you_mean(kind, kinds));
}

}  // namespace afford
