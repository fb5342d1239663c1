// Hostile input (issue 13): deep nesting, long chains, extra documents,
// files that are not regular or too large, values out of physical bounds,
// huge values in errors, failed writes. Each is a located error, at once.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "errors.h"
#include "test_util.h"
#include "expr.h"
#include "files.h"
#include "load.h"
#include "rules.h"
#include "session.h"
#include "yaml_reader.h"

#include <yaml-cpp/yaml.h>

namespace afford {
namespace {

using ::testing::HasSubstr;

std::string rules_with(const std::string& when) {
  return "functions:\n"
         "  - name: deep\n"
         "    description: d\n"
         "    nodes:\n"
         "      - when: " + when + "\n";
}

// The located message of the DataError a call throws.
template <class F>
std::string error_of(F&& f) {
  return test::thrown<DataError>(f);
}

TEST(Hardening, ParenthesesDeeperThanTheLimitAreLocated) {
  const int n = kMaxExprNesting + 1;
  const std::string when = std::string(n, '(') + "true" + std::string(n, ')');
  // Column 15 is the expression's first character; the last '(' is too deep.
  const std::string col = std::to_string(15 + kMaxExprNesting);
  EXPECT_THAT(error_of([&] { read_rules(rules_with(when), "deep.yaml"); }),
              HasSubstr("deep.yaml:5:" + col + ": expected at most 64 levels of parentheses, found '('"));
  // Thousands of levels: the same error, not a stack overflow.
  const std::string huge = std::string(100000, '(') + "true" + std::string(100000, ')');
  EXPECT_THAT(error_of([&] { read_rules(rules_with(huge), "deep.yaml"); }), HasSubstr("levels of parentheses"));
}

TEST(Hardening, ParenthesesAtTheLimitCompile) {
  const int n = kMaxExprNesting;
  EXPECT_NO_THROW(read_rules(rules_with(std::string(n, '(') + "true" + std::string(n, ')')), "ok.yaml"));
}

// A chain of `and`, `*` or `not` terms is flat, not nested: it compiles, in
// linear time (30,000 terms took 6 s when each node copied its text).
TEST(Hardening, LongFlatChainsCompileQuickly) {
  const auto start = std::chrono::steady_clock::now();
  std::string ands = "true", products = "1", nots;
  for (int i = 0; i < 30000; ++i) {
    ands += " and true";
    products += " * 1";
    nots += "not ";
  }
  EXPECT_NO_THROW(read_rules(rules_with(ands), "and.yaml"));
  EXPECT_NO_THROW(read_rules(rules_with(products + " > 0"), "mul.yaml"));
  EXPECT_NO_THROW(read_rules(rules_with(nots + "true"), "not.yaml"));
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(s, 5.0);
}

TEST(Hardening, YamlNestedTooDeeplyIsLocated) {
  std::string text = "a: ";
  for (int i = 0; i < kMaxYamlDepth + 5; ++i) text += "[";
  for (int i = 0; i < kMaxYamlDepth + 5; ++i) text += "]";
  EXPECT_THAT(error_of([&] { load_yaml_string(text, "nest.yaml"); }),
              HasSubstr("nest.yaml:1:" + std::to_string(3 + kMaxYamlDepth) +
                        ": expected at most 32 levels of nesting, found a value nested deeper"));
}

TEST(Hardening, TooManyValuesAreRejectedQuickly) {
  std::string text = "fields:\n";
  for (int i = 0; i < 100000; ++i) text += "  - x\n";
  EXPECT_THAT(error_of([&] { load_yaml_string(text, "many.yaml"); }),
              HasSubstr("many.yaml:" + std::to_string(kMaxYamlNodes - 1) + ":5: expected at most 20000 values in a file"));
}

TEST(Hardening, ASecondDocumentIsAnErrorAtItsLine) {
  EXPECT_THAT(error_of([] { load_yaml_string("---\na: 1\nb: 2\n---\nc: [\n", "two.yaml"); }),
              HasSubstr("two.yaml:4:1: expected one YAML document per file, found a second document ('---')"));
  EXPECT_NO_THROW(load_yaml_string("# leading comment\n---\na: 1\n", "one.yaml"));
}

// Found by fuzz_actee and nine other YAML fuzzers: yaml-cpp read a ','
// where no node can start as endless empty documents until memory ran out.
TEST(Hardening, AStrayCommaIsASyntaxErrorNotAHang) {
  EXPECT_THAT(error_of([] { load_yaml_string(",", "comma.yaml"); }),
              HasSubstr("comma.yaml:1:1: expected valid YAML, found ',' where no YAML node can start"));
  EXPECT_THAT(error_of([] { load_yaml_string("# a comment\n,test: x\nnote: y\n", "lead.yaml"); }),
              HasSubstr("lead.yaml:2:1: expected valid YAML, found ',' where no YAML node can start"));
  EXPECT_THAT(error_of([] { load_yaml_string("a: 1\n...\nb: 2\n", "end.yaml"); }),
              HasSubstr("end.yaml:3:1: expected one YAML document per file, found a second document"));
}

// A file is parsed once where yaml-cpp can only end its document at the end
// of the text; where the document could end sooner (a root mapping that is
// indented, a directive line), the second document is still found.
TEST(Hardening, ASecondDocumentIsFoundWhereTheFirstCouldEndEarly) {
  EXPECT_THAT(error_of([] { load_yaml_string("  a: 1\nb: 2\n", "indented.yaml"); }),
              HasSubstr("indented.yaml:2:1: expected one YAML document per file, found a second document"));
  EXPECT_THAT(error_of([] { load_yaml_string("a: 1\n%TAG ! tag:x,2000:\nb: 2\n", "directive.yaml"); }),
              HasSubstr("directive.yaml:3:1: expected one YAML document per file, found a second document"));
  EXPECT_NO_THROW(load_yaml_string("a: 1\nb: [2,\n  3]\nc: |\n  ...\n", "one.yaml"));
}

// yaml-cpp reads comments slowly; the lines of comments before a file's
// first content are emptied before it parses, their line ends kept.
TEST(Hardening, LeadingCommentsAreEmptiedAndEveryPlaceStays) {
  EXPECT_EQ(without_leading_comments("# a\n  # b\n\nkey: 1 # c\n# d\n"), "\n\n\nkey: 1 # c\n# d\n");
  EXPECT_EQ(without_leading_comments("# a\r\nk: v\r\n"), "\r\nk: v\r\n");
  EXPECT_EQ(without_leading_comments("# a\n\t# b\nk: 1\n"), "\n\t# b\nk: 1\n");  // a tab: yaml-cpp's to judge
  EXPECT_EQ(without_leading_comments("# only"), "");
  EXPECT_EQ(without_leading_comments("k: 1\n# a\n"), "k: 1\n# a\n");
  const std::string bom = "\xEF\xBB\xBF# a\nk: 1\n";
  EXPECT_EQ(without_leading_comments(bom), bom);
  const std::string utf16("#\0 \0a\0\n\0", 8);
  EXPECT_EQ(without_leading_comments(utf16), utf16);
  // Errors keep their line and column.
  EXPECT_THAT(error_of([] { load_yaml_string("# a\n  # b\n,x: 1\n", "lead.yaml"); }),
              HasSubstr("lead.yaml:3:1: expected valid YAML, found ',' where no YAML node can start"));
  EXPECT_THAT(error_of([] { load_yaml_string("# a\n# b\n\nk: [1, 2\n", "flow.yaml"); }),
              HasSubstr("flow.yaml:5:1: expected valid YAML, found a syntax error: end of sequence flow not found"));
  EXPECT_THAT(error_of([] { load_yaml_string("# a\n# b\n", "empty.yaml"); }),
              HasSubstr("empty.yaml:1:1: expected a YAML mapping, found an empty file"));
}

// Every shipped YAML file is the same tree, at the same places, with its
// leading comments emptied.
TEST(Hardening, ShippedFilesParseTheSameWithoutTheirLeadingComments) {
  int files = 0, shorter = 0;
  for (const char* folder : {"objects", "actees", "agents", "rules", "sessions", "devices", "measurements",
                             "tests/rules"}) {
    for (const auto& entry : std::filesystem::directory_iterator(std::string(AFFORD_SOURCE_DIR) + "/" + folder)) {
      if (entry.path().extension() != ".yaml") continue;
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      const std::string emptied = without_leading_comments(raw);
      EXPECT_EQ(std::count(raw.begin(), raw.end(), '\n'), std::count(emptied.begin(), emptied.end(), '\n'));
      const YAML::Node a = YAML::Load(raw), b = YAML::Load(emptied);
      EXPECT_EQ(YAML::Dump(a), YAML::Dump(b)) << entry.path();
      ASSERT_TRUE(a.IsMap()) << entry.path();
      for (auto i = a.begin(), j = b.begin(); i != a.end() && j != b.end(); ++i, ++j) {
        EXPECT_EQ(i->first.Mark().line, j->first.Mark().line) << entry.path();
        EXPECT_EQ(i->second.Mark().column, j->second.Mark().column) << entry.path();
      }
      ++files;
      shorter += emptied.size() < raw.size() ? 1 : 0;
    }
  }
  EXPECT_GT(files, 40);
  EXPECT_GT(shorter, 20);  // most open with their sources or reasons
}

TEST(Hardening, OnlyRegularFilesAreRead) {
  const std::string fifo = testing::TempDir() + "afford_fifo_" + std::to_string(getpid());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THAT(error_of([&] { load_yaml_file(fifo); }),
              HasSubstr(fifo + ": expected a regular file, found a FIFO"));
  std::remove(fifo.c_str());
  EXPECT_THAT(error_of([] { load_yaml_file("/dev/zero"); }),
              HasSubstr("/dev/zero: expected a regular file, found a device"));
  EXPECT_THAT(error_of([] { load_yaml_file("/dev/urandom"); }), HasSubstr("found a device"));
}

TEST(Hardening, FilesLargerThanTheCapAreRejectedBeforeReading) {
  const std::string path = testing::TempDir() + "afford_big_" + std::to_string(getpid()) + ".yaml";
  {
    std::ofstream out(path);
    out << "a: '" << std::string(kMaxYamlBytes, 'v') << "'\n";
  }
  EXPECT_THAT(error_of([&] { load_yaml_file(path); }),
              HasSubstr(path + ": expected a file of at most 1048576 bytes, found 1048582 bytes"));
  std::remove(path.c_str());
}

TEST(Hardening, HugeValuesAreShortenedInErrors) {
  const std::string value(1000000, 'v');
  const std::string message = error_of([&] { read_rules("functions: " + value + "\n", "big.yaml"); });
  EXPECT_THAT(message, HasSubstr("found 'vvvvvvvvvv"));
  EXPECT_THAT(message, HasSubstr("\u2026' (1000000 characters)"));
  EXPECT_LT(message.size(), 300u);
}

std::string shipped(const std::string& path) {
  std::ifstream in(std::string(AFFORD_SOURCE_DIR) + "/" + path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Hardening, ActeeParametersOutsidePhysicalBoundsAreLocated) {
  std::string egg = shipped("actees/egg.yaml");
  const size_t at = egg.find("stiffness:");
  ASSERT_NE(at, std::string::npos);
  egg.replace(at, egg.find('\n', at) - at, "stiffness: 5e-324 N/m");
  EXPECT_THAT(error_of([&] { read_actee(load_yaml_string(egg, "egg.yaml")); }),
              HasSubstr("egg.yaml:31:12: expected a stiffness (e.g. '800 N/m') of at least 0.001 N/m (the range that makes sense for a hand tool), found '5e-324 N/m'"));
  egg.replace(at, egg.find('\n', at) - at, "stiffness: 1e308 N/m");
  EXPECT_THAT(error_of([&] { read_actee(load_yaml_string(egg, "egg.yaml")); }),
              HasSubstr("egg.yaml:31:12: expected a stiffness (e.g. '800 N/m') of at most 1e+09 N/m in size"));
}

// A session is run for its script's duration at its timestep: both bounded.
std::string session_error(const std::string& from, const std::string& to) {
  std::string text = shipped("sessions/paper-tongs.yaml");
  const size_t at = text.find(from);
  text.replace(at, from.size(), to);
  const std::string path =
      std::string(AFFORD_SOURCE_DIR) + "/sessions/.hardening-" + std::to_string(getpid()) + ".yaml";
  {
    std::ofstream(path) << text;
  }
  const std::string e = error_of([&] { load_session(path); });
  std::remove(path.c_str());
  return e;
}

TEST(Hardening, SessionTimestepAndDurationAreBounded) {
  EXPECT_THAT(session_error("grasps: ../rules/grasps.yaml\n", "grasps: ../rules/grasps.yaml\ntimestep: 1e-9 s\n"),
              HasSubstr(":35:11: expected a timestep from 1e-05 s to 0.1 s, found '1e-9 s'"));
  std::string text = shipped("sessions/paper-tongs.yaml");
  const size_t last = text.rfind("  - t: ");
  const std::string line = text.substr(last, text.find('\n', last) - last);
  EXPECT_THAT(session_error(line, "  - t: 1e9 s"), HasSubstr(":63:8: expected a time (e.g. '200 ms') of at most 3600 s in size (the range that makes sense for a hand tool), found '1e9 s'"));
  EXPECT_THAT(session_error(line, "  - t: 3000 s"), HasSubstr(":63:8: expected a last keyframe at most 600 s (the script's duration), found 3000 s"));
}

TEST(Hardening, AFailedWriteNamesThePathAndTheReason) {
  try {
    write_file_checked("/dev/full", "x");
    FAIL() << "no error";
  } catch (const WriteError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot write /dev/full: No space left on device"));
  }
  EXPECT_THROW(write_file_checked("/nonexistent-dir/x.json", "x"), WriteError);
}

}  // namespace
}  // namespace afford
