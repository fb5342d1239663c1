// Rule test cases as data (engine/session/rule_tests.h): the case loader's errors
// (file:line:col, "did you mean"), judging a run against expect and reject
// (windows, exact counts, the reasons), loading a case's session (a file or
// in place, a rules override) and running one end to end.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "rule_tests.h"
#include "scripted_agent.h"
#include "test_util.h"

namespace afford::test {
namespace {

using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::StartsWith;

// Case documents are named as if they sat in tests/rules/, so that their
// relative paths reach the shipped files.
const std::string kCaseFile = kSource + "/tests/rules/case.yaml";

std::string at(int line, int column) { return "case.yaml:" + std::to_string(line) + ":" + std::to_string(column) + ": "; }

RuleCase case_from(const std::string& yaml) { return read_rule_case(load_yaml_string(yaml, kCaseFile)); }

// The DataError's text: from reading the case, or else from loading its files.
std::string case_error(const std::string& yaml) {
  try {
    const RuleCase c = case_from(yaml);
    compile_rule_case(c);
  } catch (const DataError& e) {
    const std::string what = e.what();
    const size_t slash = what.rfind('/', what.find(".yaml:"));
    return slash == std::string::npos ? what : what.substr(slash + 1);  // "case.yaml:3:1: ..."
  }
  ADD_FAILURE() << "no DataError for:\n" << yaml;
  return "";
}

const AgentFactory kAgent = [](const Script& script) -> std::unique_ptr<SampleSource> {
  return std::make_unique<ScriptedAgent>(script);
};

// A case on the shipped paper-nutcracker session. Line numbers in the comments.
const std::string kCase =
    "test: a-case\n"                                          // 1
    "note: one line\n"                                        // 2
    "session: ../../sessions/paper-nutcracker.yaml\n"         // 3
    "expect:\n"                                               // 4
    "  - pinch\n"                                             // 5
    "  - {function: hold, within: [1 s, 1.2 s], times: 1}\n"  // 6
    "reject:\n"                                               // 7
    "  - carry\n";                                            // 8

// kCase with line `line` (1-based) replaced.
std::string with_line(int line, const std::string& text) {
  std::istringstream in(kCase);
  std::string out;
  int n = 0;
  for (std::string l; std::getline(in, l);) out += (++n == line ? text : l) + "\n";
  return out;
}

// ------------------------------------------------------------ reading

TEST(RuleCaseRead, ReadsEveryKey) {
  const RuleCase c = case_from(kCase);
  EXPECT_EQ(c.name, "a-case");
  EXPECT_EQ(c.note, "one line");
  ASSERT_TRUE(c.session.has_value());
  EXPECT_TRUE(c.session->is_scalar());
  ASSERT_EQ(c.expect.size(), 2u);
  EXPECT_EQ(c.expect[0].function, "pinch");
  EXPECT_FALSE(c.expect[0].within.has_value());
  EXPECT_EQ(c.expect[0].times, -1);
  EXPECT_EQ(c.expect[0].loc.line, 5);
  EXPECT_EQ(c.expect[0].loc.column, 5);
  EXPECT_EQ(c.expect[1].function, "hold");
  ASSERT_TRUE(c.expect[1].within.has_value());
  EXPECT_DOUBLE_EQ(c.expect[1].within->from, 1.0);
  EXPECT_DOUBLE_EQ(c.expect[1].within->to, 1.2);
  EXPECT_EQ(c.expect[1].times, 1);
  ASSERT_EQ(c.reject.size(), 1u);
  EXPECT_EQ(c.reject[0].function, "carry");
  EXPECT_FALSE(c.error.has_value());
}

TEST(RuleCaseRead, UnknownKeyWithDidYouMean) {
  EXPECT_EQ(case_error(with_line(7, "rejcet:")),
            at(7, 1) + "expected one of the keys of a rule test case (test, note, session, rules, expect, reject, "
                       "error), found 'rejcet' (did you mean 'reject'?)");
}

TEST(RuleCaseRead, UnknownKeyInAnEntry) {
  EXPECT_EQ(case_error(with_line(6, "  - {fucntion: hold}")),
            at(6, 6) + "expected one of the keys of an expected function (function, within, times), found "
                       "'fucntion' (did you mean 'function'?)");
  EXPECT_EQ(case_error(with_line(8, "  - {function: carry, times: 1}")),
            at(8, 23) + "expected one of the keys of a rejected function (function, within), found 'times'");
}

TEST(RuleCaseRead, FirstKeyNamesACase) {
  EXPECT_EQ(case_error("session: x.yaml\ntest: a\nexpect: [pinch]\n"),
            at(1, 1) + "expected a rule test case (its first key 'test'), found 'session'");
}

TEST(RuleCaseRead, MissingSession) {
  EXPECT_EQ(case_error("test: a\nexpect: [pinch]\n"),
            at(1, 1) + "expected key 'session' in a rule test case, found no such key");
}

TEST(RuleCaseRead, NothingToCheck) {
  EXPECT_EQ(case_error("test: a\nsession: ../../sessions/paper-nutcracker.yaml\n"),
            at(1, 1) + "expected key 'expect', 'reject' or 'error' in a rule test case, found none of them");
}

TEST(RuleCaseRead, ErrorExcludesExpectations) {
  EXPECT_EQ(case_error(kCase + "error: \"bad\"\n"),
            at(9, 1) + "expected either 'error' (the files must fail to load) or 'expect' and 'reject', found both");
  EXPECT_EQ(case_error("test: a\nsession: ../../sessions/paper-nutcracker.yaml\nerror: \"\"\n"),
            at(3, 8) + "expected a text that the error message must contain, found ''");
}

TEST(RuleCaseRead, Windows) {
  EXPECT_EQ(case_error(with_line(6, "  - {function: hold, within: [2 s, 1 s]}")),
            at(6, 36) + "expected a time not before 2 s, found '1 s'");
  EXPECT_EQ(case_error(with_line(6, "  - {function: hold, within: [1 m, 2 s]}")),
            at(6, 31) + "expected a time (e.g. '200 ms'), found '1 m', a length (e.g. '18 mm')");
  EXPECT_EQ(case_error(with_line(6, "  - {function: hold, within: [-1 s, 2 s]}")),
            at(6, 31) + "expected a time of 0 s or more, found '-1 s'");
  EXPECT_EQ(case_error(with_line(6, "  - {function: hold, within: [1 s]}")),
            at(6, 30) + "expected a window [from, to] of two times, found a sequence of 1");
}

TEST(RuleCaseRead, Times) {
  EXPECT_EQ(case_error(with_line(6, "  - {function: hold, times: -1}")),
            at(6, 29) + "expected a count of 0 or more, found '-1'");
  EXPECT_EQ(case_error(with_line(6, "  - {function: hold, times: 1.5}")),
            at(6, 29) + "expected a whole number, found '1.5'");
}

TEST(RuleCaseRead, EmptyLists) {
  EXPECT_EQ(case_error("test: a\nsession: ../../sessions/paper-nutcracker.yaml\nexpect: []\n"),
            at(3, 9) + "expected a sequence of functions expected: a name, or {function, within, times}, found a "
                       "sequence of 0");
  EXPECT_EQ(case_error("test: a\nsession: ../../sessions/paper-nutcracker.yaml\nreject: crash\n"),
            at(3, 9) + "expected a sequence of functions rejected: a name, or {function, within}, found 'crash'");
}

// ------------------------------------------------------------ the session: a file, in place, overrides

const std::string kInline =
    "test: inline\n"                                              // 1
    "session:\n"                                                  // 2
    "  object: ../../objects/nutcracker.yaml\n"                   // 3
    "  actee: {file: ../../actees/walnut.yaml, at: 60 mm}\n"      // 4
    "  agent: ../../agents/hand.yaml\n"                           // 5
    "  rules: ../../rules/functions.yaml\n"                       // 6
    "  grasps: ../../rules/grasps.yaml\n"                         // 7
    "  script:\n"                                                 // 8
    "    - t: 0 s\n"                                              // 9
    "      hand: {position: [80 mm, 40 mm, 190 mm]}\n"            // 10
    "      grip: {thumb: 160 mm, index: 160 mm, squeeze: 0 mm}\n" // 11
    "      posture: medium_wrap\n"                                // 12
    "    - t: 1.5 s\n"                                            // 13
    "      grip: {thumb: 160 mm, index: 160 mm, squeeze: 30 mm}\n"  // 14
    "expect: [pinch, hold]\n"                                     // 15
    "reject: [crash]\n";                                          // 16

std::string inline_with_line(int line, const std::string& text) {
  std::istringstream in(kInline);
  std::string out;
  int n = 0;
  for (std::string l; std::getline(in, l);) out += (++n == line ? text : l) + "\n";
  return out;
}

TEST(RuleCaseSession, InPlaceTakesTheCasesNameAndNote) {
  const CompiledSession s = compile_rule_case(case_from(kInline));
  EXPECT_EQ(s.name, "inline");
  EXPECT_EQ(s.description, "inline");
  EXPECT_EQ(s.script.keyframes.size(), 2u);
  EXPECT_EQ(function_count(*s.rules), 4);
}

TEST(RuleCaseSession, InPlaceUnknownKey) {
  EXPECT_EQ(case_error(inline_with_line(8, "  scirpt:")),
            at(8, 3) + "expected one of the keys of the session in place (session, description, object, actee, actees, "
                       "agent, rules, grasps, timestep, contact_tolerance, script), found 'scirpt' (did you mean "
                       "'script'?)");
}

TEST(RuleCaseSession, InPlaceMissingKey) {
  EXPECT_EQ(case_error(inline_with_line(7, "  timestep: 1 ms")),
            at(3, 3) + "expected key 'grasps' in the session in place, found no such key");
  EXPECT_EQ(case_error(inline_with_line(6, "  timestep: 1 ms")),
            at(3, 3) + "expected key 'rules' in the session in place (or in the case), found no such key");
}

TEST(RuleCaseSession, InPlaceMistakesNameTheCaseFile) {
  // Found by read_session and the script compiler, at their place in the case.
  EXPECT_EQ(case_error(inline_with_line(12, "      posture: medium_wrp")),
            at(12, 16) + "expected a grasp type of the taxonomy (small_wrap, medium_wrap, power_sphere, "
                         "lateral_pinch, tip_pinch, tripod), found 'medium_wrp' (did you mean 'medium_wrap'?)");
  EXPECT_THAT(case_error(inline_with_line(5, "  agent: ../../agents/nobody.yaml")),
              StartsWith(at(5, 3) + "expected a readable file '../../agents/nobody.yaml'"));
}

TEST(RuleCaseSession, MissingFilesAreReportedAtTheCasesKey) {
  EXPECT_EQ(case_error(with_line(3, "session: ../../sessions/nowhere.yaml")),
            at(3, 1) + "expected a readable file '../../sessions/nowhere.yaml' (relative to the case's folder), "
                       "found none");
  EXPECT_EQ(case_error(kCase + "rules: ../data/rules/nowhere.yaml\n"),
            at(9, 1) + "expected a readable file '../data/rules/nowhere.yaml' (relative to the case's folder), "
                       "found none");
}

TEST(RuleCaseSession, RulesOverride) {
  const CompiledSession s = compile_rule_case(case_from(kCase + "rules: ../data/rules/hold-1s.yaml\n"));
  ASSERT_EQ(function_count(*s.rules), 1);
  EXPECT_EQ(function_name(*s.rules, 0), "hold");
  // In place, the case's rules stand in for a session that names none.
  const CompiledSession t =
      compile_rule_case(case_from(inline_with_line(6, "  timestep: 1 ms") + "rules: ../data/rules/hold-1s.yaml\n"));
  EXPECT_EQ(function_count(*t.rules), 1);
}

TEST(RuleCaseSession, BrokenRulesFileNamesItsToken) {
  EXPECT_THAT(case_error(kCase + "rules: ../data/rules/bad-signal.yaml\n"),
              StartsWith("bad-signal.yaml:16:15: expected a signal of the vocabulary (afford rules --list), found "
                         "'griping' (did you mean 'gripping'?)"));
}

// ------------------------------------------------------------ judging

// A run of two functions: pinch (3 nodes) inferred at the given times,
// crash (5 nodes) never, stopped before its fourth node.
CaseRun fake_run(const std::vector<double>& pinch_times) {
  CaseRun run;
  for (double t : pinch_times) {
    Inference inf;
    inf.function = "pinch";
    inf.t = t;
    inf.nodes = {{"grasping(agent, object)", t - 0.5}, {"gripping(object, actee)", t - 0.1},
                 {"force(object, actee) = 2 N > 0 N", t}};
    run.inferences.push_back(inf);
  }
  FunctionProgress pinch;
  pinch.function = "pinch";
  pinch.nodes = 3;
  pinch.furthest = 3;
  FunctionProgress crash;
  crash.function = "crash";
  crash.nodes = 5;
  crash.furthest = 3;
  crash.furthest_t = 0.412;
  crash.stopped_at = "'load(actee) > limit(actee)' (functions.yaml:37:15): never true; closest at 2.000 s: "
                     "load(actee) = 300 N > limit(actee) = 378 N";
  run.progress = {pinch, crash};
  run.coverage.file = "functions.yaml";
  return run;
}

std::vector<std::string> judge(const std::string& expectations, const CaseRun& run) {
  return judge_rule_case(case_from("test: j\nsession: x.yaml\n" + expectations), run);
}

TEST(RuleCaseJudge, AtLeastOnce) {
  EXPECT_THAT(judge("expect: [pinch]\n", fake_run({1.0})), IsEmpty());
  EXPECT_THAT(judge("expect: [pinch]\n", fake_run({1.0, 2.0})), IsEmpty());
}

TEST(RuleCaseJudge, WindowIncludesItsEnds) {
  EXPECT_THAT(judge("expect: [{function: pinch, within: [1 s, 2 s]}]\n", fake_run({1.0})), IsEmpty());
  EXPECT_THAT(judge("expect: [{function: pinch, within: [0 s, 1 s]}]\n", fake_run({1.0})), IsEmpty());
  EXPECT_THAT(judge("expect: [{function: pinch, within: [0.5 s, 1.5 s]}]\n", fake_run({0.2, 1.0, 3.0})), IsEmpty());
}

TEST(RuleCaseJudge, OutsideTheWindow) {
  EXPECT_THAT(judge("expect: [{function: pinch, within: [0 s, 0.9 s]}]\n", fake_run({1.0})),
              ::testing::ElementsAre(
                  "expected pinch within [0 s, 0.9 s], got pinch at 1.000 s because grasping(agent, object) at "
                  "0.500 s, gripping(object, actee) at 0.900 s, force(object, actee) = 2 N > 0 N at 1.000 s"));
  // With several, the explanation is of the one nearest the window.
  const std::vector<std::string> f = judge("expect: [{function: pinch, within: [2 s, 2.5 s]}]\n", fake_run({1.0, 3.0}));
  ASSERT_EQ(f.size(), 1u);
  EXPECT_THAT(f[0], StartsWith("expected pinch within [2 s, 2.5 s], got pinch at 1.000 s, 3.000 s; nearest at "
                               "3.000 s because grasping(agent, object) at 2.500 s"));
}

TEST(RuleCaseJudge, Times) {
  EXPECT_THAT(judge("expect: [{function: pinch, times: 2}]\n", fake_run({1.0, 2.0})), IsEmpty());
  EXPECT_THAT(judge("expect: [{function: pinch, times: 1}]\n", fake_run({1.0, 2.0})),
              ::testing::ElementsAre(StartsWith("expected pinch once, got it twice: pinch at 1.000 s, 2.000 s;")));
  // Counted in the window only.
  EXPECT_THAT(judge("expect: [{function: pinch, within: [1.5 s, 3 s], times: 1}]\n", fake_run({1.0, 2.0})), IsEmpty());
  EXPECT_THAT(judge("expect: [{function: pinch, within: [3 s, 4 s], times: 1}]\n", fake_run({1.0, 2.0})),
              ::testing::ElementsAre(StartsWith("expected pinch once within [3 s, 4 s], got it no time there: pinch at")));
  EXPECT_THAT(judge("expect: [{function: pinch, times: 0}]\n", fake_run({})), IsEmpty());
  EXPECT_THAT(judge("expect: [{function: pinch, times: 0}]\n", fake_run({1.0})),
              ::testing::ElementsAre(StartsWith("expected pinch 0 times, got it once: pinch at 1.000 s")));
}

TEST(RuleCaseJudge, NeverInferredSaysHowFarItsTraceGot) {
  EXPECT_THAT(judge("expect: [crash]\n", fake_run({1.0})),
              ::testing::ElementsAre(
                  "expected crash, got none: its trace reached 3 of its 5 nodes (by 0.412 s), then stopped at "
                  "'load(actee) > limit(actee)' (functions.yaml:37:15): never true; closest at 2.000 s: "
                  "load(actee) = 300 N > limit(actee) = 378 N"));
}

TEST(RuleCaseJudge, Reject) {
  EXPECT_THAT(judge("reject: [crash]\n", fake_run({1.0})), IsEmpty());
  EXPECT_THAT(judge("reject: [pinch]\n", fake_run({1.0, 2.0})),
              ::testing::ElementsAre(StartsWith("expected no pinch, got pinch at 1.000 s, 2.000 s because "
                                                "grasping(agent, object) at 0.500 s")));
  EXPECT_THAT(judge("reject: [{function: pinch, within: [1.1 s, 1.9 s]}]\n", fake_run({1.0, 2.0})), IsEmpty());
  EXPECT_THAT(judge("reject: [{function: pinch, within: [1.5 s, 3 s]}]\n", fake_run({1.0, 2.0})),
              ::testing::ElementsAre(StartsWith("expected no pinch within [1.5 s, 3 s], got pinch at 2.000 s because")));
}

TEST(RuleCaseJudge, UnknownFunctionWithDidYouMean) {
  EXPECT_THAT(judge("expect:\n  - pnich\n", fake_run({1.0})),
              ::testing::ElementsAre(HasSubstr("case.yaml:4:5: expected a function of functions.yaml (pinch, crash), "
                                               "found 'pnich' (did you mean 'pinch'?)")));
  EXPECT_THAT(judge("reject: [{function: crahs}]\n", fake_run({1.0})),
              ::testing::ElementsAre(HasSubstr("case.yaml:3:21: expected a function of functions.yaml (pinch, "
                                               "crash), found 'crahs' (did you mean 'crash'?)")));
}

TEST(RuleCaseJudge, EveryUnmetEntryIsAReason) {
  EXPECT_EQ(judge("expect: [crash, {function: pinch, times: 3}]\nreject: [pinch]\n", fake_run({1.0})).size(), 3u);
}

// ------------------------------------------------------------ end to end

TEST(RuleCaseRun, PassesAndCoversTheNodesItReached) {
  const RuleCaseResult r = run_rule_case(case_from(kInline), kAgent);
  EXPECT_TRUE(r.passed) << r.reason();
  EXPECT_EQ(r.name, "inline");
  EXPECT_DOUBLE_EQ(r.simulated, 1.5);
  ASSERT_TRUE(r.coverage.has_value());
  ASSERT_EQ(r.coverage->functions.size(), 4u);  // in file order
  EXPECT_EQ(r.coverage->functions[0].name, "pinch");
  EXPECT_EQ(r.coverage->functions[3].name, "crash");
  for (const NodeCoverage& n : r.coverage->functions[0].nodes) EXPECT_TRUE(n.reached) << n.text;
  EXPECT_FALSE(r.coverage->functions[2].nodes.back().reached);  // carry: the hand never moves
}

TEST(RuleCaseRun, FailureNamesWhatWasExpectedAndWhatCame) {
  const RuleCaseResult r = run_rule_case(case_from(inline_with_line(16, "reject: [pinch]")), kAgent);
  EXPECT_FALSE(r.passed);
  EXPECT_THAT(r.reason(), StartsWith("expected no pinch, got pinch at "));
}

TEST(RuleCaseRun, ExpectedErrors) {
  const std::string broken = "test: e\nsession: ../../sessions/paper-nutcracker.yaml\nrules: ../data/rules/unit-mismatch.yaml\n";
  EXPECT_TRUE(run_rule_case(case_from(broken + "error: \"unit-mismatch.yaml:17:38: expected a force\"\n"), kAgent).passed);
  const RuleCaseResult other = run_rule_case(case_from(broken + "error: \"unit-mismatch.yaml:1:1\"\n"), kAgent);
  EXPECT_FALSE(other.passed);
  EXPECT_THAT(other.reason(), StartsWith("expected the files to fail to load with \"unit-mismatch.yaml:1:1\", got: "));
  const RuleCaseResult loads =
      run_rule_case(case_from("test: e\nsession: ../../sessions/paper-nutcracker.yaml\nerror: \"expected\"\n"), kAgent);
  EXPECT_EQ(loads.reason(), "expected the files to fail to load with \"expected\", but they loaded");
  const RuleCaseResult unexpected = run_rule_case(case_from(broken + "expect: [pinch]\n"), kAgent);
  EXPECT_THAT(unexpected.reason(), StartsWith("the files did not load: "));
  EXPECT_THAT(unexpected.reason(), HasSubstr("unit-mismatch.yaml:17:38: "));
}

TEST(RuleCaseRun, ACaseThatDoesNotLoadIsAFailure) {
  const RuleCaseResult r = run_rule_case(kSource + "/tests/data/rule_cases_failing/misspelt-key.yaml", kAgent);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.name, "misspelt-key");
  EXPECT_THAT(r.reason(), HasSubstr("misspelt-key.yaml:4:1: expected one of the keys of a rule test case"));
  EXPECT_FALSE(r.coverage.has_value());
}

TEST(RuleCaseCoverage, MergeReachedByAnyRun) {
  RulesCoverage a{"rules/functions.yaml", {{"pinch", {{"x", {}, true}, {"y", {}, false}}}}};
  RulesCoverage b{"rules/../rules/functions.yaml", {{"pinch", {{"x", {}, false}, {"y", {}, true}}}, {"hold", {{"z", {}, false}}}}};
  RulesCoverage c{"other.yaml", {{"pinch", {{"x", {}, false}}}}};
  std::vector<RulesCoverage> total;
  merge_coverage(&total, a);
  merge_coverage(&total, b);
  merge_coverage(&total, c);
  ASSERT_EQ(total.size(), 2u);
  EXPECT_EQ(total[0].file, "rules/functions.yaml");
  ASSERT_EQ(total[0].functions.size(), 2u);
  EXPECT_TRUE(total[0].functions[0].nodes[0].reached);
  EXPECT_TRUE(total[0].functions[0].nodes[1].reached);
  EXPECT_FALSE(total[0].functions[1].nodes[0].reached);
  EXPECT_FALSE(total[1].functions[0].nodes[0].reached);
}

}  // namespace
}  // namespace afford::test
