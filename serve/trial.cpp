// The trials of a served session (trial.h).
#include "trial.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "derive.h"
#include "files.h"
#include "load.h"

namespace afford::serve {

namespace fs = std::filesystem;

std::vector<ShelfActee> actee_shelf(const std::string& folder) {
  std::vector<ShelfActee> shelf;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    if (!e.is_regular_file() || e.path().extension() != ".yaml") continue;
    shelf.push_back({e.path().stem().string(), e.path().string()});
  }
  if (ec) throw std::runtime_error("cannot list the actees in " + folder + ": " + ec.message());
  std::sort(shelf.begin(), shelf.end(), [](const ShelfActee& a, const ShelfActee& b) { return a.name < b.name; });
  return shelf;
}

std::vector<ShelfActee> actee_shelf(const std::string& shipped, const std::string& user) {
  std::vector<ShelfActee> shelf = actee_shelf(shipped);
  if (user.empty()) return shelf;
  std::error_code ec;
  if (fs::equivalent(shipped, user, ec)) return shelf;  // the shipped folder named again
  if (!fs::is_directory(user)) throw std::runtime_error("--actees " + user + ": not a folder");
  const size_t shipped_count = shelf.size();
  for (ShelfActee& a : actee_shelf(user)) {
    load_actee(a.file);  // a mistake in the user's file stops the start, located, not the trial that takes it
    for (size_t i = 0; i < shipped_count; ++i) {
      if (shelf[i].name == a.name) {
        throw std::runtime_error(a.file + ": an actee named '" + a.name + "' is already on the shelf (" +
                                 shelf[i].file + "); rename the file");
      }
    }
    shelf.push_back(std::move(a));
  }
  return shelf;
}

std::vector<std::string> shelf_names(const std::vector<ShelfActee>& shelf) {
  std::vector<std::string> names;
  for (const ShelfActee& a : shelf) names.push_back(a.name);
  return names;
}

bool valid_participant(const std::string& id) {
  if (id.empty() || id.size() > 32) return false;
  return std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
  });
}

std::string trial_stem(const std::string& participant, int trial) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%03d", trial);
  return participant + "-trial-" + buf;
}

int next_trial(const fs::path& dir, const std::string& participant) {
  const std::string prefix = participant + "-trial-";
  int highest = 0;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    int n = 0;
    size_t i = prefix.size();
    for (; i < name.size() && name[i] >= '0' && name[i] <= '9' && n < 100000; ++i) n = n * 10 + (name[i] - '0');
    if (i > prefix.size()) highest = std::max(highest, n);
  }
  return highest + 1;  // a folder that does not exist yet holds no trials
}

namespace {

// `value` (a path relative to the session's folder, or absolute) relative to DIR.
std::string moved(const fs::path& session_dir, const std::string& value, const fs::path& dir) {
  fs::path p(value);
  if (p.is_relative()) p = session_dir / p;
  return fs::absolute(p).lexically_normal().lexically_relative(fs::absolute(dir).lexically_normal()).generic_string();
}

std::string millimetres(double m) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g mm", m * 1e3);
  return buf;
}

// The actee at `at` on the fixed jaw, or (at empty) at `position` in the world.
YAML::Node trial_document(const CompiledSession& original, const std::string& actee_file, const std::string& at,
                          const Eigen::Vector3d& position, const fs::path& dir) {
  const YAML::Node src = YAML::LoadFile(original.file);
  const fs::path from = fs::path(original.file).parent_path();
  YAML::Node out(YAML::NodeType::Map);
  out["session"] = src["session"];
  out["description"] = src["description"];
  const auto path_or_content = [&](const char* key) {
    const YAML::Node v = src[key];
    out[key] = v.IsScalar() ? YAML::Node(moved(from, v.as<std::string>(), dir)) : YAML::Clone(v);
  };
  path_or_content("object");
  if (!actee_file.empty()) {
    YAML::Node entry(YAML::NodeType::Map);
    entry["file"] = moved(fs::current_path(), actee_file, dir);
    if (!at.empty()) {
      entry["at"] = at;
    } else {
      YAML::Node p(YAML::NodeType::Sequence);
      p.SetStyle(YAML::EmitterStyle::Flow);
      for (int i = 0; i < 3; ++i) p.push_back(millimetres(position[i]));
      entry["position"] = p;
    }
    out["actee"] = entry;
  } else {
    YAML::Node entry;
    if (src["actee"]) {
      entry = YAML::Clone(src["actee"]);
    } else if (src["actees"]) {
      entry = YAML::Clone(src["actees"][original.first_actee]);
      entry.remove("name");
    }
    if (entry.IsMap()) {
      if (entry["file"].IsScalar()) entry["file"] = moved(from, entry["file"].as<std::string>(), dir);
      out["actee"] = entry;
    }
  }
  path_or_content("agent");
  out["rules"] = moved(from, src["rules"].as<std::string>(), dir);
  out["grasps"] = moved(from, src["grasps"].as<std::string>(), dir);
  for (const char* key : {"timestep", "contact_tolerance", "camera"}) {
    if (src[key]) out[key] = YAML::Clone(src[key]);
  }
  YAML::Node first = YAML::Clone(src["script"][0]);
  first.remove("actee");
  YAML::Node script(YAML::NodeType::Sequence);
  script.push_back(first);
  YAML::Node still(YAML::NodeType::Map);  // a script must last: held still a second (not played)
  still["hold"] = "1 s";
  script.push_back(still);
  out["script"] = script;
  return out;
}

CompiledSession write_and_load(const YAML::Node& doc, const CompiledSession& original, const fs::path& file) {
  YAML::Emitter e;
  e << YAML::Comment("afford serve: a trial of " + original.file + " (the page drives the hand)") << YAML::Newline;
  e << doc;
  if (!e.good()) throw std::runtime_error("cannot write the trial's session: " + e.GetLastError());
  write_file_checked(file.string(), std::string(e.c_str()) + "\n");
  return load_session(file.string());
}

}  // namespace

CompiledSession write_trial_session(const CompiledSession& original, const std::string& actee_file,
                                    const fs::path& dir, const std::string& stem) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create " + dir.string() + ": " + ec.message());
  const fs::path file = dir / (stem + ".yaml");
  // First beside the tool (off the jaws, in the world), to see where the
  // jaws close on it; then there, or, fitting nowhere, left beside the tool.
  const Model& m = original.model;
  const Eigen::Vector3d beside =
      m.object_start * Eigen::Vector3d(0.5 * (m.application_from + m.application_to), -0.15, 0);
  if (actee_file.empty()) return write_and_load(trial_document(original, "", "", beside, dir), original, file);
  CompiledSession s = write_and_load(trial_document(original, actee_file, "", beside, dir), original, file);
  if (!s.model.has_actee) return s;
  const ActeeFit fit = fit_actee(s.model);
  if (!fit.fits) return s;
  return write_and_load(trial_document(original, actee_file, millimetres(0.5 * (fit.from + fit.to)), beside, dir),
                        original, file);
}

}  // namespace afford::serve
