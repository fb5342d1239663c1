// fuzz_seeds SOURCE_DIR OUT_DIR: writes the seed corpora that are not
// shipped files as they are: a short recording of a shipped session (in
// OUT_DIR/recording), one report per shipped device (OUT_DIR/report) and
// measured traces (OUT_DIR/trace), each with the leading byte its fuzzer
// reads as a selector.
#include <cstdio>
#include <filesystem>
#include <string>

#include "device_description.h"
#include "files.h"
#include "recording.h"
#include "run.h"
#include "scripted_agent.h"
#include "session.h"

namespace fs = std::filesystem;

namespace {

// The first frames of a script only: a seed of a few kilobytes past the
// embedded files.
class FirstFrames : public afford::SampleSource {
 public:
  explicit FirstFrames(afford::SampleSource& inner) : inner_(inner) {}
  bool sample_at(double t, afford::Sample* out) override { return inner_.sample_at(t, out); }
  double duration() const override { return 0.01; }

 private:
  afford::SampleSource& inner_;
};

std::string with_selector(char selector, const std::string& bytes) { return std::string(1, selector) + bytes; }

void write_recordings(const fs::path& source, const fs::path& out) {
  const fs::path dir = out / "recording";
  fs::create_directories(dir);
  const std::string session_file = (source / "sessions/paper-nutcracker.yaml").string();
  const afford::CompiledSession session = afford::load_session(session_file);
  const std::string rec_file = (dir / "raw.afrec").string();
  {
    afford::Recorder recorder(rec_file, session, "script " + session_file);
    afford::ScriptedAgent agent(session.script);
    FirstFrames first(agent);
    afford::Observer* const observers[] = {&recorder};
    afford::run_session(session, *session.rules, first, observers);
  }
  const std::string bytes = afford::read_regular_file(rec_file, size_t{1} << 20);
  fs::remove(rec_file);
  afford::write_file_checked((dir / "nutcracker-raw").string(), with_selector(0, bytes));
  afford::write_file_checked((dir / "nutcracker-checksummed").string(), with_selector(1, bytes));
}

void write_reports(const fs::path& source, const fs::path& out) {
  const fs::path dir = out / "report";
  fs::create_directories(dir);
  const char* const devices[] = {"glove.yaml", "force_feedback.yaml"};  // as fuzz_report.cpp
  for (int i = 0; i < 2; ++i) {
    const afford::DeviceDescription d = afford::load_device_description((source / "devices" / devices[i]).string());
    std::string report(static_cast<size_t>(d.in_size), '\0');
    if (d.in_report_id >= 0 && !report.empty()) report[0] = static_cast<char>(d.in_report_id);
    afford::write_file_checked((dir / devices[i]).replace_extension().string(), with_selector(static_cast<char>(i), report));
  }
}

void write_traces(const fs::path& source, const fs::path& out) {
  const fs::path dir = out / "trace";
  fs::create_directories(dir);
  // The trace format (docs/), a lever and plates; selector bit 0 is the rig.
  afford::write_file_checked((dir / "lever.csv").string(),
                             with_selector(0, "t,angle,effort_force,actee_force,broken\n"
                                              "0.001,0.5,0,0,0\n0.002,0.49,1.5,0,0\n0.003,0.47,3.25,2.5,1\n"));
  afford::write_file_checked((dir / "plates.csv").string(),
                             with_selector(1, "t,displacement,force\n0,0,0\n0.1,1e-5,20\n0.2,2e-5,45.5\n"));
  // The macadamia machine's files, where the shared data is (selector: plates, tab, its layout).
  const fs::path real = source / "../shared/data/real/macadamia";
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(real, ec)) {
    if (e.path().extension() != ".txt") continue;
    const std::string text = afford::read_regular_file(e.path().string(), size_t{1} << 20);
    afford::write_file_checked((dir / e.path().filename()).string(), with_selector(static_cast<char>(0x83), text));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fuzz_seeds SOURCE_DIR OUT_DIR\n");
    return 2;
  }
  try {
    write_recordings(argv[1], argv[2]);
    write_reports(argv[1], argv[2]);
    write_traces(argv[1], argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
