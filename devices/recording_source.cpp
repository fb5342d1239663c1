// Reading and replaying recordings (recording_source.h).
#include "recording_source.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace afford {
namespace {

namespace fs = std::filesystem;

// Bounds-checked reads of one record's payload: a read past its end sets
// ok to false and gives zeros.
class Cursor {
 public:
  Cursor(const unsigned char* p, size_t n) : p_(p), end_(p + n) {}
  bool ok() const { return ok_; }
  bool at_end() const { return p_ == end_; }
  const unsigned char* take(size_t n) {
    if (!ok_ || static_cast<size_t>(end_ - p_) < n) {
      ok_ = false;
      return nullptr;
    }
    const unsigned char* at = p_;
    p_ += n;
    return at;
  }
  std::uint8_t u8() {
    const unsigned char* p = take(1);
    return p ? *p : 0;
  }
  std::uint16_t u16() {
    const unsigned char* p = take(2);
    return p ? get_u16(p) : 0;
  }
  std::uint32_t u32() {
    const unsigned char* p = take(4);
    return p ? get_u32(p) : 0;
  }
  std::uint64_t u64() {
    const unsigned char* p = take(8);
    return p ? get_u64(p) : 0;
  }
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64() { return std::bit_cast<double>(u64()); }
  std::string bytes(size_t n) {
    const unsigned char* p = take(n);
    return p ? std::string(reinterpret_cast<const char*>(p), n) : std::string();
  }
  std::string str() { return bytes(u32()); }

 private:
  const unsigned char* p_;
  const unsigned char* end_;
  bool ok_ = true;
};

struct Record {
  std::uint8_t type = 0;
  const unsigned char* payload = nullptr;
  size_t length = 0;
};

enum class Status { ok, incomplete, corrupt };

// The record at `at`; on ok, `at` moves past it.
Status next_record(const unsigned char* b, size_t size, size_t* at, Record* r, std::string* why) {
  const size_t left = size - *at;
  if (left < kRecordOverhead) {
    *why = std::to_string(left) + " of at least " + std::to_string(kRecordOverhead) + " bytes";
    return Status::incomplete;
  }
  const std::uint32_t length = get_u32(b + *at);
  const std::uint8_t type = b[*at + 4];
  // A frame or end record has a known size range: a length outside it is a
  // corrupt length, not a short file.
  const bool bad_length =
      (type == kRecordFrame && (length < kFrameFixedPayload ||
                                length > kFrameFixedPayload + kEventBytes * kMaxEventsPerFrame ||
                                (length - kFrameFixedPayload) % kEventBytes != 0)) ||
      (type == kRecordEnd && length != kEndPayload);
  if (bad_length) {
    *why = "a length of " + std::to_string(length) + " bytes for a '" + std::string(1, static_cast<char>(type)) +
           "' record";
    return Status::corrupt;
  }
  if (left - kRecordOverhead < length) {
    *why = std::to_string(left) + " of " + std::to_string(length + kRecordOverhead) + " bytes";
    return Status::incomplete;
  }
  const size_t crc_at = *at + 5 + length;
  if (crc32(b + *at, 5 + length) != get_u32(b + crc_at)) {
    *why = "its checksum does not match";
    return Status::corrupt;
  }
  r->type = type;
  r->payload = b + *at + 5;
  r->length = length;
  *at = crc_at + 4;
  return Status::ok;
}

bool parse_frame(const Record& r, Recording* rec, std::string* why) {
  Cursor c(r.payload, r.length);
  RecordedFrame f;
  f.frame = c.i64();
  f.sample.t = c.f64();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 3; ++row) m(row, col) = c.f64();
  }
  f.sample.hand.matrix() = m;
  for (Eigen::Vector3d& tip : f.sample.fingertip) {
    for (int i = 0; i < 3; ++i) tip[i] = c.f64();
  }
  for (auto& finger : f.sample.joint) {
    for (double& a : finger) a = c.f64();
  }
  f.state_hash = c.u64();
  const std::uint16_t count = c.u16();
  f.first_event = static_cast<std::uint32_t>(rec->events.size());
  f.event_count = count;
  for (int i = 0; i < count; ++i) {
    Event e;
    const std::uint8_t kind = c.u8();
    if (kind > static_cast<std::uint8_t>(EventKind::inferred)) {
      *why = "an event of unknown kind " + std::to_string(kind);
      rec->events.resize(f.first_event);
      return false;
    }
    e.kind = static_cast<EventKind>(kind);
    e.function = c.u16();
    e.node = c.u16();
    e.t = c.f64();
    rec->events.push_back(e);
  }
  if (!c.ok() || !c.at_end()) {
    *why = "its events do not fill it";
    rec->events.resize(f.first_event);
    return false;
  }
  const std::int64_t expected = static_cast<std::int64_t>(rec->frames.size()) + 1;
  if (f.frame != expected) {
    *why = "frame " + std::to_string(f.frame) + " where frame " + std::to_string(expected) + " belongs";
    rec->events.resize(f.first_event);
    return false;
  }
  rec->frames.push_back(f);
  return true;
}

