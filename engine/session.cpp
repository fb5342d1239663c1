// Session files -> CompiledSession (see session.h).
#include "session.h"

#include <filesystem>
#include <unistd.h>

#include "grasps.h"
#include "load.h"
#include "units.h"

namespace afford {
namespace {

namespace fs = std::filesystem;

constexpr double kDefaultTimestep = 1e-3;          // s
constexpr double kDefaultContactTolerance = 5e-4;  // m
constexpr double kMinTimestep = 1e-5;              // s: finer only fills the disk
constexpr double kMaxTimestep = 0.1;               // s: coarser is no simulation of a hand

// The node of `key` itself in a mapping (errors about the key: a missing file).
Node key_node(const Node& map, std::string_view key) {
  for (auto it = map.yaml().begin(); it != map.yaml().end(); ++it) {
    if (it->first.Scalar() == key) return map.child(it->first);
  }
  return map;
}

class Files {
 public:
  Files(const Node& root, std::vector<std::string>* read) : read_(read) {
    base_ = fs::path(root.loc().file).parent_path();
  }

  // The path a `key: path` names, resolved against the session's folder,
  // checked to be a readable file (reported at the key) and recorded.
  std::string resolve(const Node& map, std::string_view key, const Node& value) {
    const std::string given = read_string(value);
    if (given.empty()) value.fail("a path to a file");
    fs::path p(given);
    if (p.is_relative()) p = base_ / p;
    const std::string path = p.lexically_normal().string();
    const std::string expected =
        "a readable file '" + given + "'" + (fs::path(given).is_relative() ? " (relative to the session's folder)" : "");
    std::error_code ec;
    if (fs::is_directory(path, ec)) key_node(map, key).fail(expected, "a directory");
    if (!fs::is_regular_file(path, ec) || ::access(path.c_str(), R_OK) != 0) key_node(map, key).fail(expected, "none");
    read_->push_back(path);
    return path;
  }

  // A path, or the file's content in place (a mapping).
  Node document(const Node& map, std::string_view key, const Node& value) {
    if (value.is_map()) return value;
    if (!value.is_scalar()) value.fail("a path to a file, or the file's content as a mapping");
    return load_yaml_file(resolve(map, key, value));
  }

 private:
  fs::path base_;
  std::vector<std::string>* read_;
};

void read_actee_entry(const Node& node, Files& files, ActeeSpec* actee, ModelOptions* options) {
  MapReader m(node, "the actee", {"file", "at", "position", "rotation"});
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

// `camera: {position, target, up?, fov?}`: eye and target apart, up not
// along the view, a field of view inside (0, 180) deg.
SessionCamera read_camera(const Node& node) {
  MapReader m(node, "the camera", {"position", "target", "up", "fov"});
  SessionCamera c;
  c.set = true;
  c.position = read_vector(m.required("position"), dim::length);
  const Node target = m.required("target");
  c.target = read_vector(target, dim::length);
  if ((c.target - c.position).norm() < 1e-9) target.fail("a target away from the camera's position", "the same point");
  if (std::optional<Node> up = m.optional("up")) {
    c.up = read_direction(*up);
    if (c.up.cross((c.target - c.position).normalized()).norm() < 1e-6) {
      up->fail("an up direction across the line of sight", "one along it");
    }
  }
  if (std::optional<Node> fov = m.optional("fov")) {
    c.fov = read_positive(*fov, dim::angle);
    if (c.fov >= 3.1) fov->fail("a field of view below 180 deg");
  }
  return c;
}

}  // namespace

CompiledSession read_session(const Node& root) {
  const std::string kind = file_kind(root);
  if (kind != "session") {
    root.child(root.yaml().begin()->first).fail("a session file (its first key 'session')", "'" + kind + "'");
  }
  MapReader m(root, "a session file",
              {"session", "description", "object", "actee", "agent", "rules", "grasps", "timestep",
               "contact_tolerance", "camera", "script"});
  CompiledSession s;
  s.file = root.loc().file;
  s.files.push_back(s.file);
  Files files(root, &s.files);
  s.name = read_name(m.required("session"));
  s.description = read_string(m.required("description"));

  ModelOptions options;
  options.timestep = kDefaultTimestep;
  options.contact_tolerance = kDefaultContactTolerance;
  if (std::optional<Node> dt = m.optional("timestep")) {
    options.timestep = read_positive(*dt, dim::time);
    if (options.timestep > kMaxTimestep || options.timestep < kMinTimestep) {
      dt->fail("a timestep from " + format_quantity(kMinTimestep, dim::time) + " to " +
               format_quantity(kMaxTimestep, dim::time));
    }
  }
  if (std::optional<Node> tol = m.optional("contact_tolerance")) {
    options.contact_tolerance = read_positive(*tol, dim::length);
  }

  // Parse every file first, then compile (the object before the actee that
  // is placed on it).
  const ObjectSpec object = read_object(files.document(root, "object", m.required("object")));
  std::optional<ActeeSpec> actee;
  if (std::optional<Node> a = m.optional("actee")) {
    actee.emplace();
    read_actee_entry(*a, files, &*actee, &options);
  }
  const AgentSpec agent = read_agent(files.document(root, "agent", m.required("agent")));
  const Node rules_node = m.required("rules");
  const std::string rules_path = files.resolve(root, "rules", rules_node);
  const Node grasps_node = m.required("grasps");
  options.grasps = load_grasps(files.resolve(root, "grasps", grasps_node));
  const ScriptSpec script = read_script(m.required("script"));
  if (std::optional<Node> cam = m.optional("camera")) s.camera = read_camera(*cam);

  s.rules = load_rules(rules_path);
  s.model = compile(object, actee ? &*actee : nullptr, &agent, options);
  s.script = compile_script(script, s.model);
  return s;
}

CompiledSession load_session(const std::string& path) { return read_session(load_yaml_file(path)); }

}  // namespace afford
