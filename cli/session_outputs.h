// The files every command that runs a session writes into its output
// directory, the same for `run`, `replay` and `live`: DIR/timeline.jsonl
// and DIR/trace.csv (formats in engine/session/trace.h and docs/trace-format.md).
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "files.h"
#include "trace.h"

namespace afford::cli {

// An output file whose writes are checked when it is closed (engine/base/files.h).
using OutFile = CheckedFile;

// DIR as given, or out/<session name> when none was.
std::filesystem::path output_dir(const std::string& given, const std::string& session_name);

class SessionOutputs {
 public:
  explicit SessionOutputs(const std::filesystem::path& dir);  // creates DIR; throws std::runtime_error
  Observer* timeline() { return &timeline_writer_; }
  Observer* trace() { return &trace_writer_; }
  std::string written() const;  // "DIR/timeline.jsonl and DIR/trace.csv"
  // Closes both, checked: a full disk is an error naming the file, never "wrote".
  void close();

 private:
  std::filesystem::path dir_;
  OutFile timeline_, trace_;
  TimelineWriter timeline_writer_;
  TraceWriter trace_writer_;
};

}  // namespace afford::cli
