// afford test [DIR] [--coverage]: runs every rule test case under DIR
// (default tests/rules; every *.yaml file in it and its subfolders is a
// case, engine/session/rule_tests.h), in the order of their paths, and prints one
// line per case:
//   PASS name (file)
//   FAIL name (file): reason
// then, with --coverage, the nodes of each function-model file that the
// cases reached, and last the line "N passed, M failed". Exit status 1 when
// a case failed (or DIR holds no case), 0 otherwise, 2 on bad usage.
#include <algorithm>
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "option_checks.h"
#include "rule_tests.h"
#include "scripted_agent.h"

namespace afford::cli {
namespace {

namespace fs = std::filesystem;

// Every case file under dir, sorted by its path relative to dir.
std::vector<std::string> case_files(const fs::path& dir) {
  std::vector<fs::path> relative;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".yaml" || ext == ".yml")) relative.push_back(fs::relative(e.path(), dir));
  }
  std::sort(relative.begin(), relative.end(),
            [](const fs::path& a, const fs::path& b) { return a.generic_string() < b.generic_string(); });
  std::vector<std::string> out;
  for (const fs::path& p : relative) out.push_back((dir / p).string());
  return out;
}

void print_coverage(const std::vector<RulesCoverage>& coverage) {
  for (const RulesCoverage& file : coverage) {
    int reached = 0, all = 0;
    for (const FunctionCoverage& f : file.functions) {
      for (const NodeCoverage& n : f.nodes) {
        reached += n.reached ? 1 : 0;
        ++all;
      }
    }
    std::cout << "coverage of " << file.file << ": " << reached << "/" << all << " nodes reached\n";
    for (const FunctionCoverage& f : file.functions) {
      int r = 0;
      for (const NodeCoverage& n : f.nodes) r += n.reached ? 1 : 0;
      std::cout << "  " << f.name << " " << r << "/" << f.nodes.size() << " nodes";
      if (r == static_cast<int>(f.nodes.size())) {
        std::cout << "\n";
        continue;
      }
      std::cout << ", unreached:\n";
      for (const NodeCoverage& n : f.nodes) {
        if (!n.reached) std::cout << "    " << n.loc.file << ":" << n.loc.line << "  " << n.text << "\n";
      }
    }
  }
}

struct TestOptions {
  std::string dir = "tests/rules";
  bool coverage = false;
};

int test(const TestOptions& o) {
  const std::string& dir = o.dir;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return usage_error("test: '" + dir + "' is not a directory of rule test cases");

  const AgentFactory agent = [](const Script& script) -> std::unique_ptr<SampleSource> {
    return std::make_unique<ScriptedAgent>(script);
  };
  const std::vector<std::string> files = case_files(dir);
  int passed = 0, failed = 0;
  std::vector<RulesCoverage> total;
  for (const std::string& file : files) {
    const RuleCaseResult r = run_rule_case(file, agent);
    if (r.passed) {
      ++passed;
      std::cout << "PASS " << r.name << " (" << r.file << ")\n";
    } else {
      ++failed;
      std::cout << "FAIL " << r.name << " (" << r.file << "): " << r.reason() << "\n";
    }
    std::cout.flush();
    if (r.coverage) merge_coverage(&total, *r.coverage);
  }
  if (files.empty()) std::cout << "no rule test cases (*.yaml) under " << dir << "\n";
  if (o.coverage) print_coverage(total);
  std::cout << passed << " passed, " << failed << " failed\n";
  return failed > 0 || files.empty() ? 1 : 0;
}

}  // namespace

void add_test(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand("test", "run the rule test cases under DIR: PASS/FAIL each, nodes reached");
  auto o = std::make_shared<TestOptions>();
  cmd->add_option("DIR", o->dir, "the folder of rule test cases (*.yaml, searched recursively)")
      ->type_name(kDir)
      ->capture_default_str();
  cmd->add_flag("--coverage", o->coverage, "also print the nodes of each function model the cases reached");
  cmd->callback([run, o] { *run = [o] { return test(*o); }; });
}

}  // namespace afford::cli
