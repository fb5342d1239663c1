// The kinds of file that `afford check` adds to the engine's (devices,
// measurements, rule tests; cli/check.cpp), registered the same way for
// the fuzzers.
#pragma once

#include <string>

#include "device_description.h"
#include "measurement.h"
#include "rule_tests.h"
#include "validate.h"
#include "yaml_reader.h"

namespace afford::fuzz {

inline void add_check_kinds() {
  add_file_kind("device", [](const Node& root) { return "device " + read_device_description(root).name; });
  add_file_kind("measurement", [](const Node& root) { return "measurement " + read_measurement(root).name; });
  add_file_kind("test", [](const Node& root) {
    const RuleCase c = read_rule_case(root);
    if (!c.error) compile_rule_case(c);
    return "rule test " + c.name;
  });
}

}  // namespace afford::fuzz
