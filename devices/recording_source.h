// Reading recordings (the format is in recording.h) and replaying them: the
// recorded model files, the recorded samples as a SampleSource, and a
// checker that compares a re-run with the recorded events, frame by frame.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "recording.h"
#include "sample_source.h"
#include "session.h"

namespace afford {

struct RecordedFrame {
  std::int64_t frame = 0;            // k, 1-based
  Sample sample;                     // as the session stepped it
  std::uint64_t state_hash = 0;      // after the step
  std::uint32_t first_event = 0;     // into Recording::events
  std::uint32_t event_count = 0;
};

// How the file ends.
enum class RecordingTail {
  end,         // with the end record: the session ended cleanly
  no_end,      // after a whole record, without the end record (a crash between frames)
  incomplete,  // in the middle of a record (a crash while writing it)
  corrupt,     // at a record that fails its checksum or does not parse
};

struct Recording {
  std::string file;  // as named
  std::uint32_t version = 0;
  std::string source;        // what produced the samples
  std::string session_name;
  std::string session_file;  // as named when recorded
  std::string root;          // the folder the files were recorded from
  double timestep = 0;       // s
  std::vector<RecordedFile> files;  // the session first
  std::vector<RecordedFrame> frames;
  std::vector<Event> events;  // of every frame, in order
  RecordingTail tail = RecordingTail::no_end;
  std::string tail_detail;    // for incomplete and corrupt: what and where
  std::int64_t end_frames = 0;        // from the end record
  std::uint64_t end_state_hash = 0;   // from the end record
  std::uint64_t file_bytes = 0;       // the file's size
  std::uint64_t good_bytes = 0;       // up to the end of the last good record
  std::int64_t skipped_records = 0;   // of types this reader does not know

  // "4000 frames, ended cleanly", "4000 frames, ended cleanly; 12 bytes
  // after its end record are ignored", "1234 frames; the last record was
  // incomplete", "1234 frames; record 1236 is corrupt (...): the rest is ignored".
  std::string summary() const;
};

// Reads a recording. A truncated or corrupt tail is not an error: the
// frames before it are kept and `tail` says how the file ends. A file that
// is not a recording (wrong magic number), has another format version, or
// whose header is incomplete or corrupt is an error naming the file
// (std::runtime_error).
// Only a regular file of at most kMaxRecordingBytes is read (a DataError at
// the path otherwise).
// (kMaxRecordingBytes is in recording.h: the recorder stops before it.)
Recording read_recording(const std::string& path);
Recording parse_recording(std::string_view bytes, const std::string& name);

// Loads the recorded session from the recorded copies of its files, not
// from the files on disk now: writes them into a fresh temporary folder,
// loads the session from there and removes the folder. A DataError in a
// recorded file names it as REC[path]:line:col.
CompiledSession load_recorded_session(const Recording& rec);

// The recorded files that differ from the files at the place they were
// recorded from (or are gone from it), as "objects/x.yaml".
std::vector<std::string> changed_since_recording(const Recording& rec);

// The recorded samples: frame k's at t = k * timestep. Allocates nothing.
class RecordingSource : public SampleSource {
 public:
  // Keeps a reference: the recording must outlive the source.
  explicit RecordingSource(const Recording& rec) : rec_(rec) {}
  bool sample_at(double t, Sample* out) override;  // false past the last frame
  double duration() const override;                // the last frame's time, s

 private:
  const Recording& rec_;
};

// Compares a re-run with the recording frame by frame: every event (kind,
// function, node and time, bit for bit) and the state hash. Keeps the first
// frame that differs. With events false it compares the state only (a
// re-run under other function models). Allocates nothing per frame.
class ReplayChecker : public Observer {
 public:
  ReplayChecker(const Recording& rec, bool events) : rec_(rec), events_(events) {}
  void on_frame(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override;
  void on_end(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override;

  bool identical() const { return first_difference_ == 0 && !end_differs_; }
  std::int64_t frames() const { return frames_; }
  std::int64_t first_difference() const { return first_difference_; }  // frame k, 0: none
  bool state_differs() const { return state_differs_; }
  std::uint64_t final_state_hash() const { return final_hash_; }
  // The first difference, precisely: which frame, recorded vs re-run.
  std::string describe(const RuleSet& rules) const;

 private:
  const Recording& rec_;
  bool events_;
  std::int64_t frames_ = 0;
  std::int64_t first_difference_ = 0;
  bool state_differs_ = false;  // at first_difference_: the state, not (only) the events
  bool end_differs_ = false;    // the final state or the frame count differ from the end record
  std::uint64_t replayed_hash_ = 0;
  std::uint64_t final_hash_ = 0;
  std::array<Event, kMaxEventsPerFrame> replayed_{};  // the re-run's events at first_difference_
  int replayed_count_ = 0;
};

}  // namespace afford
