// Recordings (devices/recording.h): a recorded session replays to the same
// events and the same final state, bit for bit, from the recorded copies of
// its files; a file cut at any byte or with a corrupt byte reads up to the
// last good record; a wrong magic number or version is an error naming the
// file; records of unknown types are skipped; a re-run under edited
// function models gives the expected timeline difference.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "recording.h"
#include "recording_source.h"
#include "run.h"
#include "scripted_agent.h"
#include "session.h"
#include "test_util.h"
#include "timeline_diff.h"

namespace afford::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;


std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void spit(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

// Keeps the final state's hash.
class FinalHash : public Observer {
 public:
  void on_frame(const Model&, const State&, const RuleSet&, const RuleState&) override {}
  void on_end(const Model&, const State& s, const RuleSet&, const RuleState&) override { hash = state_hash(s); }
  std::uint64_t hash = 0;
};

// One recording of the paper's nutcracker, made once for the suite.
struct Recorded {
  TempDir dir;
  std::string file;
  std::string bytes;
  std::vector<Event> events;  // as the recorded run emitted them
  std::uint64_t final_hash = 0;
  std::int64_t frames = 0;
  std::vector<Inference> inferences;
};

const Recorded& nutcracker() {
  static Recorded rec;  // its folder is removed at exit
  static const bool made = [] {
    rec.file = (rec.dir.path / "nut.afrec").string();
    const CompiledSession s = load_session(kSource + "/sessions/paper-nutcracker.yaml");
    Recorder recorder(rec.file, s, "script sessions/paper-nutcracker.yaml");
    TimelineCollector events;
    FinalHash final_hash;
    Observer* const observers[] = {&recorder, &events, &final_hash};
    ScriptedAgent agent(s.script);
    const RunResult result = run_session(s.model, *s.rules, agent, observers);
    EXPECT_EQ(recorder.error(), "");
    EXPECT_EQ(recorder.frames(), result.frames);
    rec.events = events.events();
    rec.final_hash = final_hash.hash;
    rec.frames = result.frames;
    rec.inferences = result.inferences;
    rec.bytes = slurp(rec.file);
    EXPECT_EQ(recorder.bytes(), rec.bytes.size());
    return true;
  }();
  (void)made;
  return rec;
}

bool same_event(const Event& a, const Event& b) {
  return a.kind == b.kind && a.function == b.function && a.node == b.node &&
         std::bit_cast<std::uint64_t>(a.t) == std::bit_cast<std::uint64_t>(b.t);
}

bool same_sample(const Sample& a, const Sample& b) {
  return std::memcmp(a.hand.matrix().data(), b.hand.matrix().data(), sizeof(double) * 16) == 0 &&
         std::memcmp(a.fingertip.data(), b.fingertip.data(), sizeof a.fingertip) == 0 &&
         std::memcmp(a.joint.data(), b.joint.data(), sizeof a.joint) == 0 &&
         std::bit_cast<std::uint64_t>(a.t) == std::bit_cast<std::uint64_t>(b.t);
}

// The byte offset where each frame record ends, from the frames' event counts.
std::vector<size_t> frame_ends(const Recording& rec) {
  std::vector<size_t> ends;
  size_t at = kRecordingMagic.size() + 4;
  // The header record: its length field.
  at += kRecordOverhead + get_u32(reinterpret_cast<const unsigned char*>(nutcracker().bytes.data()) + at);
  ends.push_back(at);  // [0]: the end of the header
  for (const RecordedFrame& f : rec.frames) {
    at += kRecordOverhead + kFrameFixedPayload + kEventBytes * f.event_count;
    ends.push_back(at);
  }
  return ends;
}

// ------------------------------------------------------------ round trip

TEST(Recording, ReadsBackEveryFrameAndTheFiles) {
  const Recorded& r = nutcracker();
  const Recording rec = read_recording(r.file);
  EXPECT_EQ(rec.version, kRecordingVersion);
  EXPECT_EQ(rec.tail, RecordingTail::end);
  EXPECT_EQ(rec.summary(), "4000 frames, ended cleanly");
  EXPECT_EQ(static_cast<std::int64_t>(rec.frames.size()), r.frames);
  EXPECT_EQ(rec.end_frames, r.frames);
  EXPECT_EQ(rec.end_state_hash, r.final_hash);
  EXPECT_EQ(rec.good_bytes, r.bytes.size());
  EXPECT_EQ(rec.session_name, "paper-nutcracker");
  EXPECT_EQ(rec.source, "script sessions/paper-nutcracker.yaml");
  EXPECT_EQ(rec.timestep, 1e-3);
  // Every file the session read, named from their common folder, session first.
  std::vector<std::string> paths;
  for (const RecordedFile& f : rec.files) paths.push_back(f.path);
  EXPECT_THAT(paths, ::testing::ElementsAre("sessions/paper-nutcracker.yaml", "objects/nutcracker.yaml",
                                            "actees/walnut.yaml", "agents/hand.yaml", "rules/functions.yaml",
                                            "rules/grasps.yaml"));
  EXPECT_EQ(rec.files[1].content, slurp(kSource + "/objects/nutcracker.yaml"));
  EXPECT_EQ(rec.files[1].hash, fnv1a64(rec.files[1].content));
  // The events, frame by frame, as emitted.
  ASSERT_EQ(rec.events.size(), r.events.size());
  for (size_t i = 0; i < rec.events.size(); ++i) EXPECT_TRUE(same_event(rec.events[i], r.events[i])) << i;
  EXPECT_GT(rec.events.size(), 3u);
  // Bytes per frame: 371 without events, 13 more per event.
  EXPECT_EQ(r.bytes.size(), frame_ends(rec).back() + kRecordOverhead + kEndPayload);
}

TEST(Recording, ReplaysToTheSameEventsAndFinalState) {
  const Recorded& r = nutcracker();
  const Recording rec = read_recording(r.file);
  const CompiledSession s = load_recorded_session(rec);
  EXPECT_EQ(s.name, "paper-nutcracker");
  RecordingSource source(rec);
  ReplayChecker checker(rec, true);
  TimelineCollector events;
  FinalHash final_hash;
  Observer* const observers[] = {&checker, &events, &final_hash};
  const RunResult replay = run_session(s.model, *s.rules, source, observers);
  EXPECT_TRUE(checker.identical()) << checker.describe(*s.rules);
  EXPECT_EQ(replay.frames, r.frames);
  EXPECT_EQ(final_hash.hash, r.final_hash);
  ASSERT_EQ(events.events().size(), r.events.size());
  for (size_t i = 0; i < r.events.size(); ++i) EXPECT_TRUE(same_event(events.events()[i], r.events[i])) << i;
  ASSERT_EQ(replay.inferences.size(), r.inferences.size());
  for (size_t i = 0; i < r.inferences.size(); ++i) {
    EXPECT_EQ(replay.inferences[i].function, r.inferences[i].function);
    EXPECT_EQ(replay.inferences[i].t, r.inferences[i].t);
  }
}

TEST(Recording, SourceGivesTheRecordedSamplesByFrame) {
  const Recorded& r = nutcracker();
  const Recording rec = read_recording(r.file);
  const CompiledSession s = load_session(kSource + "/sessions/paper-nutcracker.yaml");
  ScriptedAgent agent(s.script);
  RecordingSource source(rec);
  EXPECT_EQ(source.duration(), 4.0);
  Sample expected, got;
  for (std::int64_t k : {1, 2, 500, 2560, 4000}) {
    const double t = static_cast<double>(k) * s.model.timestep;
    ASSERT_TRUE(agent.sample_at(t, &expected));
    expected.t = t;
    ASSERT_TRUE(source.sample_at(t, &got));
    EXPECT_TRUE(same_sample(got, expected)) << "frame " << k;
  }
  EXPECT_FALSE(source.sample_at(4.001, &got));
  EXPECT_FALSE(source.sample_at(0.0, &got));
}

TEST(Recording, ChangedEventsAreReportedAtTheFirstDifferingFrame) {
  const Recorded& r = nutcracker();
  Recording rec = read_recording(r.file);
  ASSERT_GT(rec.events.size(), 2u);
  // Move the second recorded event one frame's worth of time later.
  size_t frame = 0;
  while (rec.frames[frame].event_count == 0 || rec.frames[frame].first_event < 1) ++frame;
  rec.events[rec.frames[frame].first_event].t += 1e-3;
  const CompiledSession s = load_recorded_session(rec);
  RecordingSource source(rec);
  ReplayChecker checker(rec, true);
  Observer* const observers[] = {&checker};
  run_session(s.model, *s.rules, source, observers);
  EXPECT_FALSE(checker.identical());
  EXPECT_EQ(checker.first_difference(), rec.frames[frame].frame);
  EXPECT_FALSE(checker.state_differs());
  EXPECT_THAT(checker.describe(*s.rules),
              StartsWith("frame " + std::to_string(rec.frames[frame].frame) + " (t = "));
  EXPECT_THAT(checker.describe(*s.rules), HasSubstr("\n  recorded: "));
}

// ------------------------------------------------------------ damage

TEST(Recording, ACutAtAnyByteReadsUpToTheLastWholeRecord) {
  const Recorded& r = nutcracker();
  const Recording full = read_recording(r.file);
  const std::vector<size_t> ends = frame_ends(full);
  // Offsets: across the whole file at a prime stride, and around every 97th
  // record boundary.
  std::vector<size_t> cuts;
  for (size_t at = ends[0]; at < r.bytes.size(); at += 7919) cuts.push_back(at);
  for (size_t i = 0; i < ends.size(); i += 97) {
    for (size_t d : {0, 1, 4, 5, 9}) cuts.push_back(ends[i] + d);
    cuts.push_back(ends[i] - 1);
  }
  cuts.push_back(r.bytes.size() - 1);
  for (size_t cut : cuts) {
    if (cut < ends[0] || cut >= r.bytes.size()) continue;
    const Recording rec = parse_recording(std::string_view(r.bytes).substr(0, cut), "cut.afrec");
    // Whole frame records before the cut.
    const size_t whole = static_cast<size_t>(std::upper_bound(ends.begin(), ends.end(), cut) - ends.begin()) - 1;
    ASSERT_EQ(rec.frames.size(), std::min(whole, full.frames.size())) << "cut at " << cut;
    const bool on_boundary = cut == ends[whole];
    EXPECT_EQ(rec.tail, on_boundary ? RecordingTail::no_end : RecordingTail::incomplete) << "cut at " << cut;
    EXPECT_EQ(rec.good_bytes, ends[whole]);
    if (!on_boundary) {
      EXPECT_THAT(rec.summary(), HasSubstr("frames; the last record was incomplete ("));
    }
    for (size_t i = 0; i < rec.frames.size(); i += 211) {
      EXPECT_TRUE(same_sample(rec.frames[i].sample, full.frames[i].sample));
    }
    if (!rec.frames.empty()) {
      EXPECT_TRUE(same_sample(rec.frames.back().sample, full.frames[rec.frames.size() - 1].sample));
    }
  }
}

TEST(Recording, ACutInTheHeaderIsAnError) {
  const Recorded& r = nutcracker();
  for (size_t cut : {0, 5, 8, 11}) {
    try {
      parse_recording(std::string_view(r.bytes).substr(0, cut), "short.afrec");
      ADD_FAILURE() << "cut at " << cut;
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), StartsWith("short.afrec: ")) << cut;
    }
  }
  for (size_t cut : {12, 16, 100, 5000}) {
    try {
      parse_recording(std::string_view(r.bytes).substr(0, cut), "short.afrec");
      ADD_FAILURE() << "cut at " << cut;
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), StartsWith("short.afrec: the recording's header is incomplete (")) << cut;
      EXPECT_THAT(e.what(), HasSubstr("nothing to replay"));
    }
  }
}

