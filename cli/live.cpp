// afford live SESSION --device DEV.yaml [--duration S] [--record FILE]
//                     [--wait S] [--silence S] [--out DIR]:
// runs the session's frame loop at its timestep (1 kHz) in real time
// against a USB device described by DEV.yaml (devices/README.md): the
// session gives the model and the function models (its script is not
// used), the device gives the hand. After every frame the haptic force
// (usb_live.h haptic_forces) goes back through the device's OUT report.
// Inferred functions are printed as they happen; at the end, why the
// session ended, the reports received and those skipped, by reason. If the
// device disappears the session ends cleanly, says so, and keeps what was
// recorded. Ctrl-C ends it the same way. It writes DIR/timeline.jsonl and
// DIR/trace.csv as `afford run` does (DIR: --out, default out/<session>) and
// is always recorded (to --record FILE, default DIR/live.afrec).
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>

#include "commands.h"
#include "option_checks.h"
#include "output_file.h"
#include "session_outputs.h"
#include "recording.h"
#include "report_decoder.h"
#include "run.h"
#include "session.h"
#include "usb_live.h"

namespace afford::cli {
namespace {

std::atomic<bool> g_stop{false};

extern "C" void on_interrupt(int) { g_stop.store(true); }

// Prints each inference as it happens (the frame's events).
class EventPrinter : public Observer {
 public:
  void on_frame(const Model&, const State&, const RuleSet& rules, const RuleState& rs) override {
    for (const Event* e = events_begin(rs); e != events_end(rs); ++e) {
      if (e->kind != EventKind::inferred) continue;
      std::printf("%9.3f s  %s\n", e->t, function_name(rules, e->function).c_str());
      std::fflush(stdout);
    }
  }
};

struct LiveOptions {
  std::string file, device_file, record, out_dir;
  double duration = std::numeric_limits<double>::infinity(), wait = 0, silence = 2;
  bool force = false;  // replace existing output files afford did not write (output_file.h)
};

int live(const LiveOptions& o) {
  const std::string& file = o.file;
  const std::string& device_file = o.device_file;
  const std::string& out_dir = o.out_dir;
  std::string record = o.record;
  const double duration = o.duration, wait = o.wait, silence = o.silence;

  const CompiledSession session = load_session(file);              // DataError: file:line:col
  const DeviceDescription device = load_device_description(device_file);

  UsbOptions options;
  options.silence_limit_s = silence;
  std::string error;
  std::unique_ptr<UsbDevice> usb = UsbDevice::wait_and_open(device, options, wait, &error);
  if (!usb) {
    std::cerr << "afford: " << error << "\n";
    return 1;
  }
  // DIR/timeline.jsonl and DIR/trace.csv as `afford run` writes them; DIR
  // is out/<session> unless --out says. A live session is always recorded:
  // to --record FILE, or by default to DIR/live.afrec.
  const std::filesystem::path dir = output_dir(out_dir, session.name);
  std::vector<std::string> inputs = session.files;
  inputs.push_back(device_file);
  const OutputScope scope({.writer = "live", .force = o.force, .inputs = inputs});  // engine/base/output_file.h
  SessionOutputs outputs(dir);
  if (record.empty()) record = (dir / "live.afrec").string();
  std::optional<Recorder> recorder;
  recorder.emplace(record, session, "device " + device.name + " (" + device_file + ")");

  ReportDecoder decoder(device, session.model);
  UsbSampleStream stream(*usb, decoder);
  RealTimeSource source(*usb, stream, device.resample, device.rate, duration, &g_stop, std::max(2.0, silence));
  EventPrinter printer;
  HapticObserver haptic(*usb);
  std::vector<Observer*> observers = {&printer, outputs.timeline(), outputs.trace()};
  if (device.has_out) observers.push_back(&haptic);
  if (recorder) observers.push_back(&*recorder);

  std::printf("live session %s with %s (%04x:%04x) at %g Hz, frames every %s%s\n", session.name.c_str(),
              device.name.c_str(), device.vendor, device.product, device.rate,
              format_quantity(session.model.timestep, dim::time).c_str(),
              device.has_out ? ", force feedback on" : "");
  std::fflush(stdout);
  auto previous = std::signal(SIGINT, on_interrupt);
  usb->start(std::chrono::steady_clock::now());
  const RunResult result = run_session(session, *session.rules, source, observers);
  usb->stop();
  std::signal(SIGINT, previous);

  std::string why = source.end_reason();
  if (why == "device ended") why = usb->end_reason();
  if (why.empty()) why = "duration reached";
  std::printf("ended after %lld frames (%.3f s): %s\n", static_cast<long long>(result.frames), result.end_time,
              why.c_str());
  std::printf("functions inferred: %zu\n", result.inferences.size());
  std::printf("reports: %lld received, %lld decoded, %lld skipped", static_cast<long long>(usb->reports_received()),
              static_cast<long long>(decoder.count(ReportStatus::ok)), static_cast<long long>(decoder.skipped()));
  for (int s = 1; s < kReportStatuses; ++s) {
    std::printf(", %lld %s", static_cast<long long>(decoder.count(static_cast<ReportStatus>(s))),
                report_status_name(static_cast<ReportStatus>(s)));
  }
  std::printf(", %lld dropped (buffer full)\n", static_cast<long long>(usb->reports_dropped()));
  std::printf("read timeouts: %lld; read errors: %lld; late frames: %lld; report to frame latency: mean %.3f ms, max %.3f ms\n",
              static_cast<long long>(usb->read_timeouts()), static_cast<long long>(usb->read_errors()),
              static_cast<long long>(source.late_frames()),
              source.mean_latency_s() * 1e3, source.max_latency_s() * 1e3);
  if (device.has_out) {
    std::printf("force reports: %lld sent, %lld failed; peak force %.2f N\n",
                static_cast<long long>(usb->reports_sent()), static_cast<long long>(usb->send_errors()),
                haptic.peak_force());
  }
  if (recorder) {
    if (!recorder->error().empty()) {
      std::cerr << "afford: recording: " << recorder->error() << "\n";
      return 1;
    }
    std::printf("recorded %lld frames to %s\n", static_cast<long long>(recorder->frames()), record.c_str());
  }
  outputs.close();  // checked, and renamed into place (engine/base/output_file.h)
  std::printf("wrote %s\n", outputs.written().c_str());
  return 0;
}

}  // namespace

void add_live(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "live", "run a session in real time against a USB device: functions as they happen, force feedback");
  auto o = std::make_shared<LiveOptions>();
  cmd->add_option("SESSION", o->file, "a session file: the model and function models (not its script)")
      ->required()
      ->type_name(kFile);
  cmd->add_option("--device", o->device_file, "the device description (devices/*.yaml)")
      ->required()
      ->type_name(kFile);
  cmd->add_option("--duration", o->duration, "stop after S seconds (default: until the device ends or Ctrl-C)")
      ->type_name("S")
      ->check(seconds_above_zero());
  cmd->add_option("--wait", o->wait, "wait up to S seconds for the device to appear")
      ->type_name("S")
      ->check(seconds_above_zero());
  cmd->add_option("--silence", o->silence, "end when the device sends nothing for S seconds")
      ->type_name("S")
      ->check(seconds_above_zero())
      ->capture_default_str();
  cmd->add_option("--record", o->record, "the recording (default DIR/live.afrec)")->type_name(kFile);
  cmd->add_option("--out", o->out_dir, "the folder of timeline.jsonl and trace.csv (default out/<session>)")
      ->type_name(kDir);
  cmd->add_flag("--force", o->force, "replace existing output files that afford did not write");
  cmd->callback([run, o] { *run = [o] { return live(*o); }; });
}

}  // namespace afford::cli
