// afford check FILE...: validate files; non-zero exit on any error.
#include <iostream>

#include "commands.h"
#include "option_checks.h"
#include "errors.h"
#include "device_description.h"
#include "measurement.h"
#include "rule_tests.h"
#include "setup_warnings.h"
#include "validate.h"

namespace afford::cli {

namespace {

std::string check_device(const Node& root) { return "device " + read_device_description(root).name; }

std::string check_measurement(const Node& root) {
  const Measurement m = read_measurement(root);
  return "measurement " + m.name + ", " + std::to_string(m.traces.size()) + " traces";
}

// A rule test's keys, and the session and rules it names; not for a case
// whose point is that they fail to load (`error:`).
std::string check_rule_test(const Node& root) {
  const RuleCase c = read_rule_case(root);
  if (!c.error) compile_rule_case(c);
  return "rule test " + c.name;
}

int check_files(const std::vector<std::string>& files) {
  add_file_kind("device", check_device);  // device descriptions live in devices/
  add_file_kind("measurement", check_measurement);  // and measurements in gap/
  add_file_kind("test", check_rule_test);  // rule tests live in tests/rules/
  int errors = 0;
  for (const std::string& path : files) {
    try {
      std::vector<Warning> warnings;
      const std::string what = validate_file(path, &warnings);  // before printing: it may throw
      std::cout << path << ": ok (" << what << ")\n";
      std::cout.flush();  // before the warnings, in order on a terminal
      for (const Warning& w : warnings) std::cerr << w.str() << "\n";
    } catch (const DataError& e) {
      std::cerr << e.what() << "\n";
      ++errors;
    }
  }
  return errors == 0 ? 0 : 1;
}

}  // namespace

void add_check(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand("check", "validate object, actee, agent, session, rules and other files");
  auto files = std::make_shared<std::vector<std::string>>();
  cmd->add_option("FILE", *files, "a file to validate (any kind afford reads)")->required()->type_name(kFile);
  cmd->callback([run, files] { *run = [files] { return check_files(*files); }; });
}

}  // namespace afford::cli