TEST(Recording, ACorruptByteReadsUpToTheRecordBeforeIt) {
  const Recorded& r = nutcracker();
  const Recording full = read_recording(r.file);
  const std::vector<size_t> ends = frame_ends(full);
  // In frame record k (1-based): its length, type, payload and checksum bytes.
  for (size_t k : {1, 2, 777, 2000, 3999, 4000}) {
    for (size_t d : {0, 3, 4, 5, 12, 100, 370}) {
      const size_t at = ends[k - 1] + d;
      if (at >= ends[k]) continue;
      std::string bytes = r.bytes;
      bytes[at] = static_cast<char>(bytes[at] ^ 0x10);
      const Recording rec = parse_recording(bytes, "bad.afrec");
      EXPECT_EQ(rec.frames.size(), k - 1) << "frame " << k << " byte " << d;
      // A corrupt length that runs past the end reads as a cut file.
      EXPECT_TRUE(rec.tail == RecordingTail::corrupt || rec.tail == RecordingTail::incomplete)
          << "frame " << k << " byte " << d;
      if (rec.tail == RecordingTail::corrupt) {
        EXPECT_THAT(rec.summary(), HasSubstr("record " + std::to_string(k) + " (at byte " +
                                             std::to_string(ends[k - 1]) + ") is corrupt: "));
      }
    }
  }
  // A corrupt end record: every frame is kept, the end is not.
  std::string bytes = r.bytes;
  bytes[bytes.size() - 6] = static_cast<char>(bytes[bytes.size() - 6] ^ 1);
  const Recording rec = parse_recording(bytes, "bad.afrec");
  EXPECT_EQ(rec.frames.size(), 4000u);
  EXPECT_EQ(rec.tail, RecordingTail::corrupt);
  // A corrupt byte in the header (a model file's copy) is an error.
  bytes = r.bytes;
  bytes[ends[0] - 100] = static_cast<char>(bytes[ends[0] - 100] ^ 1);
  try {
    parse_recording(bytes, "bad.afrec");
    ADD_FAILURE() << "a corrupt header was read";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), StartsWith("bad.afrec: the recording's header is corrupt (its checksum does not match)"));
  }
}

