// Outputs never lose a user's data, and every limit agrees with itself
// (issue 31): engine/base/output_file.h, the recorder's cap (devices/recording.h)
// and the limits compared with a tolerance (engine/base/units.h).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "errors.h"
#include "files.h"
#include "load.h"
#include "output_file.h"
#include "recording.h"
#include "recording_source.h"
#include "run.h"
#include "scripted_agent.h"
#include "session.h"
#include "test_sessions.h"
#include "test_util.h"
#include "yaml_reader.h"

namespace afford {
namespace {
using test::TempDir;
using test::paper_nutcracker;
using test::kSource;

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;


std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A file written as a user would, not through afford.
void user_writes(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::string refused(const std::function<void()>& f) { return test::thrown<OutputRefused>(f); }

// Only the named files, the manifest aside: no temporary file is left.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// ------------------------------------------------------------ outputs

TEST(Outputs, AFileIsWrittenWholeAndListedAsAffordsOwn) {
  TempDir dir;
  write_file_checked(dir.at("a.txt"), "one");
  EXPECT_EQ(slurp(dir.at("a.txt")), "one");
  EXPECT_TRUE(listed_as_afford_output(dir.at("a.txt")));
  write_file_checked(dir.at("a.txt"), "two");  // its own: replaced without --force
  EXPECT_EQ(slurp(dir.at("a.txt")), "two");
  EXPECT_EQ(names_in(dir.path), (std::vector<std::string>{kOutputManifest, "a.txt"}));
}

TEST(Outputs, AForeignFileIsKeptUnlessForced) {
  TempDir dir;
  user_writes(dir.at("notes.txt"), "the user's");
  EXPECT_THAT(refused([&] { write_file_checked(dir.at("notes.txt"), "afford's"); }),
              HasSubstr(dir.at("notes.txt") + ": exists and afford did not write it; choose another name, or "
                                              "--force to replace it"));
  EXPECT_EQ(slurp(dir.at("notes.txt")), "the user's");
  const OutputScope force({.writer = "test", .force = true, .inputs = {}});
  write_file_checked(dir.at("notes.txt"), "afford's");
  EXPECT_EQ(slurp(dir.at("notes.txt")), "afford's");
}

TEST(Outputs, ASymlinkIsNeverFollowed) {
  TempDir dir;
  user_writes(dir.at("precious.txt"), "keep me");
  fs::create_symlink(dir.at("precious.txt"), dir.at("trace.csv"));
  const OutputScope force({.writer = "test", .force = true, .inputs = {}});  // not even with --force
  EXPECT_THAT(refused([&] { write_file_checked(dir.at("trace.csv"), "x"); }),
              HasSubstr(dir.at("trace.csv") + ": a symbolic link; afford does not write through links"));
  EXPECT_THAT(refused([&] { CheckedFile f(dir.at("trace.csv")); }), HasSubstr("a symbolic link"));
  EXPECT_EQ(slurp(dir.at("precious.txt")), "keep me");
  EXPECT_TRUE(fs::is_symlink(dir.at("trace.csv")));
}

TEST(Outputs, AnInputIsNeverAnOutput) {
  TempDir dir;
  user_writes(dir.at("session.yaml"), "the session");
  fs::create_hard_link(dir.at("session.yaml"), dir.at("same.yaml"));
  const OutputScope scope({.writer = "test", .force = true, .inputs = {dir.at("session.yaml")}});
  for (const std::string& name : {dir.at("session.yaml"), dir.at("same.yaml"), dir.at("./session.yaml")}) {
    EXPECT_THAT(refused([&] { write_file_checked(name, "x"); }),
                HasSubstr(name + ": one of this command's inputs; choose another output"));
  }
  EXPECT_EQ(slurp(dir.at("session.yaml")), "the session");
}

TEST(Outputs, AFailedWriteLeavesTheEarlierFile) {
  TempDir dir;
  write_file_checked(dir.at("trace.csv"), "earlier");
  {
    CheckedFile f(dir.at("trace.csv"));
    std::fputs("half of a new one", f.file);
    // destroyed without close(): as when the run throws
  }
  EXPECT_EQ(slurp(dir.at("trace.csv")), "earlier");
  EXPECT_EQ(names_in(dir.path), (std::vector<std::string>{kOutputManifest, "trace.csv"}));
}

TEST(Outputs, StaleFilesOfTheSameWriterAreClearedAndOnlyThose) {
  TempDir dir;
  {
    const OutputScope first({.writer = "explore", .force = false, .inputs = {}});
    write_file_checked(dir.at("walnut.svg"), "old");
    write_file_checked(dir.at("hazelnut.svg"), "old");
  }
  {
    const OutputScope other({.writer = "gap", .force = false, .inputs = {}});
    write_file_checked(dir.at("residual.svg"), "gap's");
  }
  user_writes(dir.at("notes.txt"), "the user's");
  const OutputScope second({.writer = "explore", .force = false, .inputs = {}});
  write_file_checked(dir.at("walnut.svg"), "new");
  EXPECT_EQ(clear_stale_outputs(dir.path.string()), std::vector<std::string>{dir.at("hazelnut.svg")});
  EXPECT_EQ(names_in(dir.path),
            (std::vector<std::string>{kOutputManifest, "notes.txt", "residual.svg", "walnut.svg"}));
  EXPECT_FALSE(listed_as_afford_output(dir.at("hazelnut.svg")));
  EXPECT_TRUE(listed_as_afford_output(dir.at("residual.svg")));
}

TEST(Outputs, AFileAnotherCommandWroteSinceIsNotStale) {
  TempDir dir;
  {
    const OutputScope first({.writer = "explore", .force = false, .inputs = {}});
    write_file_checked(dir.at("plot.svg"), "explore's");
  }
  {
    const OutputScope other({.writer = "gap", .force = false, .inputs = {}});
    write_file_checked(dir.at("plot.svg"), "gap's");
  }
  const OutputScope again({.writer = "explore", .force = false, .inputs = {}});
  EXPECT_TRUE(clear_stale_outputs(dir.path.string()).empty());
  EXPECT_EQ(slurp(dir.at("plot.svg")), "gap's");
  EXPECT_TRUE(listed_as_afford_output(dir.at("plot.svg")));
}

TEST(Outputs, ADamagedManifestIsALocatedError) {
  TempDir dir;
  user_writes(dir.at(kOutputManifest), "# head\nexplore\t../../etc/passwd\n");
  user_writes(dir.at("a.svg"), "x");
  EXPECT_THAT(test::thrown<DataError>([&] { clear_stale_outputs(dir.path.string()); }),
              HasSubstr(dir.at(kOutputManifest) + ":2:1: expected WRITER<TAB>FILE NAME"));
}

// ------------------------------------------------------------ recordings

std::int64_t record(const std::string& file, std::uint64_t max_bytes, std::string* error) {
  const CompiledSession& s = paper_nutcracker();
  Recorder recorder(file, s, "script", 0, max_bytes);
  ScriptedAgent agent(s.script);
  Observer* const observers[] = {&recorder};
  run_session(s.model, *s.rules, agent, observers);
  *error = recorder.error();
  return recorder.frames();
}

TEST(Outputs, TheRecorderStopsBeforeTheCapAndTheReaderReadsWhatItWrote) {
  TempDir dir;
  const std::uint64_t cap = 200000;  // bytes: about 500 frames of the nutcracker's 4000
  std::string error;
  const std::int64_t frames = record(dir.at("capped.afrec"), cap, &error);
  EXPECT_THAT(error, HasSubstr(dir.at("capped.afrec") + ": stopped recording after " + std::to_string(frames) +
                               " frames"));
  EXPECT_THAT(error, HasSubstr("the next record would take it past 200000 bytes"));
  EXPECT_LE(fs::file_size(dir.at("capped.afrec")), cap);
  EXPECT_GT(frames, 100);
  const Recording rec = read_recording(dir.at("capped.afrec"));
  EXPECT_EQ(static_cast<std::int64_t>(rec.frames.size()), frames);
  EXPECT_EQ(rec.tail, RecordingTail::no_end);
}

TEST(Outputs, TheWriterAndTheReaderShareOneCap) {
  // What the recorder may write by default, the reader reads: one constant.
  TempDir dir;
  std::string error;
  EXPECT_EQ(record(dir.at("whole.afrec"), kMaxRecordingBytes, &error), 4000);
  EXPECT_EQ(error, "");
  const std::string huge = dir.at("huge.afrec");
  write_file_checked(huge, "");
  fs::resize_file(huge, kMaxRecordingBytes + 1);  // sparse
  EXPECT_THAT(test::thrown<DataError>([&] { read_recording(huge); }),
              HasSubstr("expected a file of at most " + std::to_string(kMaxRecordingBytes) + " bytes"));
}

TEST(Outputs, ASessionTooLongToRecordIsRefusedBeforeItStarts) {
  TempDir dir;
  // 6 million frames (600 s at 0.1 ms, say) of at least 371 bytes: over 2 GiB.
  const std::string file = dir.at("long.afrec");
  EXPECT_THAT(test::thrown<std::runtime_error>([&] { Recorder(file, paper_nutcracker(), "script", 6000000); }),
              HasSubstr(file + ": cannot record 6000000 frames of 1 ms: at least 212"));
  EXPECT_FALSE(fs::exists(file));
}

TEST(Outputs, ARecordingReplacesAnEarlierOneButNotAForeignFile) {
  TempDir dir;
  std::string error;
  record(dir.at("r.afrec"), kMaxRecordingBytes, &error);
  user_writes(dir.at("cp.afrec"), slurp(dir.at("r.afrec")));  // a copy: recognised by its header
  record(dir.at("cp.afrec"), kMaxRecordingBytes, &error);
  EXPECT_EQ(error, "");
  user_writes(dir.at("notes.afrec"), "not a recording");
  EXPECT_THAT(refused([&] { Recorder(dir.at("notes.afrec"), paper_nutcracker(), "script"); }),
              HasSubstr("exists and afford did not write it"));
  EXPECT_EQ(slurp(dir.at("notes.afrec")), "not a recording");
}

TEST(Outputs, TrailingBytesAfterTheEndRecordAreReported) {
  TempDir dir;
  std::string error;
  record(dir.at("r.afrec"), kMaxRecordingBytes, &error);
  std::ofstream(dir.at("r.afrec"), std::ios::binary | std::ios::app) << "12345";
  const Recording rec = read_recording(dir.at("r.afrec"));
  EXPECT_EQ(rec.tail, RecordingTail::end);
  EXPECT_EQ(rec.summary(), "4000 frames, ended cleanly; 5 bytes after its end record are ignored");
}

// ------------------------------------------------------------ limits and locations

TEST(Limits, TheDocumentedLimitsPassExactlyInAnyUnit) {
  EXPECT_TRUE(at_least(10 * 1e-6, 1e-5));  // 10 us: below 1e-5 in floating point
  EXPECT_FALSE(at_least(9.99e-6, 1e-5));
  EXPECT_TRUE(at_most(0.1, 0.1));
  EXPECT_FALSE(at_most(0.1001, 0.1));
}

CompiledSession session_with(const std::string& timestep) {
  return read_session(load_yaml_string(test::kNutcrackerSession + "timestep: " + timestep + "\n",
                                       test::kSessionName));
}

TEST(Limits, ATimestepOf10UsIsAccepted) {
  EXPECT_DOUBLE_EQ(session_with("10 us").model.timestep, 1e-5);
  EXPECT_DOUBLE_EQ(session_with("0.01 ms").model.timestep, 1e-5);
  EXPECT_THAT(test::thrown<DataError>([] { session_with("9 us"); }), HasSubstr("expected a timestep from"));
}

std::string walnut_with(const std::string& shape) {
  const std::string text = slurp(kSource + "/actees/walnut.yaml");
  const std::string yaml =
      test::replace_once(text, "shape: {ellipsoid: {radii: [18 mm, 14.1 mm, 14.1 mm]}}", "shape: " + shape);
  try {
    read_actee(load_yaml_string(yaml, "walnut.yaml"));
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

TEST(Limits, BoxSizesAndEllipsoidRadiiBelow1UmAreRejectedLikeSpheres) {
  EXPECT_THAT(walnut_with("{ellipsoid: {radii: [18 mm, 1e-320 mm, 14.1 mm]}}"),
              HasSubstr("walnut.yaml:21:36: expected a length (e.g. '18 mm') of at least 0.001 mm"));
  EXPECT_THAT(walnut_with("{box: {size: [0.9 um, 20 mm, 20 mm]}}"),
              HasSubstr("walnut.yaml:21:22: expected a length (e.g. '18 mm') of at least 0.001 mm"));
  EXPECT_THAT(walnut_with("{sphere: {radius: 0.9 um}}"), HasSubstr("walnut.yaml:21:26: expected a length (e.g. '18 mm') of at least 0.001 mm"));
  // 1 um itself, in any unit, is not refused for its size.
  EXPECT_THAT(walnut_with("{box: {size: [1 um, 0.001 mm, 1e-6 m]}}"), Not(HasSubstr("of at least")));
}

TEST(Locations, AFileLevelErrorNamesTheFileWithoutAFakeLineAndColumn) {
  TempDir dir;
  EXPECT_EQ(test::thrown<DataError>([&] { read_regular_file(dir.at("none.yaml"), 100); }),
            dir.at("none.yaml") + ": expected a readable file, found none");
  fs::create_symlink(dir.at("loop.yaml"), dir.at("loop.yaml"));
  EXPECT_EQ(test::thrown<DataError>([&] { read_regular_file(dir.at("loop.yaml"), 100); }),
            dir.at("loop.yaml") + ": expected a readable file, found a loop of symbolic links");
}

}  // namespace
}  // namespace afford