void parse_header(const Record& r, Recording* rec) {
  Cursor c(r.payload, r.length);
  rec->source = c.str();
  rec->session_name = c.str();
  rec->session_file = c.str();
  rec->root = c.str();
  rec->timestep = c.f64();
  const std::uint32_t count = c.u32();
  for (std::uint32_t i = 0; i < count && c.ok(); ++i) {
    RecordedFile f;
    f.path = c.str();
    f.hash = c.u64();
    f.content = c.bytes(static_cast<size_t>(c.u64()));
    if (c.ok() && fnv1a64(f.content) != f.hash) {
      throw std::runtime_error(rec->file + ": the recorded copy of " + f.path + " does not match its hash");
    }
    rec->files.push_back(std::move(f));
  }
  if (!c.ok() || !c.at_end() || rec->files.empty() || !(rec->timestep > 0)) {
    throw std::runtime_error(rec->file + ": the recording's header does not parse");
  }
}

// A fresh folder under $TMPDIR (or /tmp), removed with this object.
struct TempFolder {
  TempFolder() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = (tmp != nullptr && *tmp != '\0' ? std::string(tmp) : std::string("/tmp")) +
                          "/afford-replay-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw std::runtime_error("cannot create a temporary folder " + pattern + ": " + std::strerror(errno));
    }
    path = pattern;
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  fs::path path;
};

// A recorded path is relative and stays inside its folder.
bool safe_path(const std::string& p) {
  const fs::path path(p);
  if (p.empty() || path.is_absolute()) return false;
  for (const fs::path& part : path.lexically_normal()) {
    if (part == "..") return false;
  }
  return true;
}

}  // namespace

std::string Recording::summary() const {
  std::string s = std::to_string(frames.size()) + (frames.size() == 1 ? " frame" : " frames");
  switch (tail) {
    case RecordingTail::end:
      // Bytes appended after the end (a second recording written onto the
      // first, a copy gone wrong) are not read: say so.
      if (file_bytes > good_bytes) {
        return s + ", ended cleanly; " + std::to_string(file_bytes - good_bytes) +
               " bytes after its end record are ignored";
      }
      return s + ", ended cleanly";
    case RecordingTail::no_end: return s + "; the session did not end cleanly (no end record)";
    case RecordingTail::incomplete: return s + "; the last record was incomplete (" + tail_detail + ")";
    case RecordingTail::corrupt: return s + "; " + tail_detail + ": the rest of the file is ignored";
  }
  return s;
}