// A small fuzzer: random flips, cuts, insertions and deletions, anywhere.
// The reader keeps a prefix of the frames or reports an error, never more.
TEST(Recording, RandomDamageReadsAPrefixOrFails) {
  const Recorded& r = nutcracker();
  const Recording full = read_recording(r.file);
  const std::string head = r.bytes.substr(0, 60000);  // the header and ~100 frames
  std::mt19937_64 rng(20261121);
  int errors = 0;
  for (int i = 0; i < 400; ++i) {
    std::string b = head;
    for (int m = 0, n = 1 + static_cast<int>(rng() % 4); m < n && !b.empty(); ++m) {
      const size_t at = rng() % b.size();
      switch (rng() % 4) {
        case 0: b[at] = static_cast<char>(rng()); break;
        case 1: b.resize(at); break;
        case 2: b.insert(at, std::string(rng() % 20, static_cast<char>(rng()))); break;
        default: b.erase(at, rng() % 50); break;
      }
    }
    try {
      const Recording rec = parse_recording(b, "fuzz.afrec");
      ASSERT_LE(rec.frames.size(), full.frames.size());
      for (size_t k = 0; k < rec.frames.size(); ++k) {
        // A frame that reads is one that was written (a CRC-32 collision aside).
        ASSERT_EQ(rec.frames[k].frame, static_cast<std::int64_t>(k) + 1);
        ASSERT_TRUE(same_sample(rec.frames[k].sample, full.frames[k].sample)) << i;
      }
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), StartsWith("fuzz.afrec: "));
      ++errors;
    }
  }
  EXPECT_GT(errors, 0);
  EXPECT_LT(errors, 400);
}

