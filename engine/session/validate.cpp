#include "validate.h"

#include "did_you_mean.h"
#include "grasps.h"
#include "guides.h"
#include "load.h"
#include "model.h"
#include "rules.h"
#include "session.h"

namespace afford {
namespace {

std::vector<std::pair<std::string, FileKindCheck>>& added_kinds() {
  static std::vector<std::pair<std::string, FileKindCheck>> kinds;
  return kinds;
}

}  // namespace

void add_file_kind(const std::string& name, FileKindCheck check) {
  for (const auto& [n, c] : added_kinds()) {
    if (n == name) return;
  }
  added_kinds().emplace_back(name, check);
}

std::vector<std::string> file_kinds() {
  std::vector<std::string> kinds{"object", "actee", "agent", "functions", "grasps", "guides", "session"};
  for (const auto& [name, check] : added_kinds()) kinds.push_back(name);
  return kinds;
}

std::string validate_file(const std::string& path, std::vector<Warning>* warnings) {
  return validate_node(load_yaml_file(path), warnings);
}

std::string validate_node(const Node& root, std::vector<Warning>* warnings) {
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
    const auto rules = read_rules(root);
    return "function models, " + std::to_string(function_count(*rules)) + " functions";
  }
  if (kind == "session") {
    const CompiledSession session = read_session(root);
    if (warnings != nullptr) warnings->insert(warnings->end(), session.warnings.begin(), session.warnings.end());
    return "session " + session.name + ", " + std::to_string(session.files.size()) + " files";
  }
  if (kind == "guides") return "guides, " + std::to_string(read_guides(root).size()) + " guides";
  if (kind == "grasps") return "grasp taxonomy, " + std::to_string(read_grasps(root).size()) + " types";
  for (const auto& [name, check] : added_kinds()) {
    if (kind == name) return check(root);
  }
  const std::vector<std::string> kinds = file_kinds();
  std::string expected = "a file whose first key names its kind (";
  for (size_t i = 0; i < kinds.size(); ++i) expected += (i ? ", " : "") + kinds[i];
  root.child(root.yaml().begin()->first).fail(expected + ")", "'" + kind + "'" + did_you_mean(kind, kinds));
}

}  // namespace afford
