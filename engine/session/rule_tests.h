// Rule tests as data (DESIGN.md "Rule tests"; Open Policy Agent's
// `opa test`): a YAML case names a session (a session file, or its content
// in place), optionally other function models, and the functions it
// expects or rejects, with optional time windows; or the load error its
// files must give. `afford test` (cli/test.cpp) walks a folder of cases;
// tests/rules/README.md is the schema.
//
//   test: tongs-carry-egg            first key: the case's name
//   note: one line, optional
//   session: ../../sessions/x.yaml   a session file, relative to the case's
//                                    folder, or a session's keys in place
//                                    (`session` and `description` optional
//                                    there: they default to the case's name
//                                    and note; paths relative to the case)
//   rules: ../data/rules/edited.yaml optional: these function models instead
//                                    of the session's
//   expect:                          functions that must be inferred
//     - hold                         at least once
//     - {function: pinch, within: [0.5 s, 1.5 s]}   at least once in the window
//     - {function: hold, times: 2}   exactly twice (in the window, if any)
//   reject:                          functions that must not be inferred
//     - crash
//     - {function: carry, within: [0 s, 2 s]}
//   error: "bad.yaml:12:13: expected"   instead of expect/reject: loading the
//                                    files must fail with a message (it
//                                    starts with file:line:col) containing
//                                    this text
//
// Windows include both ends. A case file holds one case. Every mistake in a
// case is a DataError naming file:line:col (unknown keys with "did you
// mean"; a function the rules do not define, found when the case is judged).
//
// Running a case needs an agent for its script; the engine does not know
// the devices, so the caller passes a factory (cli/test.cpp and the tests
// give devices/scripted_agent.h's ScriptedAgent).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "errors.h"
#include "closest_approach.h"
#include "rules.h"
#include "sample_source.h"
#include "script.h"
#include "session.h"
#include "yaml_reader.h"

namespace afford {

// ------------------------------------------------------------ the case

struct TimeWindow {
  double from = 0;  // s
  double to = 0;    // s, >= from; both ends included
};

struct CaseExpectation {
  std::string function;
  SourceLoc loc;                     // the function's name in the case file
  std::optional<TimeWindow> within;  // none: the whole session
  int times = -1;                    // exact count (in the window); -1: at least once
};

struct CaseRejection {
  std::string function;
  SourceLoc loc;
  std::optional<TimeWindow> within;
};

struct RuleCase {
  std::string file;  // the case file as named
  std::string name;  // `test:`
  std::string note;
  SourceLoc loc;     // the `test:` value
  // `session:`: a path (a scalar) or the session's keys (a mapping); always
  // set by read_rule_case.
  std::optional<Node> session;
  SourceLoc session_key;      // the key `session` itself (a missing file is reported there)
  std::optional<Node> rules;  // `rules:` (a path), if the case overrides the session's
  SourceLoc rules_key;
  std::vector<CaseExpectation> expect;
  std::vector<CaseRejection> reject;
  std::optional<std::string> error;  // `error:`: the files must fail to load with this text
};

// Reads a case. Throws DataError at the wrong value: an unknown key (with
// "did you mean"), a missing `test` or `session`, a window that is not two
// times in order, a negative `times`, `error` together with expect/reject,
// a case with nothing to check. The session is not loaded yet.
RuleCase read_rule_case(const Node& root);
const MapSchema& rule_test_schema();  // the keys of a rule test case
RuleCase load_rule_case(const std::string& path);

// Loads the case's session (a file, or the keys in place) and its function
// models (the override, if any). Throws the files' DataError; a session or
// rules file that is missing is reported at the case's key that names it.
CompiledSession compile_rule_case(const RuleCase& c);

// Lets validate_file (afford check, afford.check) read rule tests: a case's
// keys, and the session and rules it names (not for a case whose point is
// that they fail to load, `error:`).
void add_rule_test_file_kind();

// ------------------------------------------------------------ a run

struct CaseRun {
  std::vector<Inference> inferences;       // in order
  std::vector<FunctionProgress> progress;  // one per function of the rules
  RulesCoverage coverage;
  double end_time = 0;  // s
};

using AgentFactory = std::function<std::unique_ptr<SampleSource>(const Script&)>;

// Runs the session (run_session) with an observer that records each
// function's progress and the nodes reached.
CaseRun run_case_session(const CompiledSession& session, const AgentFactory& agent);

// Judges a run against the case's expect and reject: one reason per unmet
// entry ("expected pinch within [0.5 s, 1 s], got pinch at 1.181 s (...)"),
// none when the case passes. A function the rules do not define is a
// reason too, as a DataError's text at the name (with "did you mean").
std::vector<std::string> judge_rule_case(const RuleCase& c, const CaseRun& run);

// ------------------------------------------------------------ the whole

struct RuleCaseResult {
  std::string file;  // as named
  std::string name;  // the case's name (the file's stem if the case did not load)
  bool passed = false;
  std::vector<std::string> failures;  // why not; empty when passed
  std::optional<RulesCoverage> coverage;  // of the run (none: the session did not run)
  double simulated = 0;  // s of simulated time

  std::string reason() const;  // the failures joined with "; "
};

// Loads, runs and judges the case in `path`. Never throws a DataError: a
// case that does not load, files that fail (or do not fail) to load, and
// unmet expectations are all failures with their reason.
RuleCaseResult run_rule_case(const std::string& path, const AgentFactory& agent);
RuleCaseResult run_rule_case(const RuleCase& c, const AgentFactory& agent);

// Adds a run's coverage to a total: files by their path, functions by
// name, nodes by index; a node counts as reached when any run reached it.
void merge_coverage(std::vector<RulesCoverage>* total, const RulesCoverage& run);

}  // namespace afford