TEST(Recording, WrongMagicOrVersionIsAnErrorNamingTheFile) {
  const Recorded& r = nutcracker();
  std::string bytes = r.bytes;
  bytes[1] = 'X';
  EXPECT_THROW(
      {
        try {
          parse_recording(bytes, "other.bin");
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "other.bin: not an afford recording (its magic number is wrong)");
          throw;
        }
      },
      std::runtime_error);
  bytes = r.bytes;
  put_u32(reinterpret_cast<unsigned char*>(bytes.data()) + 8, 2);
  EXPECT_THROW(
      {
        try {
          parse_recording(bytes, "new.afrec");
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "new.afrec: recording format version 2; this afford reads version 1");
          throw;
        }
      },
      std::runtime_error);
  EXPECT_THROW(parse_recording("", "empty.afrec"), std::runtime_error);
  EXPECT_THROW(read_recording("/nonexistent/x.afrec"), std::runtime_error);
}

TEST(Recording, RecordsOfUnknownTypesAreSkipped) {
  const Recorded& r = nutcracker();
  const Recording full = read_recording(r.file);
  const std::vector<size_t> ends = frame_ends(full);
  // A device's raw report ('R', not known to this reader) after frame 10.
  std::string report(5 + 6, '\0');
  auto* p = reinterpret_cast<unsigned char*>(report.data());
  put_u32(p, 6);
  p[4] = 'R';
  std::memcpy(p + 5, "\x01\x02\x03\x04\x05\x06", 6);
  const std::uint32_t crc = crc32(report.data(), report.size());
  report.resize(report.size() + 4);
  put_u32(reinterpret_cast<unsigned char*>(report.data()) + 11, crc);
  const std::string bytes = r.bytes.substr(0, ends[10]) + report + r.bytes.substr(ends[10]);
  const Recording rec = parse_recording(bytes, "raw.afrec");
  EXPECT_EQ(rec.frames.size(), 4000u);
  EXPECT_EQ(rec.skipped_records, 1);
  EXPECT_EQ(rec.tail, RecordingTail::end);
}

