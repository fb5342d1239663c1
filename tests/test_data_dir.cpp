// Where the shipped data is found (engine/base/data_dir.h): the order of the
// places looked in, and the errors that name them.
#include <gtest/gtest.h>
#include <gmock/gmock.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "data_dir.h"

namespace afford {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A scratch tree: a source tree, a build tree, a moved install prefix, a
// configured install folder and an $AFFORD_DATA_DIR folder, each holding
// the shipped folders unless a test removes them.
class DataDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("afford-data-dir-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    for (const char* dir : {"src", "prefix/share/afford", "installed", "env"}) give_data(root_ / dir);
    fs::create_directories(root_ / "build/cli");
    fs::create_directories(root_ / "prefix/bin");
    fs::create_directories(root_ / "empty");
    search_.program = (root_ / "build/cli/afford").string();
    search_.build_dir = (root_ / "build").string();
    search_.source_dir = (root_ / "src").string();
    search_.program_to_data = "../share/afford";
    search_.installed_dir = (root_ / "installed").string();
  }
  void TearDown() override { fs::remove_all(root_); }

  static void give_data(const fs::path& dir) {
    for (const char* folder : {"rules", "agents", "actees", "objects"}) fs::create_directories(dir / folder);
  }
  std::string at(const std::string& relative) const { return (root_ / relative).string(); }
  std::string error_of(const DataDirSearch& s) const {
    try {
      find_data_dir(s);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "no error";
  }

  fs::path root_;
  DataDirSearch search_;
};

TEST_F(DataDirTest, TheEnvironmentVariableComesFirst) {
  search_.env = at("env");
  EXPECT_EQ(find_data_dir(search_), at("env"));
}

TEST_F(DataDirTest, AWrongEnvironmentVariableIsAnErrorNotPassedOver) {
  search_.env = at("empty");
  EXPECT_THAT(error_of(search_), HasSubstr("AFFORD_DATA_DIR=" + at("empty") + ": expected a folder holding afford's "
                                           "shipped data (rules/, agents/, actees/, objects/), found a folder without them"));
  search_.env = at("nowhere");
  EXPECT_THAT(error_of(search_), HasSubstr("AFFORD_DATA_DIR=" + at("nowhere") + ": expected a folder holding"));
  EXPECT_THAT(error_of(search_), HasSubstr("found no folder"));
}

TEST_F(DataDirTest, TheSourceTreeWhenRunFromTheBuildTree) {
  EXPECT_EQ(find_data_dir(search_), at("src"));
}

TEST_F(DataDirTest, AProgramOutsideTheBuildTreeFindsTheDataBesideIt) {
  search_.program = at("prefix/bin/afford");
  EXPECT_EQ(find_data_dir(search_), at("prefix/share/afford"));
}

TEST_F(DataDirTest, TheConfiguredInstallFolderComesLast) {
  search_.program = at("elsewhere/bin/app");
  EXPECT_EQ(find_data_dir(search_), at("installed"));
  // In the build tree, but the source tree has gone: on to the installed data.
  fs::remove_all(root_ / "src/rules");
  search_.program = at("build/cli/afford");
  EXPECT_EQ(find_data_dir(search_), at("installed"));
}

TEST_F(DataDirTest, NothingFoundNamesEveryPlaceLookedIn) {
  search_.program = at("elsewhere/bin/app");
  search_.installed_dir = at("empty");
  const std::string e = error_of(search_);
  EXPECT_THAT(e, HasSubstr("expected afford's shipped data (rules/, agents/, actees/, objects/), found none"));
  EXPECT_THAT(e, HasSubstr("AFFORD_DATA_DIR (not set)"));
  EXPECT_THAT(e, HasSubstr("not the source tree (the program is not in its build tree " + at("build") + ")"));
  EXPECT_THAT(e, HasSubstr(at("elsewhere/share/afford") + " (beside the program)"));
  EXPECT_THAT(e, HasSubstr(at("empty") + " (installed)"));
}

TEST_F(DataDirTest, AFolderLikeTheBuildTreeNameIsNotInsideIt) {
  // build-other/ starts with the characters of build/ but is not inside it.
  search_.program = at("build-other/cli/afford");
  search_.installed_dir = at("empty");
  EXPECT_THAT(error_of(search_), HasSubstr("not the source tree"));
}

// This test program runs from the build tree: without $AFFORD_DATA_DIR its
// shipped data is the source tree's.
TEST(DataDir, TheTestsFindTheSourceTree) {
  const char* saved = std::getenv("AFFORD_DATA_DIR");
  const std::string restore = saved ? saved : "";
  ::unsetenv("AFFORD_DATA_DIR");
  EXPECT_EQ(fs::weakly_canonical(data_dir()), fs::weakly_canonical(AFFORD_SOURCE_DIR));
  EXPECT_EQ(fs::path(shipped_path("rules/guides.yaml")), fs::path(data_dir()) / "rules/guides.yaml");
  if (saved) ::setenv("AFFORD_DATA_DIR", restore.c_str(), 1);
}

}  // namespace
}  // namespace afford
