// The recorder (recording.h): the header once, then one write() per frame.
#include "recording.h"
#include "write_all.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>
#include <zlib.h>

namespace afford {
namespace {

namespace fs = std::filesystem;

// A growing buffer for the header (written once; frames use a fixed one).
class ByteWriter {
 public:
  void u8(std::uint8_t v) { b_.push_back(v); }
  void u32(std::uint32_t v) { put_u32(grow(4), v); }
  void u64(std::uint64_t v) { put_u64(grow(8), v); }
  void f64(double v) { put_f64(grow(8), v); }
  void bytes(const void* p, size_t n) {
    if (n > 0) std::memcpy(grow(n), p, n);
  }
  void str(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    bytes(s.data(), s.size());
  }
  void patch_u32(size_t at, std::uint32_t v) { put_u32(b_.data() + at, v); }
  const unsigned char* data() const { return b_.data(); }
  size_t size() const { return b_.size(); }

 private:
  unsigned char* grow(size_t n) {
    b_.resize(b_.size() + n);
    return b_.data() + b_.size() - n;
  }
  std::vector<unsigned char> b_;
};

// Whether p lies in folder (both absolute and normal).
bool is_under(const fs::path& p, const fs::path& folder) {
  const fs::path rel = p.lexically_relative(folder);
  return !rel.empty() && *rel.begin() != "..";
}

std::string read_file_bytes(const std::string& path) {
  try {
    return read_regular_file(path, kMaxYamlBytes);
  } catch (const DataError& e) {
    throw std::runtime_error("cannot read " + path + " to record it: " + e.message());
  }
}

}  // namespace

// zlib's (table-driven, several bytes at a time); the frame path calls it on every record.
std::uint32_t crc32(const void* data, size_t n, std::uint32_t crc) {
  return static_cast<std::uint32_t>(::crc32_z(crc, static_cast<const Bytef*>(data), n));
}

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;  // the FNV-1a 64 offset basis
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::vector<RecordedFile> collect_session_files(const std::vector<std::string>& files, std::string* root) {
  // The common folder of every file, so that the copies keep their layout
  // (the session's "../objects/x.yaml" still names the object's copy).
  std::vector<fs::path> abs;
  for (const std::string& f : files) abs.push_back(fs::absolute(f).lexically_normal());
  fs::path common = abs.empty() ? fs::path("/") : abs.front().parent_path();
  for (const fs::path& p : abs) {
    while (!is_under(p, common) && common != common.root_path()) common = common.parent_path();
  }
  if (root != nullptr) *root = common.string();
  std::vector<RecordedFile> out;
  for (size_t i = 0; i < abs.size(); ++i) {
    RecordedFile r;
    r.path = abs[i].lexically_relative(common).generic_string();
    // The same file read twice (two sessions' keys naming one file) is stored once.
    bool seen = false;
    for (const RecordedFile& o : out) seen = seen || o.path == r.path;
    if (seen) continue;
    r.content = read_file_bytes(files[i]);
    r.hash = fnv1a64(r.content);
    out.push_back(std::move(r));
  }
  return out;
}

namespace {

// Whether the file at path begins as a recording does: afford's own.
bool is_recording(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  unsigned char magic[kRecordingMagic.size()];
  struct stat st {};
  const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  const bool read = regular && ::read(fd, magic, sizeof magic) == static_cast<ssize_t>(sizeof magic);
  ::close(fd);
  return read && std::memcmp(magic, kRecordingMagic.data(), sizeof magic) == 0;
}

std::string mib(std::uint64_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(bytes) / (1 << 20));
  return buf;
}

}  // namespace

Recorder::Recorder(const std::string& path, const CompiledSession& session, const std::string& source,
                   std::int64_t expected_frames, std::uint64_t max_bytes)
    : path_(path), max_bytes_(max_bytes) {
  std::string root;
  const std::vector<RecordedFile> files = collect_session_files(session.files, &root);

  ByteWriter h;
  h.bytes(kRecordingMagic.data(), kRecordingMagic.size());
  h.u32(kRecordingVersion);
  const size_t record = h.size();
  h.u32(0);  // length, below
  h.u8(kRecordHeader);
  h.str(source);
  h.str(session.name);
  h.str(session.file);
  h.str(root);
  h.f64(session.model.timestep);
  h.u32(static_cast<std::uint32_t>(files.size()));
  for (const RecordedFile& f : files) {
    h.str(f.path);
    h.u64(f.hash);
    h.u64(f.content.size());
    h.bytes(f.content.data(), f.content.size());
  }
  const size_t payload = h.size() - record - 5;
  if (payload > 0xFFFFFFFFu) throw std::runtime_error("the session's files are too large to record");
  h.patch_u32(record, static_cast<std::uint32_t>(payload));
  h.u32(crc32(h.data() + record, h.size() - record));

  // Refused before anything is written when even event-free frames would
  // not fit: replay could not read the file.
  const std::uint64_t least = h.size() + static_cast<std::uint64_t>(std::max<std::int64_t>(expected_frames, 0)) *
                                             kMinFrameRecordBytes + kRecordOverhead + kEndPayload;
  if (least > max_bytes_) {
    char step[32];
    std::snprintf(step, sizeof step, "%g ms", session.model.timestep * 1e3);
    throw std::runtime_error(path + ": cannot record " + std::to_string(expected_frames) + " frames of " + step +
                             ": at least " + mib(least) +
                             " (" + std::to_string(kMinFrameRecordBytes) + " bytes a frame), over the " +
                             mib(max_bytes_) + " a recording may hold (replay reads no more); record a shorter "
                             "session or a longer timestep");
  }

  out_ = std::make_unique<OutputFile>(path, OutputFile::Options{.in_place_when_new = true, .own = is_recording(path)});
  fd_ = out_->release_fd();
  if (const int e = write_all(fd_, h.data(), h.size())) {
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(e));
  }
  bytes_ = h.size();
  buffer_.resize(kRecordOverhead +
                 std::max(kFrameFixedPayload + kEventBytes * kMaxEventsPerFrame, kMaxOtherPayload));
}