// A device layer adds its raw reports through Recorder::append.
class RawReports : public Observer {
 public:
  explicit RawReports(Recorder& r) : recorder_(r) {}
  void on_frame(const Model&, const State& s, const RuleSet&, const RuleState&) override {
    const unsigned char report[3] = {1, 2, static_cast<unsigned char>(s.frame)};
    if (s.frame % 100 == 0) ok = recorder_.append('R', report, sizeof report) && ok;
  }
  Recorder& recorder_;
  bool ok = true;
};

TEST(Recording, AppendedRecordsAreSkippedByTheReplay) {
  TempDir dir;
  const std::string file = (dir.path / "raw.afrec").string();
  const CompiledSession s = load_session(kSource + "/sessions/paper-nutcracker.yaml");
  Recorder recorder(file, s, "device test");
  EXPECT_FALSE(recorder.append(kRecordFrame, "x", 1));
  EXPECT_FALSE(recorder.append('R', "", Recorder::kMaxOtherPayload + 1));
  RawReports raw(recorder);
  Observer* const observers[] = {&recorder, &raw};
  ScriptedAgent agent(s.script);
  run_session(s.model, *s.rules, agent, observers);
  EXPECT_TRUE(raw.ok);
  const Recording rec = read_recording(file);
  EXPECT_EQ(rec.frames.size(), 4000u);
  EXPECT_EQ(rec.skipped_records, 40);
  EXPECT_EQ(rec.tail, RecordingTail::end);
  const CompiledSession replayed = load_recorded_session(rec);
  RecordingSource source(rec);
  ReplayChecker checker(rec, true);
  Observer* const check[] = {&checker};
  run_session(replayed.model, *replayed.rules, source, check);
  EXPECT_TRUE(checker.identical()) << checker.describe(*replayed.rules);
}

TEST(Recording, Crc32IsTheIeeeOne) {
  EXPECT_EQ(crc32("123456789", 9), 0xCBF43926u);  // the standard check value
  EXPECT_EQ(crc32("", 0), 0u);
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);  // the published test vectors
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
}

// ------------------------------------------------------------ files

TEST(Recording, ReplaysTheRecordedFilesNotTheOnesOnDisk) {
  TempDir dir;
  for (const char* d : {"objects", "actees", "agents", "rules", "sessions"}) {
    fs::copy(kSource + "/" + d, dir.path / d, fs::copy_options::recursive);
  }
  const std::string rec_file = (dir.path / "r.afrec").string();
  {
    const CompiledSession s = load_session((dir.path / "sessions/paper-nutcracker.yaml").string());
    Recorder recorder(rec_file, s, "script");
    Observer* const observers[] = {&recorder};
    ScriptedAgent agent(s.script);
    run_session(s.model, *s.rules, agent, observers);
  }
  // The walnut on disk is now ten times harder: a fresh run would not crash.
  const fs::path walnut = dir.path / "actees/walnut.yaml";
  spit(walnut, replace_once(slurp(walnut), "limit: 378 N", "limit: 3780 N"));
  const Recording rec = read_recording(rec_file);
  EXPECT_EQ(rec.root, fs::absolute(dir.path).lexically_normal().string());
  EXPECT_THAT(changed_since_recording(rec), ::testing::ElementsAre("actees/walnut.yaml"));
  const CompiledSession s = load_recorded_session(rec);
  RecordingSource source(rec);
  ReplayChecker checker(rec, true);
  Observer* const observers[] = {&checker};
  const RunResult result = run_session(s.model, *s.rules, source, observers);
  EXPECT_TRUE(checker.identical()) << checker.describe(*s.rules);
  bool crash = false;
  for (const Inference& inf : result.inferences) crash = crash || inf.function == "crash";
  EXPECT_TRUE(crash);
}

