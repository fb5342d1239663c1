// Recordings: a session written to a file as it runs, so that it can be
// replayed bit for bit (`afford replay`) and re-run under edited function
// models. The recorder is an Observer (engine/rules/observer.h); the reader and
// the replaying SampleSource are in recording_source.h.
//
// The format (version 1), little-endian throughout:
//
//   magic    8 bytes   89 'A' 'F' 'R' 'E' 'C' 0D 0A (PNG-style: a high
//                      byte and CR LF catch 7-bit and text-mode copies)
//   version  u32       kRecordingVersion
//   records  ...       append-only, each one
//       length   u32   bytes of the payload
//       type     u8    'H' header, 'F' frame, 'E' end; other types are
//                      skipped by readers that do not know them (room for
//                      a device's raw reports)
//       payload  length bytes
//       crc      u32   CRC-32 (IEEE 802.3, as zlib) of length, type, payload
//
// The first record is the header ('H'):
//   str      the source: "script sessions/paper-nutcracker.yaml", a device
//   str      the session's name
//   str      the session file as named when recorded
//   str      the folder the files were recorded from (absolute), for "this
//            file has changed since" notes; never read from
//   f64      timestep, s
//   u32      file count, then per file (the session first):
//     str    path relative to the files' common folder, '/'-separated
//     u64    FNV-1a 64 of the bytes
//     u64    size, bytes
//     bytes  the file's content
// (str is a u32 length and that many bytes of UTF-8.) FNV-1a 64 only
// tells an edited file from the recorded one (no defence against forgery,
// which nothing here is); the CRC-32 of every record catches torn writes
// and flipped bits.
//
// Then one frame record ('F') per frame, a payload of 362 bytes + 13 per
// event (371 bytes on disk for a frame without events):
//   i64      frame k (1, 2, ...; consecutive)
//   f64      t, s (= k * timestep)
//   f64[12]  the hand's pose: rotation (column-major 3x3), then translation, m
//   f64[15]  fingertips, 5 x (x, y, z), m, world, thumb first
//   f64[15]  joint angles, 5 fingers x 3 joints, rad
//   u64      state_hash (engine/model/state.h) after the frame's step
//   u16      event count, then per event:
//     u8     kind (EventKind)
//     u16    function index, u16 node index
//     f64    t, s
//
// The last record, when the session ended cleanly, is the end ('E'):
//   i64      frames
//   u64      state_hash of the final state
//
// A reader stops at the first record that is incomplete or fails its
// checksum: everything before it replays. A crash (kill -9) therefore loses
// at most the frame being written.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "observer.h"
#include "output_file.h"
#include "session.h"