Recording parse_recording(std::string_view bytes, const std::string& name) {
  Recording rec;
  rec.file = name;
  rec.file_bytes = bytes.size();
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  const size_t size = bytes.size();
  if (size < kRecordingMagic.size() || std::memcmp(b, kRecordingMagic.data(), kRecordingMagic.size()) != 0) {
    throw std::runtime_error(name + ": not an afford recording (its magic number is wrong)");
  }
  if (size < kRecordingMagic.size() + 4) throw std::runtime_error(name + ": the recording ends in its version number");
  rec.version = get_u32(b + kRecordingMagic.size());
  if (rec.version != kRecordingVersion) {
    throw std::runtime_error(name + ": recording format version " + std::to_string(rec.version) +
                             "; this afford reads version " + std::to_string(kRecordingVersion));
  }
  size_t at = kRecordingMagic.size() + 4;
  Record r;
  std::string why;
  const Status header = next_record(b, size, &at, &r, &why);
  if (header != Status::ok) {
    throw std::runtime_error(name + ": the recording's header is " +
                             (header == Status::incomplete ? "incomplete (" : "corrupt (") + why +
                             "): nothing to replay");
  }
  if (r.type != kRecordHeader) throw std::runtime_error(name + ": the recording does not begin with its header");
  parse_header(r, &rec);
  rec.good_bytes = at;
  std::int64_t index = 1;  // of the record, the header 0
  while (true) {
    if (at == size) {
      rec.tail = RecordingTail::no_end;
      break;
    }
    const size_t start = at;
    const Status s = next_record(b, size, &at, &r, &why);
    if (s != Status::ok) {
      rec.tail = s == Status::incomplete ? RecordingTail::incomplete : RecordingTail::corrupt;
      rec.tail_detail = s == Status::incomplete
                            ? why
                            : "record " + std::to_string(index) + " (at byte " + std::to_string(start) +
                                  ") is corrupt: " + why;
      break;
    }
    if (r.type == kRecordFrame) {
      if (!parse_frame(r, &rec, &why)) {
        rec.tail = RecordingTail::corrupt;
        rec.tail_detail =
            "record " + std::to_string(index) + " (at byte " + std::to_string(start) + ") is corrupt: " + why;
        break;
      }
    } else if (r.type == kRecordEnd) {
      Cursor c(r.payload, r.length);
      rec.end_frames = c.i64();
      rec.end_state_hash = c.u64();
      rec.tail = RecordingTail::end;
      rec.good_bytes = at;
      break;
    } else {
      ++rec.skipped_records;  // a record type for other readers (a device's raw reports)
    }
    rec.good_bytes = at;
    ++index;
  }
  return rec;
}

Recording read_recording(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw std::runtime_error(path + ": a folder, not a recording");
  return parse_recording(read_regular_file(path, kMaxRecordingBytes), path);
}

CompiledSession load_recorded_session(const Recording& rec) {
  TempFolder tmp;
  for (const RecordedFile& f : rec.files) {
    if (!safe_path(f.path)) {
      throw std::runtime_error(rec.file + ": the recording names a file outside its folder: '" + f.path + "'");
    }
    const fs::path p = tmp.path / f.path;
    fs::create_directories(p.parent_path());
    std::ofstream out(p, std::ios::binary);
    out.write(f.content.data(), static_cast<std::streamsize>(f.content.size()));
    if (!out) throw std::runtime_error("cannot write " + p.string());
  }
  const std::string prefix = tmp.path.string() + "/";
  try {
    CompiledSession s = load_session((tmp.path / rec.files.front().path).string());
    if (s.model.timestep != rec.timestep) {
      throw std::runtime_error(rec.file + ": the recorded session's timestep does not match the recording's");
    }
    s.file = rec.session_file;
    s.files.clear();
    for (const RecordedFile& f : rec.files) s.files.push_back(f.path);
    return s;
  } catch (const DataError& e) {
    SourceLoc loc = e.loc();
    if (loc.file.starts_with(prefix)) loc.file = rec.file + "[" + loc.file.substr(prefix.size()) + "]";
    throw DataError(loc, e.message());
  }
}

std::vector<std::string> changed_since_recording(const Recording& rec) {
  std::vector<std::string> out;
  for (const RecordedFile& f : rec.files) {
    const fs::path p = fs::path(rec.root) / f.path;
    // Named by the recording: only a regular file there counts as unchanged.
    try {
      if (fnv1a64(read_regular_file(p.string(), kMaxYamlBytes)) != f.hash) out.push_back(f.path);
    } catch (const DataError&) {
      out.push_back(f.path);
    }
  }
  return out;
}

bool RecordingSource::sample_at(double t, Sample* out) {
  if (rec_.frames.empty()) return false;
  const long long k = std::llround(t / rec_.timestep);
  if (k < 1 || k > static_cast<long long>(rec_.frames.size())) return false;
  *out = rec_.frames[static_cast<size_t>(k - 1)].sample;
  return true;
}