Recorder::~Recorder() {
  if (fd_ >= 0) ::close(fd_);
}

void Recorder::stop(const std::string& why) {
  error_ = why;
  ::close(fd_);
  fd_ = -1;
}

void Recorder::write_record(size_t payload_bytes) {
  if (fd_ < 0) return;
  unsigned char* b = buffer_.data();
  const size_t crc_at = 5 + payload_bytes;
  // The end record always fits: a recording stopped here still reads whole.
  const std::uint64_t room = b[4] == kRecordEnd ? 0 : kRecordOverhead + kEndPayload;
  if (bytes_ + crc_at + 4 + room > max_bytes_) {
    stop(path_ + ": stopped recording after " + std::to_string(frames_) + " frames (" + std::to_string(bytes_) +
         " bytes): the next record would take it past " + std::to_string(max_bytes_) +
         " bytes, the most a recording may hold (replay reads no more)");
    return;
  }
  put_u32(b, static_cast<std::uint32_t>(payload_bytes));
  put_u32(b + crc_at, crc32(b, crc_at));
  if (const int e = write_all(fd_, b, crc_at + 4)) {
    stop("cannot write " + path_ + " after " + std::to_string(frames_) + " frames: " + std::strerror(e));
    return;
  }
  bytes_ += crc_at + 4;
}

bool Recorder::append(std::uint8_t type, const void* payload, size_t bytes) {
  if (fd_ < 0 || bytes > kMaxOtherPayload || type == kRecordHeader || type == kRecordFrame || type == kRecordEnd) {
    return false;
  }
  unsigned char* b = buffer_.data();
  b[4] = type;
  if (bytes > 0) std::memcpy(b + 5, payload, bytes);
  write_record(bytes);
  return fd_ >= 0;
}

void Recorder::on_frame(const Model&, const State& s, const RuleSet&, const RuleState& rs) {
  if (fd_ < 0) return;
  unsigned char* b = buffer_.data();
  b[4] = kRecordFrame;
  unsigned char* p = b + 5;
  p = put_i64(p, s.frame);
  p = put_f64(p, s.t);
  const Eigen::Matrix4d& m = s.hand.matrix();
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 3; ++r) p = put_f64(p, m(r, c));
  }
  for (const Eigen::Vector3d& f : s.fingertip) {
    for (int i = 0; i < 3; ++i) p = put_f64(p, f[i]);
  }
  for (const auto& finger : s.joint) {
    for (double a : finger) p = put_f64(p, a);
  }
  p = put_u64(p, state_hash(s));
  const Event* begin = events_begin(rs);
  const Event* end = events_end(rs);
  const auto count = static_cast<std::uint16_t>(std::min<std::ptrdiff_t>(end - begin, kMaxEventsPerFrame));
  p = put_u16(p, count);
  for (const Event* e = begin; e != begin + count; ++e) {
    *p++ = static_cast<unsigned char>(e->kind);
    p = put_u16(p, static_cast<std::uint16_t>(e->function));
    p = put_u16(p, static_cast<std::uint16_t>(e->node));
    p = put_f64(p, e->t);
  }
  write_record(static_cast<size_t>(p - (b + 5)));
  if (fd_ >= 0) ++frames_;
}

void Recorder::on_end(const Model&, const State& s, const RuleSet&, const RuleState&) {
  if (fd_ < 0) return;
  unsigned char* b = buffer_.data();
  b[4] = kRecordEnd;
  unsigned char* p = put_i64(b + 5, frames_);
  p = put_u64(p, state_hash(s));
  write_record(static_cast<size_t>(p - (b + 5)));
  if (fd_ >= 0) {
    ::fdatasync(fd_);  // a clean end is on the disk, not only in the kernel
    ::close(fd_);
    fd_ = -1;
    try {
      out_->commit();  // an earlier recording is replaced only now
    } catch (const std::exception& e) {
      error_ = e.what();
    }
  }
}

}  // namespace afford