TEST(Recording, AnErrorInARecordedFileNamesTheRecording) {
  const Recorded& r = nutcracker();
  Recording rec = read_recording(r.file);
  RecordedFile& walnut = rec.files[2];
  ASSERT_EQ(walnut.path, "actees/walnut.yaml");
  walnut.content = replace_once(walnut.content, "limit: 378 N", "limit: oops");
  try {
    load_recorded_session(rec);
    ADD_FAILURE() << "the broken copy loaded";
  } catch (const DataError& e) {
    EXPECT_THAT(e.what(), StartsWith(r.file + "[actees/walnut.yaml]:"));
  }
  rec.files[2].path = "../../etc/x.yaml";
  EXPECT_THROW(load_recorded_session(rec), std::runtime_error);
}

TEST(Recording, AFileThatCannotBeCreatedIsAnError) {
  const CompiledSession s = load_session(kSource + "/sessions/paper-nutcracker.yaml");
  EXPECT_THROW(Recorder("/nonexistent-folder/x.afrec", s, "script"), std::runtime_error);
}

// ------------------------------------------------------------ timeline diff

TEST(TimelineDiff, PairsEventsByWhatTheyAreAndReportsShifts) {
  auto ev = [](EventKind k, double t, const char* f, int node, const char* text) {
    return NamedEvent{k, t, f, node, text};
  };
  const std::vector<NamedEvent> before = {ev(EventKind::node_reached, 0.5, "hold", 0, "grasping(agent, object)"),
                                          ev(EventKind::inferred, 1.1, "hold", 1, "held"),
                                          ev(EventKind::inferred, 2.56, "crash", 4, "x"),
                                          ev(EventKind::inferred, 3.0, "pinch", 1, "y")};
  const std::vector<NamedEvent> after = {ev(EventKind::node_reached, 0.5, "hold", 0, "grasping(agent, object)"),
                                         ev(EventKind::inferred, 1.3, "hold", 2, "held"),
                                         ev(EventKind::inferred, 2.731, "crash", 4, "x"),
                                         ev(EventKind::inferred, 3.5, "carry", 0, "z")};
  const TimelineDiff d = diff_timelines(before, after);
  EXPECT_EQ(d.same, 1u);
  EXPECT_EQ(d.shifted, 2u);
  EXPECT_EQ(d.removed, 1u);
  EXPECT_EQ(d.added, 1u);
  EXPECT_EQ(format_diff(d),
            "- 1.100 s  hold inferred\n"
            "+ 1.300 s  hold inferred  (+0.200 s)\n"
            "- 2.560 s  crash inferred\n"
            "+ 2.731 s  crash inferred  (+0.171 s)\n"
            "- 3.000 s  pinch inferred\n"
            "+ 3.500 s  carry inferred\n");
  EXPECT_TRUE(diff_timelines(before, before).identical());
}

TEST(TimelineDiff, RaisingHoldsForDelaysHoldOnly) {
  const Recorded& r = nutcracker();
  const Recording rec = read_recording(r.file);
  const CompiledSession s = load_recorded_session(rec);
  const std::string edited =
      replace_once(slurp(kSource + "/rules/functions.yaml"), "        for: 300 ms", "        for: 500 ms");
  const std::shared_ptr<const RuleSet> rules = read_rules(edited, "hold500.yaml");
  RecordingSource source(rec);
  ReplayChecker physics(rec, false);
  TimelineCollector rerun;
  Observer* const observers[] = {&physics, &rerun};
  run_session(s.model, *rules, source, observers);
  EXPECT_TRUE(physics.identical()) << physics.describe(*rules);
  std::vector<NamedEvent> recorded;
  for (const Event& e : rec.events) recorded.push_back(name_event(*s.rules, e));
  const TimelineDiff d = diff_timelines(recorded, rerun.named(*rules));
  ASSERT_FALSE(d.identical());
  EXPECT_EQ(d.removed, 0u);
  EXPECT_EQ(d.added, 0u);
  // hold's last node and its inference, and carry's first node (carry
  // requires hold), each 200 ms later.
  EXPECT_EQ(d.shifted, 3u);
  for (const TimelineChange& c : d.changes) {
    EXPECT_EQ(c.kind, TimelineChange::shifted);
    EXPECT_THAT(c.before.function, ::testing::AnyOf("hold", "carry"));
    EXPECT_NEAR(c.after.t - c.before.t, 0.2, 1e-9) << format_event(c.before);
  }
}

}  // namespace
}  // namespace afford::test