double RecordingSource::duration() const { return rec_.frames.empty() ? 0.0 : rec_.frames.back().sample.t; }

void ReplayChecker::on_frame(const Model&, const State& state, const RuleSet&, const RuleState& rs) {
  frames_ = state.frame;
  if (first_difference_ != 0) return;
  const Event* begin = events_begin(rs);
  const Event* end = events_end(rs);
  const std::uint64_t hash = state_hash(state);
  bool same = state.frame >= 1 && state.frame <= static_cast<std::int64_t>(rec_.frames.size());
  bool state_same = same;
  if (same) {
    const RecordedFrame& f = rec_.frames[static_cast<size_t>(state.frame - 1)];
    state_same = hash == f.state_hash;
    same = state_same && (!events_ || end - begin == static_cast<std::ptrdiff_t>(f.event_count));
    for (std::uint32_t i = 0; events_ && same && i < f.event_count; ++i) {
      const Event& a = rec_.events[f.first_event + i];
      const Event& b = begin[i];
      same = a.kind == b.kind && a.function == b.function && a.node == b.node &&
             std::bit_cast<std::uint64_t>(a.t) == std::bit_cast<std::uint64_t>(b.t);
    }
  }
  if (same) return;
  first_difference_ = state.frame;
  state_differs_ = !state_same;
  replayed_hash_ = hash;
  replayed_count_ = static_cast<int>(std::min<std::ptrdiff_t>(end - begin, kMaxEventsPerFrame));
  std::copy(begin, begin + replayed_count_, replayed_.begin());
}

void ReplayChecker::on_end(const Model&, const State& state, const RuleSet&, const RuleState&) {
  final_hash_ = state_hash(state);
  if (rec_.tail == RecordingTail::end) {
    end_differs_ = frames_ != rec_.end_frames || final_hash_ != rec_.end_state_hash;
  }
}

std::string ReplayChecker::describe(const RuleSet& rules) const {
  auto list = [&](const Event* begin, const Event* end) {
    if (begin == end) return std::string("no events");
    std::string s;
    for (const Event* e = begin; e != end; ++e) {
      if (!s.empty()) s += "; ";
      const int function = e->function;
      if (function < 0 || function >= function_count(rules)) {
        s += "an event of function " + std::to_string(function) + " (not in these rules)";
        continue;
      }
      const int nodes = node_count(rules, function);
      std::string what = function_name(rules, function);
      if (e->kind == EventKind::inferred) {
        what += " inferred";
      } else {
        what += " node " + std::to_string(e->node) + (e->kind == EventKind::node_reached ? " reached" : " lost");
        if (e->node >= 0 && e->node < nodes) what += " (" + node_text(rules, function, e->node) + ")";
      }
      char t[32];
      std::snprintf(t, sizeof t, " at %.17g s", e->t);
      s += what + t;
    }
    return s;
  };
  if (first_difference_ == 0) {
    if (!end_differs_) return "no difference";
    return "the end differs: the recording ended after " + std::to_string(rec_.end_frames) +
           " frames, the replay after " + std::to_string(frames_) +
           (frames_ == rec_.end_frames ? " (the final states differ)" : "");
  }
  const std::int64_t k = first_difference_;
  char head[96];
  std::snprintf(head, sizeof head, "frame %lld (t = %.3f s) differs", static_cast<long long>(k),
                static_cast<double>(k) * rec_.timestep);
  std::string s = head;
  if (k > static_cast<std::int64_t>(rec_.frames.size())) return s + ": the recording has no such frame";
  const RecordedFrame& f = rec_.frames[static_cast<size_t>(k - 1)];
  if (state_differs_) {
    char h[96];
    std::snprintf(h, sizeof h, ": the state (hash %016llx recorded, %016llx replayed)",
                  static_cast<unsigned long long>(f.state_hash), static_cast<unsigned long long>(replayed_hash_));
    s += h;
  }
  if (!events_) return s;
  const Event* rb = rec_.events.data() + f.first_event;
  s += "\n  recorded: " + list(rb, rb + f.event_count);
  s += "\n  replayed: " + list(replayed_.data(), replayed_.data() + replayed_count_);
  return s;
}

}  // namespace afford
