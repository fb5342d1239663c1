#include "session_outputs.h"

#include <stdexcept>

namespace afford::cli {

namespace fs = std::filesystem;

OutFile::OutFile(const fs::path& path) : file(std::fopen(path.c_str(), "w")) {
  if (file == nullptr) throw std::runtime_error("cannot write " + path.string());
}

OutFile::~OutFile() { std::fclose(file); }

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
      timeline_(dir_ / "timeline.jsonl"),
      trace_(dir_ / "trace.csv"),
      timeline_writer_(timeline_.file),
      trace_writer_(trace_.file) {}

std::string SessionOutputs::written() const {
  return (dir_ / "timeline.jsonl").string() + " and " + (dir_ / "trace.csv").string();
}

}  // namespace afford::cli
