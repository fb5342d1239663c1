// afford serve [SESSION] [--port N] [--bind ADDR] [--participant ID]
//              [--out DIR] [--actees DIR] [--guides FILE] [--duration S]:
// the session's frame loop at its timestep (1 kHz) in real time behind a
// local web page (serve/server.h): the page drives the hand (grasp,
// squeeze, carry, release), takes actees from the shelf and resets the
// trial; it shows the tool, the forces and the functions as they are
// inferred, with their explanations. Every trial is recorded
// (DIR/P-trial-NNN.afrec, `afford replay` gives the same verdicts) and
// writes DIR/P-trial-NNN/timeline.jsonl and trace.csv as `afford run`
// does. Ctrl-C (or --duration) ends it; then each trial's functions and
// the frames that missed their deadline are printed.
#include <arpa/inet.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <limits>

#include "commands.h"
#include "data_dir.h"
#include "option_checks.h"
#include "output_file.h"
#include "server.h"
#include "trial.h"

namespace afford::cli {
namespace {

std::atomic<bool> g_serve_stop{false};

extern "C" void on_serve_interrupt(int) { g_serve_stop.store(true); }

struct ServeCliOptions {
  serve::ServeOptions server;
};

int serve_session(ServeCliOptions o) {
  serve::ServeOptions& s = o.server;
  if (s.session_file.empty()) s.session_file = shipped_path("sessions/paper-tongs.yaml");
  if (s.bind != "127.0.0.1" && s.bind != "localhost") {
    std::fprintf(stderr,
                 "afford: warning: serving on %s, not only on this machine (127.0.0.1): anyone who can reach "
                 "it can watch and drive the session\n",
                 s.bind.c_str());
  }
  if (s.bind == "localhost") s.bind = "127.0.0.1";
  // Trials go through engine/base/output_file.h: never over the session, nor over files afford did not write.
  const OutputScope scope({.writer = "serve", .force = false, .inputs = {s.session_file}});
  serve::Server server(s);  // DataError: file:line:col
  server.start();
  // Caught before the address is printed: a Ctrl-C as soon as it shows ends the session cleanly.
  auto previous = std::signal(SIGINT, on_serve_interrupt);
  auto previous_term = std::signal(SIGTERM, on_serve_interrupt);
  std::printf("serving %s at %s (participant %s, trials in %s); Ctrl-C ends\n", s.session_file.c_str(),
              server.url().c_str(), s.participant.c_str(), server.out_dir().string().c_str());
  if (!server.real_time_priority()) {
    std::printf("the frame loop runs at ordinary priority (this system allows no real-time scheduling): a busy "
                "machine makes more frames late\n");
  }
  std::fflush(stdout);
  while (!server.wait(0.02)) {  // Ctrl-C is seen within 20 ms
    if (g_serve_stop.load()) break;
  }
  server.stop();
  std::signal(SIGINT, previous);
  std::signal(SIGTERM, previous_term);

  int status = 0;
  std::int64_t frames = 0, misses = 0;
  double late = 0;
  for (const serve::TrialSummary& t : server.trials()) {
    std::printf("trial %d (%s): %.3f s, %lld frames; ", t.number, t.actee.empty() ? "no actee" : t.actee.c_str(),
                t.end_time, static_cast<long long>(t.frames));
    if (t.inferences.empty()) std::printf("no function inferred");
    for (size_t i = 0; i < t.inferences.size(); ++i) {
      std::printf("%s%s at %.3f s", i ? ", " : "", t.inferences[i].function.c_str(), t.inferences[i].t);
    }
    std::printf("\n  recorded to %s; wrote %s/timeline.jsonl and trace.csv\n", t.recording.c_str(), t.outputs.c_str());
    if (!t.error.empty()) {
      std::cerr << "afford: trial " << t.number << ": " << t.error << "\n";
      status = 1;
    }
    frames += t.frames;
    misses += t.deadline_misses;
    late = std::max(late, t.max_lateness);
  }
  const serve::MessageCounts m = server.messages();
  std::printf("frame deadline misses: %lld of %lld frames (latest %.3f ms)\n", static_cast<long long>(misses),
              static_cast<long long>(frames), late * 1e3);
  std::printf("messages from pages: %lld applied, %lld dropped as bad, %lld stale, %lld from watchers, %lld with "
              "the queue full\n",
              static_cast<long long>(m.accepted), static_cast<long long>(m.rejected), static_cast<long long>(m.stale),
              static_cast<long long>(m.from_watchers), static_cast<long long>(m.queue_full));
  return status;
}

CLI::Validator participant_id() {
  return CLI::Validator(
      [](std::string& value) {
        return serve::valid_participant(value)
                   ? std::string()
                   : "expected 1 to 32 letters, digits, '-' and '_', found '" + value + "'";
      },
      "");
}

}  // namespace

CLI::Validator port_number() {
  return CLI::Validator(
      [](std::string& value) {
        char* end = nullptr;
        const long v = std::strtol(value.c_str(), &end, 10);
        const bool ok = !value.empty() && *end == '\0' && v >= 0 && v <= 65535;
        return ok ? std::string() : "expected a port number from 0 (any free port) to 65535, found '" + value + "'";
      },
      "");
}

CLI::Validator ipv4_address() {
  return CLI::Validator(
      [](std::string& value) {
        in_addr a{};
        const bool ok = value == "localhost" || inet_pton(AF_INET, value.c_str(), &a) == 1;
        return ok ? std::string() : "expected an IPv4 address such as 127.0.0.1, found '" + value + "'";
      },
      "");
}

void add_serve(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "serve", "run a session in real time behind a local web page: drive the hand, see forces and functions");
  auto o = std::make_shared<ServeCliOptions>();
  cmd->add_option("SESSION", o->server.session_file,
                  "a session file: the tool, actee, hand, rules and start (default sessions/paper-tongs.yaml)")
      ->type_name(kFile);
  cmd->add_option("--port", o->server.port, "the port to listen on (0: any free port)")
      ->type_name("N")
      ->check(port_number())
      ->capture_default_str();
  cmd->add_option("--bind", o->server.bind, "the address to listen on (another than 127.0.0.1 is warned about)")
      ->type_name("ADDR")
      ->check(ipv4_address())
      ->capture_default_str();
  cmd->add_option("--participant", o->server.participant, "the participant id in the trials' file names")
      ->type_name("ID")
      ->check(participant_id())
      ->capture_default_str();
  cmd->add_option("--out", o->server.out_dir, "the folder of the trials (default out/serve-<session>)")
      ->type_name(kDir);
  cmd->add_option("--actees", o->server.user_actees_dir,
                  "a folder of your actees, on the shelf beside the shipped ones (each file checked at start)")
      ->type_name(kDir);
  cmd->add_option("--guides", o->server.guides_file,
                  "the guides drawn in the page (default: the shipped rules/guides.yaml, as afford guide)")
      ->type_name(kFile);
  cmd->add_option("--duration", o->server.duration, "stop after S seconds (default: until Ctrl-C)")
      ->type_name("S")
      ->check(seconds_above_zero());
  cmd->callback([run, o] { *run = [o] { return serve_session(*o); }; });
}

}  // namespace afford::cli
