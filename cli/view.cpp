// afford view REC|OUT_DIR [--port N] [--bind ADDR] [--duration S]:
// opens a recording (`afford run --record`, `live`, `serve`) in the page of
// `afford serve` to play, pause, scrub and jump to each event with its
// explanation (serve/viewer.h). OUT_DIR is a folder holding one recording,
// or a trial's outputs folder of `afford serve` (beside its .afrec).
// Prints the address; Ctrl-C (or --duration of wall time) ends it.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <limits>
#include <thread>

#include "commands.h"
#include "option_checks.h"
#include "recording_view.h"
#include "viewer.h"

namespace afford::cli {
namespace {

std::atomic<bool> g_view_stop{false};

extern "C" void on_view_interrupt(int) { g_view_stop.store(true); }

struct ViewCliOptions {
  serve::ViewOptions viewer;
  std::string path;
  double duration = std::numeric_limits<double>::infinity();  // s of wall time
};

int view(ViewCliOptions o) {
  serve::ViewOptions& v = o.viewer;
  if (v.bind != "127.0.0.1" && v.bind != "localhost") {
    std::fprintf(stderr, "afford: warning: serving on %s, not only on this machine (127.0.0.1): anyone who can "
                 "reach it can watch the recording\n", v.bind.c_str());
  }
  if (v.bind == "localhost") v.bind = "127.0.0.1";
  v.recording = serve::find_recording(o.path);  // std::runtime_error: what was looked for
  serve::Viewer viewer(v);                       // re-runs the recording
  viewer.start();
  std::printf("viewing %s (%lld frames, %d functions inferred%s) at %s; Ctrl-C ends\n", v.recording.c_str(),
              static_cast<long long>(viewer.frames()), viewer.inferences(),
              viewer.identical() ? "" : "; the re-run differs from the recording: `afford replay` says where",
              viewer.url().c_str());
  std::fflush(stdout);
  auto previous = std::signal(SIGINT, on_view_interrupt);
  auto previous_term = std::signal(SIGTERM, on_view_interrupt);
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(std::min(o.duration, 1e9));
  while (!g_view_stop.load() && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  viewer.stop();
  std::signal(SIGINT, previous);
  std::signal(SIGTERM, previous_term);
  return 0;
}

}  // namespace

void add_view(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "view", "open a recording in the web page of serve: play, pause, scrub, jump to each function inferred");
  auto o = std::make_shared<ViewCliOptions>();
  cmd->add_option("REC", o->path, "a recording (.afrec) or a folder holding one (a trial of serve, run --out)")
      ->required()
      ->type_name(kFile);
  cmd->add_option("--port", o->viewer.port, "the port to listen on (0: any free port)")
      ->type_name("N")
      ->check(port_number())
      ->capture_default_str();
  cmd->add_option("--bind", o->viewer.bind, "the address to listen on (another than 127.0.0.1 is warned about)")
      ->type_name("ADDR")
      ->check(ipv4_address())
      ->capture_default_str();
  cmd->add_option("--duration", o->duration, "stop after S seconds (default: until Ctrl-C)")
      ->type_name("S")
      ->check(seconds_above_zero());
  cmd->callback([run, o] { *run = [o] { return view(*o); }; });
}

}  // namespace afford::cli
