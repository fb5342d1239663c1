#include "data_files.h"

#include <unistd.h>

#include "load.h"
#include "units.h"

namespace afford {

namespace fs = std::filesystem;


Files::Files(const Node& root, std::string kind, std::vector<std::string>* read)
    : kind_(std::move(kind)), read_(read) {
  base_ = fs::path(root.loc().file).parent_path();
}

std::string Files::resolve(const Node& map, std::string_view key, const Node& value) {
  const std::string given = read_string(value);
  if (given.empty()) value.fail("a path to a file");
  fs::path p(given);
  if (p.is_relative()) p = base_ / p;
  const std::string path = p.lexically_normal().string();
  const std::string expected =
      "a readable file '" + given + "'" + (fs::path(given).is_relative() ? " (relative to the " + kind_ + "'s folder)" : "");
  std::error_code ec;
  if (fs::is_directory(path, ec)) key_node(map, key).fail(expected, "a directory");
  if (!fs::is_regular_file(path, ec) || ::access(path.c_str(), R_OK) != 0) key_node(map, key).fail(expected, "none");
  read_->push_back(path);
  return path;
}

Node Files::document(const Node& map, std::string_view key, const Node& value) {
  if (value.is_map()) return value;
  if (!value.is_scalar()) value.fail("a path to a file, or the file's content as a mapping");
  return load_yaml_file(resolve(map, key, value));
}


const MapSchema& actee_entry_schema() {
  using namespace schema;
  static const MapSchema kEntry = [] {
    MapSchema m{"the actee and where it is: 'at' on the fixed jaw, or 'position' in the world",
                {required_key("file", any_of({path(), mapping(actee_schema())}),
                              "the actee file, or its content as a mapping"),
                 optional_key("at", quantity(dim::length), "a distance on the fixed jaw, from the fulcrum")},
                false,
                {{"at", "position"}}};
    for (KeySchema& k : pose_keys("the actee in the world")) {
      k.required = false;  // given with 'position' instead of 'at'
      m.keys.push_back(std::move(k));
    }
    return m;
  }();
  return kEntry;
}

const MapSchema& named_actee_entry_schema() {
  using namespace schema;
  static const MapSchema kNamed = [] {
    MapSchema m = actee_entry_schema();
    m.description = "one of the session's actees and where it is; a script's keyframe takes it by name";
    m.keys.push_back(optional_key("name", name(), "what the script calls it (default: the actee file's name)"));
    return m;
  }();
  return kNamed;
}

namespace {

void read_entry(MapReader& m, const Node& node, Files& files, ActeeSpec* actee, ModelOptions* options) {
  *actee = read_actee(files.document(node, "file", m.required("file")));
  if (m.has("at") && m.has("position")) {
    key_node(node, "position").fail("either 'at' (on the fixed jaw) or 'position' (in the world)", "both");
  }
  if (std::optional<Node> at = m.optional("at")) {
    if (m.has("rotation")) key_node(node, "rotation").fail("'rotation' only with 'position'", "'at'");
    options->actee.in_jaws = true;
    options->actee.distance = read_quantity(*at, dim::length);
    options->actee.loc = at->loc();
    return;
  }
  if (!m.has("position")) node.fail("key 'at' (a distance on the fixed jaw) or 'position' (in the world)", "neither");
  const PoseSpec pose = read_pose(m);
  options->actee.in_jaws = false;
  options->actee.world.setIdentity();
  options->actee.world.linear() = pose.rotation;
  options->actee.world.translation() = pose.position;
  options->actee.loc = key_node(node, "position").loc();
}

}  // namespace

void read_actee_entry(const Node& node, Files& files, ActeeSpec* actee, ModelOptions* options) {
  MapReader m(node, "the actee", actee_entry_schema());
  read_entry(m, node, files, actee, options);
}

void read_named_actee_entry(const Node& node, Files& files, ActeeSpec* actee, ModelOptions* options,
                            std::string* name) {
  MapReader m(node, "an actee of the session", named_actee_entry_schema());
  read_entry(m, node, files, actee, options);
  const std::optional<Node> given = m.optional("name");
  *name = given ? read_name(*given) : actee->name;
}

}  // namespace afford
