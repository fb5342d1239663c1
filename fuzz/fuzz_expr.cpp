// Fuzzes the predicate language: the bytes are one predicate (`when:`),
// parsed alone (engine/rules/expr.h) and then compiled with its function model
// (rules_compile.cpp) as if written in rules/functions.yaml. The first
// byte says whether the YAML quotes it (locations shift by the quote). A DataError is the expected
// answer; anything else is a bug.
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "errors.h"
#include "expr.h"
#include "rules.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool quoted = (data[0] & 1) != 0;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    afford::parse_expression(text, afford::SourceLoc{"fuzz.yaml", 1, 1}, quoted);
  } catch (const afford::DataError&) {
  }

  // The same text as the only node of a function model.
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "functions" << YAML::Value << YAML::BeginSeq << YAML::BeginMap
      << YAML::Key << "name" << YAML::Value << "fuzzed" << YAML::Key << "nodes" << YAML::Value << YAML::BeginSeq
      << YAML::BeginMap << YAML::Key << "when" << YAML::Value;
  if (quoted) out << YAML::DoubleQuoted;
  out << text << YAML::EndMap << YAML::EndSeq << YAML::EndMap << YAML::EndSeq << YAML::EndMap;
  if (!out.good()) return 0;  // not representable as YAML (invalid UTF-8): the parser never sees it
  try {
    afford::read_rules(out.c_str(), "fuzz.yaml");
  } catch (const afford::DataError&) {
  }
  return 0;
}
