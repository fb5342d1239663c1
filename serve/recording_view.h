// What `afford view` shows: a recording re-run from its own files (as
// `afford replay` does, checked frame by frame against the recorded
// events), turned into one JSON document the page plays by itself:
//
//   {"type":"recording","file":"...","session":"paper-tongs","source":"...",
//    "summary":"4997 frames, ended cleanly","identical":true,"end_time":4.997,
//    "scene":{scene_message.h's scene},
//    "states":[{protocol.h's state}, ... 60 per second of session time, and
//              every frame with an event],
//    "events":[{protocol.h's event}, ...]}
//
// The states carry no page hand (squeeze 0, applied_seq -1): what the hand
// did is in the fingertips and the forces.
#pragma once

#include <cstdint>
#include <string>

namespace afford::serve {

struct RecordingView {
  std::string json;          // the document above
  std::string session_name;
  std::int64_t frames = 0;
  int inferences = 0;
  bool identical = false;    // the re-run's events were the recorded ones, bit for bit
};

// Reads and re-runs a recording (std::runtime_error or DataError naming
// the file when it cannot be read or its session loaded).
RecordingView recording_view(const std::string& recording_file);

// The recording PATH stands for: PATH itself when it is a file; for a
// folder, the one .afrec in it, or, for a trial's outputs folder of
// `afford serve` (DIR/P-trial-NNN/), DIR/P-trial-NNN.afrec beside it.
// std::runtime_error saying what was looked for otherwise (a folder of
// `afford run --out` without a recording names `run --record`).
std::string find_recording(const std::string& path);

}  // namespace afford::serve
