// `afford view`'s document (recording_view.h).
#include "recording_view.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "data_dir.h"
#include "guides.h"
#include "page_agent.h"
#include "protocol.h"
#include "recording_source.h"
#include "run.h"
#include "scene_message.h"

namespace afford::serve {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

// Collects the states (60 a second of session time, and each frame with
// an event) and the events, already formatted, as the page gets them live.
class Collector : public Observer {
 public:
  void on_start(const Model& model, const State&, const RuleSet&) override {
    every_ = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::lround(1.0 / 60.0 / model.timestep)));
  }
  void on_frame(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override {
    const bool events = events_begin(rs) != events_end(rs);
    for (const Event* e = events_begin(rs); e != events_end(rs); ++e) {
      events_ += events_.empty() ? "" : ",";
      events_ += frame_event_message(rules, rs, *e);
    }
    if (state.frame % every_ != 0 && !events) return;
    fill_state_message(state, model, &message_);
    const size_t n = format_state(message_, buffer_.data(), buffer_.size());
    if (n == 0) return;
    states_ += states_.empty() ? "" : ",";
    states_.append(buffer_.data(), n);
  }
  std::string states_, events_;

 private:
  std::int64_t every_ = 17;
  StateMessage message_;
  std::array<char, kStateMessageBytes> buffer_{};
};

}  // namespace

RecordingView recording_view(const std::string& recording_file) {
  const Recording rec = read_recording(recording_file);
  const CompiledSession session = load_recorded_session(rec);
  RecordingSource source(rec);
  ReplayChecker checker(rec, true);
  Collector collector;
  Observer* const observers[] = {&checker, &collector};
  const RunResult result = run_session(session, *session.rules, source, observers);

  // The grip only names the posture in the scene; a recording of a tool
  // the page could not grip is still shown.
  PageGrip grip;
  try {
    grip = page_grip(session);
  } catch (const std::runtime_error&) {
  }
  const PageStart start = page_start(session);
  // The shipped guides, as `afford guide` computes them.
  const Guides guides = compute_guides(session.model, load_guides(shipped_path("rules/guides.yaml")));
  SceneInfo info{0, "", rec.file, session.model.has_actee ? session.model.actee_name : "", {}, &guides};
  const std::string scene = scene_message(session, grip, start, command_limits(session.model, grip, start), info);

  const Json head{{"file", rec.file},         {"session", rec.session_name},   {"source", rec.source},
                  {"summary", rec.summary()}, {"identical", checker.identical()}, {"end_time", result.end_time}};
  std::string json = head.dump(-1, ' ', false, Json::error_handler_t::replace);
  json.pop_back();  // the closing brace: the large parts follow
  json.insert(1, "\"type\":\"recording\",");
  json += ",\"scene\":" + scene + ",\"states\":[" + collector.states_ + "],\"events\":[" + collector.events_ + "]}";

  RecordingView view;
  view.json = std::move(json);
  view.session_name = rec.session_name;
  view.frames = result.frames;
  view.inferences = static_cast<int>(result.inferences.size());
  view.identical = checker.identical();
  return view;
}

std::string find_recording(const std::string& path) {
  const fs::path p(path);
  std::error_code ec;
  if (fs::is_regular_file(p, ec)) return path;
  if (!fs::is_directory(p, ec)) throw std::runtime_error(path + ": no such recording or folder");
  std::vector<fs::path> found;
  for (const fs::directory_entry& e : fs::directory_iterator(p, ec)) {
    if (e.is_regular_file() && e.path().extension() == ".afrec") found.push_back(e.path());
  }
  if (found.size() == 1) return found.front().string();
  if (found.size() > 1) {
    throw std::runtime_error(path + ": holds " + std::to_string(found.size()) +
                             " recordings (.afrec): name the one to view");
  }
  // A trial's outputs of `afford serve`: DIR/P-trial-NNN/ beside DIR/P-trial-NNN.afrec.
  fs::path beside = p.lexically_normal();
  if (beside.filename().empty()) beside = beside.parent_path();
  beside += ".afrec";
  if (fs::is_regular_file(beside, ec)) return beside.string();
  throw std::runtime_error(path + ": no recording (.afrec) in it or beside it (" + beside.string() +
                           "); `afford run SESSION --out DIR --record DIR/run.afrec` records one");
}

}  // namespace afford::serve
