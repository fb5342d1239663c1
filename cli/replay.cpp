// afford replay REC [--rules FILE] [--json] [--out DIR]: re-runs a recording (made by
// `afford run --record` or `afford live`) from its recorded model files and
// samples, and checks that every frame's events are the recorded ones, bit
// for bit (exit 1 at the first frame that differs). With --rules it re-runs
// under the function models of FILE instead and prints the difference of
// the two timelines (exit 0). --out DIR also writes DIR/timeline.jsonl and
// DIR/trace.csv, as `afford run` does.
#include <cstdio>
#include <iostream>
#include <optional>
#include <vector>

#include "commands.h"
#include "json_output.h"
#include "option_checks.h"
#include "output_file.h"
#include "recording_source.h"
#include "run.h"
#include "session_outputs.h"
#include "timeline_diff.h"
#include "trace.h"

namespace afford::cli {
namespace {

const char* kEventNames[] = {"node_reached", "node_lost", "inferred"};
const char* kTailNames[] = {"end", "no_end", "incomplete", "corrupt"};

void print_inferences(const RunResult& r) {
  if (r.inferences.empty()) std::cout << "no function inferred\n";
  for (const Inference& inf : r.inferences) {
    std::printf("%s at %.3f s\n", inf.function.c_str(), inf.t);
    for (size_t i = 0; i < inf.nodes.size(); ++i) {
      std::printf("  %8.3f s  %s\n", inf.nodes[i].t, inf.nodes[i].text.c_str());
      if (i < inf.node_details.size() && !inf.node_details[i].empty()) {
        std::printf("  %10s  %s\n", "", inf.node_details[i].c_str());  // the values behind its conditions
      }
    }
  }
  std::fflush(stdout);
}

// An event's fields, for the diff's entries.
void add_event(Json& j, const NamedEvent& e) {
  j["event"] = kEventNames[static_cast<int>(e.kind)];
  j["function"] = e.function;
  j["node"] = e.node;
  j["text"] = e.text;
}

// The recorded events must name functions and nodes of the recorded rules.
void check_events(const Recording& rec, const RuleSet& rules) {
  for (const Event& e : rec.events) {
    const bool ok = e.function >= 0 && e.function < function_count(rules) && e.node >= 0 &&
                    e.node < node_count(rules, e.function);
    if (!ok) throw std::runtime_error(rec.file + ": the recorded events do not match the recorded function models");
  }
}

struct ReplayOptions {
  std::string file, rules_file, out_dir;
  bool json = false, force = false;
};

int replay(const ReplayOptions& o) {
  const std::string& file = o.file;
  const std::string& rules_file = o.rules_file;
  const std::string& out_dir = o.out_dir;
  const bool json = o.json;
  // The recording is an input: never an output (engine/base/output_file.h).
  const OutputScope scope({.writer = "replay", .force = o.force, .inputs = {file}});
  const Recording rec = read_recording(file);
  const CompiledSession session = load_recorded_session(rec);
  check_events(rec, *session.rules);
  const std::vector<std::string> changed = changed_since_recording(rec);
  if (!json) {
    std::cout << "recording " << rec.file << ": session " << rec.session_name << " (" << rec.source << "), "
              << rec.summary() << "\n";
    for (const std::string& f : changed) {
      std::cout << "note: " << f << " has changed since the recording (or is gone); replaying the recorded copy\n";
    }
    std::cout.flush();
  }
  RecordingSource source(rec);
  std::optional<SessionOutputs> outputs;
  if (!out_dir.empty()) outputs.emplace(out_dir);
  // The checkers first, then the files when asked for.
  const auto with_outputs = [&outputs](std::vector<Observer*> observers) {
    if (outputs) observers.insert(observers.end(), {outputs->timeline(), outputs->trace()});
    return observers;
  };

  if (rules_file.empty()) {
    ReplayChecker checker(rec, true);
    const std::vector<Observer*> observers = with_outputs({&checker});
    const RunResult result = run_session(session, *session.rules, source, observers);
    if (outputs) outputs->close();  // checked, and renamed into place
    if (json) {
      Json j = {{"recording", rec.file},
                {"session", rec.session_name},
                {"frames", result.frames},
                {"tail", kTailNames[static_cast<int>(rec.tail)]},
                {"changed_since", changed},
                {"identical", checker.identical()},
                {"functions", inferences_json(result)}};
      if (!checker.identical()) {
        j["first_difference"] = {{"frame", checker.first_difference()}, {"detail", checker.describe(*session.rules)}};
      }
      std::cout << j.dump() << "\n";
      return checker.identical() ? 0 : 1;
    }
    print_inferences(result);
    if (!checker.identical()) {
      std::cout << "replayed " << result.frames << " frames: " << checker.describe(*session.rules) << "\n";
      return 1;
    }
    std::cout << "replayed " << result.frames << " frames: events identical to the recording";
    if (rec.tail == RecordingTail::end) std::cout << ", and the final state";
    std::cout << "\n";
    return 0;
  }

  // Under edited function models: the same samples, other rules.
  const std::shared_ptr<const RuleSet> rules = load_rules(rules_file);  // DataError: file:line:col
  ReplayChecker physics(rec, false);  // the state must still be the recorded one
  TimelineCollector rerun(rec.events.size() + 1024);
  const std::vector<Observer*> observers = with_outputs({&physics, &rerun});
  const RunResult result = run_session(session, *rules, source, observers);
  if (outputs) outputs->close();
  std::vector<NamedEvent> recorded;
  recorded.reserve(rec.events.size());
  for (const Event& e : rec.events) recorded.push_back(name_event(*session.rules, e));
  const TimelineDiff diff = diff_timelines(recorded, rerun.named(*rules));

  if (json) {
    Json changes = Json::array();
    for (const TimelineChange& c : diff.changes) {
      static const char* kChange[] = {"only_recorded", "only_rerun", "shifted"};
      Json entry = {{"change", kChange[c.kind]}};
      add_event(entry, c.kind == TimelineChange::added ? c.after : c.before);
      if (c.kind != TimelineChange::added) entry["recorded_t"] = json_number(c.before.t);
      if (c.kind != TimelineChange::removed) entry["rerun_t"] = json_number(c.after.t);
      changes.push_back(std::move(entry));
    }
    const Json j = {{"recording", rec.file},       {"rules", rules_file},   {"frames", result.frames},
                    {"functions", inferences_json(result)}, {"same", diff.same}, {"diff", changes},
                    {"same_state", physics.identical()}};
    std::cout << j.dump() << "\n";
    return 0;
  }
  std::cout << "re-ran " << result.frames << " frames under " << rules_file << "\n";
  print_inferences(result);
  if (!physics.identical()) {
    std::cout << "note: the simulation itself differs from the recording: " << physics.describe(*rules) << "\n";
  }
  if (diff.identical()) {
    std::cout << "the timelines are identical (" << diff.same << " events)\n";
    return 0;
  }
  std::cout << "timeline difference, recorded (-) vs re-run (+):\n" << format_diff(diff);
  std::cout << diff.same << " events the same, " << diff.shifted << " shifted, " << diff.removed
            << " only in the recording, " << diff.added << " only in the re-run\n";
  return 0;
}

}  // namespace

void add_replay(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "replay", "re-run a recording: the recorded events bit for bit, or the timeline diff under edited rules");
  auto o = std::make_shared<ReplayOptions>();
  cmd->add_option("REC", o->file, "a recording (made by afford run --record or afford live)")
      ->required()
      ->type_name(kFile);
  cmd->add_option("--rules", o->rules_file, "re-run under these function models and diff the timelines")
      ->type_name(kFile);
  cmd->add_flag("--json", o->json, "print the result as JSON");
  cmd->add_option("--out", o->out_dir, "also write timeline.jsonl and trace.csv into DIR")->type_name(kDir);
  cmd->add_flag("--force", o->force, "replace existing output files that afford did not write");
  cmd->callback([run, o] { *run = [o] { return replay(*o); }; });
}

}  // namespace afford::cli
