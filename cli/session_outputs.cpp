#include "session_outputs.h"

#include <stdexcept>

namespace afford::cli {

namespace fs = std::filesystem;

fs::path output_dir(const std::string& given, const std::string& session_name) {
  return given.empty() ? fs::path("out") / session_name : fs::path(given);
}

namespace {
// Runs before the members are built, so that the files can be opened.
const fs::path& created(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create " + dir.string() + ": " + ec.message());
  return dir;
}
}  // namespace

SessionOutputs::SessionOutputs(const fs::path& dir)
    : dir_(created(dir)),
      timeline_((dir_ / "timeline.jsonl").string()),
      trace_((dir_ / "trace.csv").string()),
      timeline_writer_(timeline_.file),
      trace_writer_(trace_.file) {}

void SessionOutputs::close() {
  timeline_.close();
  trace_.close();
}

std::string SessionOutputs::written() const {
  return (dir_ / "timeline.jsonl").string() + " and " + (dir_ / "trace.csv").string();
}

}  // namespace afford::cli
