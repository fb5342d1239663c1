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

double parse_seconds(const std::string& s, const char* option, bool* ok) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  *ok = end != nullptr && *end == '\0' && v > 0 && v < 1e9;
  if (!*ok) usage_error(std::string(option) + " needs a number of seconds above 0, got '" + s + "'");
  return v;
}

}  // namespace

int run_live(const Args& args) {
  std::string file, device_file, record, out_dir;
  double duration = std::numeric_limits<double>::infinity(), wait = 0, silence = 2;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool has_value = i + 1 < args.size();
    bool ok = true;
    if (a == "--device") {
      if (!has_value) return usage_error("--device needs a device description (devices/*.yaml)");
      device_file = args[++i];
    } else if (a == "--out") {
      if (!has_value) return usage_error("--out needs a DIR");
      out_dir = args[++i];
    } else if (a == "--record") {
      if (!has_value) return usage_error("--record needs a FILE");
      record = args[++i];
    } else if (a == "--duration" || a == "--wait" || a == "--silence") {
      if (!has_value) return usage_error(a + " needs a number of seconds");
      const double v = parse_seconds(args[++i], a.c_str(), &ok);
      if (!ok) return 2;
      (a == "--duration" ? duration : a == "--wait" ? wait : silence) = v;
    } else if (!a.empty() && a[0] == '-') {
      return usage_error("live: unknown option '" + a + "'");
    } else if (file.empty()) {
      file = a;
    } else {
      return usage_error("live takes one SESSION file");
    }
  }
  if (file.empty()) return usage_error("live needs a SESSION file");
  if (device_file.empty()) return usage_error("live needs --device DEV.yaml (devices/glove.yaml, ...)");

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
  const RunResult result = run_session(session.model, *session.rules, source, observers);
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
  std::printf("wrote %s\n", outputs.written().c_str());
  return 0;
}

}  // namespace afford::cli