namespace afford {

inline constexpr std::array<unsigned char, 8> kRecordingMagic = {0x89, 'A', 'F', 'R', 'E', 'C', 0x0D, 0x0A};
inline constexpr std::uint32_t kRecordingVersion = 1;

enum RecordType : std::uint8_t {
  kRecordHeader = 'H',
  kRecordFrame = 'F',
  kRecordEnd = 'E',
};

// The largest recording, bytes: one limit for the writer and the reader.
// The recorder refuses a session whose frames alone would pass it and
// stops, with an error, before its next record would; `afford replay`
// reads any file up to it.
inline constexpr std::uint64_t kMaxRecordingBytes = std::uint64_t{1} << 30;

// Fixed sizes, bytes.
inline constexpr size_t kRecordOverhead = 4 + 1 + 4;        // length, type, crc
inline constexpr size_t kFrameFixedPayload = 8 + 8 + 12 * 8 + 15 * 8 + 15 * 8 + 8 + 2;
inline constexpr size_t kEventBytes = 1 + 2 + 2 + 8;
inline constexpr size_t kEndPayload = 8 + 8;

// CRC-32 (IEEE, reflected 0xEDB88320): zlib's crc32(); `crc` continues
// an earlier one.
std::uint32_t crc32(const void* data, size_t n, std::uint32_t crc = 0);
// FNV-1a 64, as state_hash: identifies a model file's bytes.
std::uint64_t fnv1a64(std::string_view bytes);

// The files a session read, named relative to their common folder (the
// session first), with their bytes. Throws std::runtime_error when one
// cannot be read.
struct RecordedFile {
  std::string path;     // relative, '/'-separated, e.g. "objects/nutcracker.yaml"
  std::uint64_t hash;   // FNV-1a 64 of content
  std::string content;
};
std::vector<RecordedFile> collect_session_files(const std::vector<std::string>& files, std::string* root);

// Little-endian encoding, shared by the writer and the reader. put_*
// write at p and return the byte after; get_* read at p.
inline unsigned char* put_u16(unsigned char* p, std::uint16_t v) {
  p[0] = static_cast<unsigned char>(v);
  p[1] = static_cast<unsigned char>(v >> 8);
  return p + 2;
}
inline unsigned char* put_u32(unsigned char* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
  return p + 4;
}
inline unsigned char* put_u64(unsigned char* p, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
  return p + 8;
}
inline unsigned char* put_i64(unsigned char* p, std::int64_t v) { return put_u64(p, static_cast<std::uint64_t>(v)); }
inline unsigned char* put_f64(unsigned char* p, double v) { return put_u64(p, std::bit_cast<std::uint64_t>(v)); }
inline std::uint16_t get_u16(const unsigned char* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }
inline std::uint32_t get_u32(const unsigned char* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
inline std::uint64_t get_u64(const unsigned char* p) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
inline std::int64_t get_i64(const unsigned char* p) { return static_cast<std::int64_t>(get_u64(p)); }
inline double get_f64(const unsigned char* p) { return std::bit_cast<double>(get_u64(p)); }

// The least bytes a frame takes on disk (a frame without events).
inline constexpr std::uint64_t kMinFrameRecordBytes = kRecordOverhead + kFrameFixedPayload;

// Writes a recording (an OutputFile, engine/base/output_file.h). A new file is
// written in place, so that a crash leaves what was recorded at its name;
// an earlier recording (recognised by its magic number), or another file
// with --force, is replaced by rename only when the session ends cleanly.
// The constructor writes the header; each frame is one write() from a
// buffer allocated here, so that the frame is in the kernel when on_frame
// returns. A failed write, or a frame that would take the file past
// max_bytes (room for the end record kept), does not throw in on_frame:
// the recorder stops writing and error() says why. Not copyable.
class Recorder : public Observer {
 public:
  // session: its files (session.files, the session first) are embedded;
  // source: what produced the samples, e.g. "script sessions/x.yaml".
  // expected_frames: how many frames the session will run (0: unknown);
  // when even frames without events would pass max_bytes the recording is
  // refused before it starts. Throws std::runtime_error when the file
  // cannot be created, a model file cannot be read or the session is too
  // long to record; OutputRefused (output_file.h) for a target it may not
  // replace.
  Recorder(const std::string& path, const CompiledSession& session, const std::string& source,
           std::int64_t expected_frames = 0, std::uint64_t max_bytes = kMaxRecordingBytes);
  ~Recorder() override;
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  void on_frame(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override;
  void on_end(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override;

  // Appends a record of another type (a device's raw report, say 'R'),
  // between frames, from the thread that runs the session. Readers that do
  // not know the type skip it. False (and nothing written) for the types
  // above, a payload over kMaxOtherPayload bytes, or after a failed write.
  // Allocates nothing.
  bool append(std::uint8_t type, const void* payload, size_t bytes);
  static constexpr size_t kMaxOtherPayload = 1024;

  std::int64_t frames() const { return frames_; }      // frame records written
  std::uint64_t bytes() const { return bytes_; }       // file size so far
  const std::string& error() const { return error_; }  // empty unless a write failed
  const std::string& path() const { return path_; }

 private:
  void write_record(size_t payload_bytes);  // buffer_: type and payload filled in
  void stop(const std::string& why);         // closes the file; error() = why
  std::string path_;
  std::unique_ptr<OutputFile> out_;  // renamed into place at on_end
  int fd_ = -1;
  std::uint64_t max_bytes_;
  std::vector<unsigned char> buffer_;  // one record, sized for the largest frame
  std::int64_t frames_ = 0;
  std::uint64_t bytes_ = 0;
  std::string error_;
};

}  // namespace afford
