// Session files -> CompiledSession (see session.h).
#include "session.h"

#include <algorithm>
#include <filesystem>
#include <unistd.h>

#include "data_files.h"
#include "did_you_mean.h"
#include "grasps.h"
#include "load.h"
#include "reach.h"
#include "units.h"

namespace afford {
namespace {

constexpr double kDefaultTimestep = 1e-3;          // s
constexpr double kDefaultContactTolerance = 5e-4;  // m
constexpr double kMinTimestep = 1e-5;              // s: finer only fills the disk
constexpr double kMaxTimestep = 0.1;               // s: coarser is no simulation of a hand
constexpr size_t kMaxActees = 64;                  // of one session: more is a mistake, not an experiment

// `camera: {position, target, up?, fov?}`: eye and target apart, up not
// along the view, a field of view inside (0, 180) deg.
const MapSchema& camera_schema() {
  using namespace schema;
  static const MapSchema kCamera{
      "where the renderer looks from",
      {required_key("position", vector(dim::length), "the eye, in the world"),
       required_key("target", vector(dim::length), "the point looked at, away from the eye"),
       optional_key("up", plain_vector(), "the up direction, across the line of sight"),
       optional_key("fov", quantity(dim::angle), "the vertical field of view, below 180 deg")}};
  return kCamera;
}

SessionCamera read_camera(const Node& node) {
  MapReader m(node, "the camera", camera_schema());
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

// A keyframe's `actee:` names one of the session's `actees:`: its index,
// and when the script takes it (the first keyframe's: from the start).
void take_actees(ScriptSpec& script, CompiledSession& s) {
  for (size_t i = 0; i < script.keyframes.size(); ++i) {
    KeyframeSpec& k = script.keyframes[i];
    if (k.actee.empty()) continue;
    if (s.actee_names.empty()) {
      fail(k.actee_loc, "no 'actee:' here (the session lists no 'actees:' to take one of)", "'" + k.actee + "'");
    }
    const auto it = std::find(s.actee_names.begin(), s.actee_names.end(), k.actee);
    if (it == s.actee_names.end()) {
      std::string expected = "an actee of the session's 'actees:' (";
      for (size_t j = 0; j < s.actee_names.size(); ++j) expected += (j ? ", " : "") + s.actee_names[j];
      fail(k.actee_loc, expected + ")", "'" + k.actee + "'" + did_you_mean(k.actee, s.actee_names));
    }
    k.actee_index = static_cast<int>(it - s.actee_names.begin());
    if (i == 0) {
      s.first_actee = static_cast<size_t>(k.actee_index);
    } else {
      s.actee_changes.push_back({k.t, static_cast<size_t>(k.actee_index)});
    }
  }
}

}  // namespace

const MapSchema& session_schema() {
  using namespace schema;
  static const MapSchema kSession{
      "a session file: an object, an actee, an agent and its script (sessions/README.md)",
      {required_key("session", name(), "the session's name"),
       required_key("description", text(), "what happens, in a sentence"),
       required_key("object", any_of({path(), mapping(object_schema())}), "the object file, or its content"),
       optional_key("actee", mapping(actee_entry_schema()), "the actee and where it is"),
       optional_key("actees", sequence(mapping(named_actee_entry_schema()), 1, kMaxActees),
                    "several actees instead of one: the first on the tool at the start, a keyframe's `actee:` "
                    "takes another"),
       required_key("agent", any_of({path(), mapping(agent_schema())}), "the agent file, or its content"),
       required_key("rules", path(), "the function-model file"),
       required_key("grasps", path(), "the grasp taxonomy file"),
       optional_key("timestep", quantity(dim::time), "the simulation step, 10 us to 100 ms (default 1 ms)"),
       optional_key("contact_tolerance", quantity(dim::length), "how near counts as touching (default 0.5 mm)"),
       optional_key("camera", mapping(camera_schema()), "where the renderer looks from"),
       required_key("script", sequence_starting(mapping(first_keyframe_schema()), mapping(keyframe_schema()), 1),
                    "the agent's keyframes")}};
  return kSession;
}

CompiledSession read_session(const Node& root) {
  const std::string kind = file_kind(root);
  if (kind != "session") {
    root.child(root.yaml().begin()->first).fail("a session file (its first key 'session')", "'" + kind + "'");
  }
  MapReader m(root, "a session file", session_schema());
  CompiledSession s;
  s.file = root.loc().file;
  s.files.push_back(s.file);
  Files files(root, "session", &s.files);
  s.name = read_name(m.required("session"));
  s.description = read_string(m.required("description"));

  ModelOptions options;
  options.timestep = kDefaultTimestep;
  options.contact_tolerance = kDefaultContactTolerance;
  if (std::optional<Node> dt = m.optional("timestep")) {
    options.timestep = read_positive(*dt, dim::time);
    if (!at_most(options.timestep, kMaxTimestep) || !at_least(options.timestep, kMinTimestep)) {  // 10 us passes
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
    if (m.has("actees")) a->fail("either 'actee' or 'actees' (several)", "both");
    actee.emplace();
    read_actee_entry(*a, files, &*actee, &options);
  }
  // Several actees: each with its own placement.
  std::vector<std::pair<ActeeSpec, ActeePlacement>> several;
  if (std::optional<Node> list = m.optional("actees")) {
    if (!list->is_sequence() || list->size() == 0) list->fail("a sequence of actees");
    if (list->size() > kMaxActees) {
      list->fail("at most " + std::to_string(kMaxActees) + " actees", std::to_string(list->size()));
    }
    for (size_t i = 0; i < list->size(); ++i) {
      std::pair<ActeeSpec, ActeePlacement> entry;
      ModelOptions placed;
      std::string name;
      read_named_actee_entry((*list)[i], files, &entry.first, &placed, &name);
      entry.second = placed.actee;
      for (const std::string& before : s.actee_names) {
        if (before == name) {
          (*list)[i].fail("an actee named apart from the others (give it a 'name')", "'" + name + "' again");
        }
      }
      s.actee_names.push_back(name);
      several.push_back(std::move(entry));
    }
  }
  const AgentSpec agent = read_agent(files.document(root, "agent", m.required("agent")));
  const Node rules_node = m.required("rules");
  const std::string rules_path = files.resolve(root, "rules", rules_node);
  const Node grasps_node = m.required("grasps");
  options.grasps = load_grasps(files.resolve(root, "grasps", grasps_node));
  ScriptSpec script = read_script(m.required("script"));
  if (std::optional<Node> cam = m.optional("camera")) s.camera = read_camera(*cam);

  s.rules = load_rules(rules_path);
  take_actees(script, s);
  if (several.empty()) {
    s.model = compile(object, actee ? &*actee : nullptr, &agent, options);
    s.warnings = setup_warnings(s.model, object.spring.loc);
  } else {
    for (const auto& [spec, placement] : several) {
      ModelOptions entry_options = options;
      entry_options.actee = placement;
      s.actee_models.push_back(compile(object, &spec, &agent, entry_options));
      // The spring's warnings once, each actee's own once.
      for (const Warning& w : setup_warnings(s.actee_models.back(), object.spring.loc)) {
        const auto same = [&](const Warning& x) { return x.message == w.message; };
        if (std::none_of(s.warnings.begin(), s.warnings.end(), same)) s.warnings.push_back(w);
      }
    }
    s.model = s.actee_models[s.first_actee];
  }
  s.script = compile_script(script, s.model, s.actee_models);
  check_script_reach(m.required("script"), s.script, s.model);  // fingertips the hand can reach (reach.h)
  return s;
}

CompiledSession load_session(const std::string& path) { return read_session(load_yaml_file(path)); }

}  // namespace afford
