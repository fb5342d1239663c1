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

int check_files(const std::vector<std::string>& files) {
  add_device_file_kind();       // device descriptions live in devices/
  add_measurement_file_kind();  // measurements in gap/
  add_rule_test_file_kind();    // rule tests in tests/rules/
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
