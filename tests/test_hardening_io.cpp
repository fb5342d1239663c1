// Hostile files beyond YAML (issue 13): recordings and measured traces are
// read only from regular files under a size cap, and rendered images are
// written through the checked writers, so that a failed write names the
// path and the reason.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

#include "errors.h"
#include "test_util.h"
#include "files.h"
#include "image.h"
#include "png.h"
#include "recording_source.h"
#include "trace_table.h"

namespace afford {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A FIFO in the test's temporary folder, removed with this object.
struct Fifo {
  Fifo() : path(testing::TempDir() + "afford_io_fifo_" + std::to_string(getpid())) {
    std::remove(path.c_str());
    EXPECT_EQ(mkfifo(path.c_str(), 0600), 0);
  }
  ~Fifo() { std::remove(path.c_str()); }
  std::string path;
};

TEST(HardeningIo, ARecordingIsReadOnlyFromARegularFile) {
  const Fifo fifo;
  EXPECT_THAT(test::thrown<DataError>([&] { read_recording(fifo.path); }),
              HasSubstr(fifo.path + ": expected a regular file, found a FIFO"));
  EXPECT_THAT(test::thrown<DataError>([] { read_recording("/dev/zero"); }),
              HasSubstr("/dev/zero: expected a regular file, found a device"));
}

TEST(HardeningIo, ARecordingLargerThanTheCapIsRejectedBeforeReading) {
  const std::string path = testing::TempDir() + "afford_huge_" + std::to_string(getpid()) + ".afrec";
  write_file_checked(path, "");
  fs::resize_file(path, kMaxRecordingBytes + 1);  // sparse: nothing is written
  EXPECT_THAT(test::thrown<DataError>([&] { read_recording(path); }),
              HasSubstr(path + ": expected a file of at most 1073741824 bytes, found 1073741825 bytes"));
  std::remove(path.c_str());
}

TEST(HardeningIo, ATraceIsReadOnlyFromARegularFile) {
  const Fifo fifo;
  EXPECT_THAT(test::thrown<DataError>([&] { read_trace(fifo.path, default_format(Rig::lever), Rig::lever, 2); }),
              HasSubstr(fifo.path + ": expected a regular file, found a FIFO"));
  // A missing trace is the measurement's mistake, at the key that names it.
  TableFormat f = default_format(Rig::lever);
  f.loc = SourceLoc{"m.yaml", 7, 5};
  EXPECT_THAT(test::thrown<DataError>([&] { read_trace("/nonexistent/t.csv", f, Rig::lever, 2); }),
              HasSubstr("m.yaml:7:5: expected a readable trace file '/nonexistent/t.csv', found none"));
}

TEST(HardeningIo, AFailedPngWriteNamesThePathAndTheReason) {
  const render::Image img(4, 4);
  try {
    render::write_png("/dev/full", img);
    FAIL() << "no error";
  } catch (const WriteError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot write /dev/full: No space left on device"));
  }
  try {
    render::write_png("/nonexistent-dir/frame.png", img);
    FAIL() << "no error";
  } catch (const WriteError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot write /nonexistent-dir/frame.png: No such file or directory"));
  }
}

}  // namespace
}  // namespace afford
