// afford run SESSION [--json] [--out DIR] [--watch [--runs N]] [--record FILE]:
// simulates a session file, prints each inferred function with its time and
// explanation, and writes the timeline (DIR/timeline.jsonl) and the trace
// (DIR/trace.csv); DIR defaults to out/<session name>. With --watch it runs
// again whenever a file the session uses changes. --record FILE also writes
// a recording (devices/recording.h) for `afford replay`. Outputs go through
// engine/base/output_file.h: an existing file afford did not write, or one of the
// session's own files, is not replaced (--force replaces the former).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <thread>

#include "commands.h"
#include "option_checks.h"
#include "closest_approach.h"
#include "files.h"
#include "output_file.h"
#include "progress.h"
#include "recording.h"
#include "run.h"
#include "scripted_agent.h"
#include "session.h"
#include "json_output.h"
#include "session_outputs.h"
#include "trace.h"

namespace afford::cli {
namespace {

namespace fs = std::filesystem;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

void print_text(const CompiledSession& s, const RunResult& r, const std::vector<FunctionProgress>& progress,
                const std::string& written) {
  std::cout << "session " << s.name << ": " << s.description << "\n";
  std::cout << r.frames << " frames of " << format_quantity(s.model.timestep, dim::time) << " to "
            << number(r.end_time) << " s\n";
  if (r.inferences.empty()) {
    // Why not: how near each function came (the rule tests' closest approach).
    std::cout << "no function inferred\nhow close each function came:\n";
    for (const FunctionProgress& p : progress) std::cout << "  " << p.function << ": " << progress_text(p) << "\n";
  }
  for (const Inference& inf : r.inferences) {
    std::printf("%s at %.3f s\n", inf.function.c_str(), inf.t);
    for (size_t i = 0; i < inf.nodes.size(); ++i) {
      std::printf("  %8.3f s  %s\n", inf.nodes[i].t, inf.nodes[i].text.c_str());
      if (i < inf.node_details.size() && !inf.node_details[i].empty()) {
        std::printf("  %10s  %s\n", "", inf.node_details[i].c_str());  // the values behind its conditions
      }
    }
  }
  std::cout << "wrote " << written << "\n";
}

void print_json(const CompiledSession& s, const RunResult& r) {
  const Json j = {{"session", s.name}, {"functions", inferences_json(r)}, {"frames", r.frames}};
  std::cout << j.dump() << "\n";
}

// A run of more frames than this says so before it starts.
constexpr std::int64_t kAnnouncedFrames = 1000000;

// The frames a scripted session steps (run_session's count).
std::int64_t scripted_frames(const CompiledSession& session) {
  const double duration = ScriptedAgent(session.script).duration();
  return static_cast<std::int64_t>(std::floor(duration / session.model.timestep + 1e-9));
}

// Runs a compiled session once: writes the timeline and the trace, prints
// the verdicts.
void run_once(const CompiledSession& session, const std::string& out_dir, bool json, bool force,
              const std::string& record = {}) {
  for (const Warning& w : session.warnings) std::cerr << w.str() << "\n";  // it runs, but see why it may do nothing
  const OutputScope scope({.writer = "run", .force = force, .inputs = session.files});
  const std::int64_t frames = scripted_frames(session);
  if (frames > kAnnouncedFrames) {
    std::cerr << "run: " << frames << " frames of " << format_quantity(session.model.timestep, dim::time)
              << " to simulate; progress below\n";
  }
  RunResult result;
  std::vector<FunctionProgress> closest;  // each function's closest approach
  std::int64_t recorded = -1;
  std::string written;
  {
    SessionOutputs outputs(output_dir(out_dir, session.name));
    written = outputs.written();
    ProgressObserver progress;
    FrameProgress frame_progress(frames);
    std::vector<Observer*> observers = {outputs.timeline(), outputs.trace(), &progress, &frame_progress};
    std::optional<Recorder> recorder;
    if (!record.empty()) observers.push_back(&recorder.emplace(record, session, "script " + session.file, frames));
    ScriptedAgent agent(session.script);
    result = run_session(session, *session.rules, agent, observers);
    if (recorder && !recorder->error().empty()) throw std::runtime_error(recorder->error());
    if (recorder) recorded = recorder->frames();
    closest = progress.progress();
    outputs.close();  // a full disk: exit 1 naming the file, never "wrote"
  }
  if (json) {
    print_json(session, result);
  } else {
    print_text(session, result, closest, written);
    if (recorded >= 0) std::cout << "recorded " << recorded << " frames to " << record << "\n";
  }
  std::cout.flush();
}

// What a file looked like when last read: a change of either means an edit.
struct Stamp {
  fs::file_time_type time{};
  std::uintmax_t size = 0;
  bool exists = false;
  bool operator==(const Stamp&) const = default;
};

std::vector<Stamp> stamps(const std::vector<std::string>& files) {
  std::vector<Stamp> out;
  for (const std::string& f : files) {
    std::error_code ec;
    Stamp s;
    s.time = fs::last_write_time(f, ec);
    s.exists = !ec;
    if (s.exists) s.size = fs::file_size(f, ec);
    out.push_back(s);
  }
  return out;
}

// --watch: re-runs whenever a file the session read changes. A broken edit
// prints its error and keeps the last good model (run again once the file
// is fixed). `runs` > 0 stops after that many runs or failed reloads.
int watch(const std::string& file, const std::string& out_dir, bool json, bool force, long runs) {
  std::optional<CompiledSession> good;
  std::vector<std::string> files{file};
  long done = 0;
  while (true) {
    // Stamped before reading, so that an edit made while it runs is seen.
    std::vector<Stamp> before = stamps(files);
    try {
      CompiledSession session = load_session(file);
      if (session.files != files) {
        files = session.files;
        before = stamps(files);  // first run, or the session now names other files
      }
      run_once(session, out_dir, json, force);
      good = std::move(session);
    } catch (const DataError& e) {
      std::cout << e.what() << "\n";
      if (good) std::cout << "keeping the last good model (" << good->name << "); fix the file to run again\n";
      std::cout.flush();
    }
    if (runs > 0 && ++done >= runs) return good ? 0 : 1;
    std::cout << "watching " << files.size() << " files for changes (Ctrl-C to stop)\n";
    std::cout.flush();
    while (stamps(files) == before) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::cout << "changed: re-running\n";
  }
}

struct RunOptions {
  std::string file, out_dir, record;
  bool json = false, watch = false, force = false;
  long runs = 0;
};

int run_command(const RunOptions& o) {
  if (o.watch) return watch(o.file, o.out_dir, o.json, o.force, o.runs);
  run_once(load_session(o.file), o.out_dir, o.json, o.force, o.record);  // DataError: file:line:col, exit 1
  return 0;
}

}  // namespace

void add_run(CLI::App& app, Run* run) {
  CLI::App* cmd =
      app.add_subcommand("run", "simulate a session: inferred functions and why, timeline and trace files");
  auto o = std::make_shared<RunOptions>();
  cmd->add_option("SESSION", o->file, "a session file (sessions/*.yaml)")->required()->type_name(kFile);
  cmd->add_flag("--json", o->json, "print the inferred functions as JSON");
  cmd->add_option("--out", o->out_dir, "the folder of timeline.jsonl and trace.csv (default out/<session>)")
      ->type_name(kDir);
  CLI::Option* watch = cmd->add_flag("--watch", o->watch, "run again whenever a file the session uses changes");
  cmd->add_option("--runs", o->runs, "with --watch: stop after N runs")
      ->type_name("N")
      ->check(count_above_zero())
      ->needs(watch);
  cmd->add_option("--record", o->record, "also write a recording to FILE, for afford replay")
      ->type_name(kFile)
      ->excludes(watch);
  cmd->add_flag("--force", o->force, "replace existing output files that afford did not write");
  cmd->callback([run, o] { *run = [o] { return run_command(*o); }; });
}

}  // namespace afford::cli
