// recording_helper SESSION REC US: runs a session file with a Recorder
// writing REC, sleeping US microseconds after every frame, so that a test
// can kill it in the middle of a recording (tests/cli/recording_crash_test.sh).
// Prints "recording" once the header is written.
//
// recording_helper --tamper IN OUT: copies a recording, with the time of the
// first event of the third frame that has events moved 1 ms later and that
// record's checksum made good again: a recording that reads cleanly and
// that a replay must find different (tests/cli/replay_test.sh). Prints the
// frame.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "recording.h"
#include "run.h"
#include "scripted_agent.h"
#include "session.h"

namespace {

class Sleeper : public afford::Observer {
 public:
  explicit Sleeper(long us) : us_(us) {}
  void on_frame(const afford::Model&, const afford::State&, const afford::RuleSet&,
                const afford::RuleState&) override {
    std::this_thread::sleep_for(std::chrono::microseconds(us_));
  }

 private:
  long us_;
};

int tamper(const char* in_path, const char* out_path) {
  std::ifstream in(in_path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto* b = reinterpret_cast<unsigned char*>(bytes.data());
  size_t at = afford::kRecordingMagic.size() + 4;
  int seen = 0;
  while (at + afford::kRecordOverhead <= bytes.size()) {
    const std::uint32_t length = afford::get_u32(b + at);
    if (b[at + 4] == afford::kRecordFrame && afford::get_u16(b + at + 5 + afford::kFrameFixedPayload - 2) > 0 &&
        ++seen == 3) {
      unsigned char* t = b + at + 5 + afford::kFrameFixedPayload + 5;  // the first event's time
      afford::put_f64(t, afford::get_f64(t) + 1e-3);
      afford::put_u32(b + at + 5 + length, afford::crc32(b + at, 5 + length));
      std::ofstream(out_path, std::ios::binary) << bytes;
      std::printf("tampered with frame %lld\n", static_cast<long long>(afford::get_i64(b + at + 5)));
      return 0;
    }
    at += afford::kRecordOverhead + length;
  }
  std::fprintf(stderr, "no third frame with events\n");
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == "--tamper") return tamper(argv[2], argv[3]);
  if (argc != 4) {
    std::fprintf(stderr, "usage: recording_helper SESSION REC MICROSECONDS_PER_FRAME\n");
    return 2;
  }
  try {
    const afford::CompiledSession session = afford::load_session(argv[1]);
    afford::Recorder recorder(argv[2], session, std::string("script ") + argv[1]);
    Sleeper sleeper(std::atol(argv[3]));
    afford::Observer* const observers[] = {&recorder, &sleeper};
    std::printf("recording\n");
    std::fflush(stdout);
    afford::ScriptedAgent agent(session.script);
    const afford::RunResult r = afford::run_session(session.model, *session.rules, agent, observers);
    std::printf("recorded %lld frames\n", static_cast<long long>(r.frames));
    return recorder.error().empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
