// The rule engine: the predicate language (parsing, units, names), the flat
// program (shared sub-expressions), tracing function models (order,
// durations, fallback, requirements, repeated inferences), explanations.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "rig.h"
#include "rules.h"
#include "rules_impl.h"

namespace afford::test {
namespace {

using ::testing::HasSubstr;

std::string rules_error(const std::string& yaml) {
  try {
    read_rules(yaml, "rules.yaml");
  } catch (const DataError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no DataError for:\n" << yaml;
  return "";
}

// One function `f` with the given nodes ("when" texts), for error tests.
std::string one_function(const std::string& when) {
  return "functions:\n  - name: f\n    description: test\n    nodes:\n      - when: " + when + "\n";
}
// Column where the `when` text starts in one_function's line 5.
constexpr int kWhenColumn = 15;

std::string at(int column) { return "rules.yaml:5:" + std::to_string(column) + ":"; }

TEST(RuleLanguage, UnknownSignalSaysDidYouMean) {
  const std::string e = rules_error(one_function("grasp(agent, object)"));
  EXPECT_THAT(e, HasSubstr(at(kWhenColumn)));
  EXPECT_THAT(e, HasSubstr("found 'grasp' (did you mean 'grasping'?)"));
}

TEST(RuleLanguage, UnknownEntitySaysDidYouMean) {
  const std::string e = rules_error(one_function("grasping(agent, objcet)"));
  EXPECT_THAT(e, HasSubstr("found 'objcet' (did you mean 'object'?)"));
}

TEST(RuleLanguage, WrongArgumentsListTheForms) {
  const std::string e = rules_error(one_function("force(agent, actee) > 3 N"));
  EXPECT_THAT(e, HasSubstr(at(kWhenColumn)));
  EXPECT_THAT(e, HasSubstr("expected one of force(agent, object), force(object, actee), found 'force(agent, actee)'"));
}

TEST(RuleLanguage, UnitsAreCheckedAtTheOffendingToken) {
  const std::string e = rules_error(one_function("force(object, actee) > 5 cm"));
  EXPECT_THAT(e, HasSubstr(at(kWhenColumn + 23)));
  EXPECT_THAT(e, HasSubstr("expected a force (e.g. '30 N') to go with 'force(object, actee)', found '5 cm'"));
}

TEST(RuleLanguage, ABareNumberIsNotAForce) {
  const std::string e = rules_error(one_function("force(object, actee) > 0"));
  EXPECT_THAT(e, HasSubstr("found '0', a plain number"));
}

TEST(RuleLanguage, CountsCompareWithPlainNumbers) {
  EXPECT_NO_THROW(read_rules(one_function("contacts(object, actee) >= 2"), "rules.yaml"));
}

TEST(RuleLanguage, UnitsCombine) {
  EXPECT_NO_THROW(read_rules(one_function("force(agent, object) * 0.15 m > 2 N*m"), "rules.yaml"));
  EXPECT_NO_THROW(read_rules(one_function("moved(actee) / time > 1 cm/s"), "rules.yaml"));
  EXPECT_NO_THROW(read_rules(one_function("actee.limit - load(actee) < 30 N"), "rules.yaml"));
  const std::string e = rules_error(one_function("force(agent, object) + angle(object) > 1 N"));
  EXPECT_THAT(e, HasSubstr("found 'angle(object)', an angle"));
}

TEST(RuleLanguage, TheWholeNodeMustBeACondition) {
  const std::string e = rules_error(one_function("force(object, actee)"));
  EXPECT_THAT(e, HasSubstr(at(kWhenColumn)));
  EXPECT_THAT(e, HasSubstr("expected a condition"));
}

TEST(RuleLanguage, LogicNeedsConditions) {
  const std::string e = rules_error(one_function("grasping(agent, object) and load(actee)"));
  EXPECT_THAT(e, HasSubstr(at(kWhenColumn + 28)));
  EXPECT_THAT(e, HasSubstr("expected a condition after 'and', found 'load(actee)'"));
}

TEST(RuleLanguage, SyntaxErrorsNameTheToken) {
  EXPECT_THAT(rules_error(one_function("(held(actee)")), HasSubstr(at(kWhenColumn + 12)));
  EXPECT_THAT(rules_error(one_function("(held(actee)")), HasSubstr("expected ')', found the end of the expression"));
  EXPECT_THAT(rules_error(one_function("load(actee) = 3 N")), HasSubstr("expected '==' to compare, found '='"));
  EXPECT_THAT(rules_error(one_function("held(actee) held(actee)")), HasSubstr(at(kWhenColumn + 12)));
  EXPECT_THAT(rules_error(one_function("load(actee) > 3 furlongs")),
              HasSubstr("expected an operator or the end of the expression, found 'furlongs'"));
  EXPECT_THAT(rules_error(one_function("1 N < load(actee) < 3 N")), HasSubstr("expected 'and' between two comparisons"));
}

TEST(RuleLanguage, QuotedTextCountsItsQuote) {
  const std::string e = rules_error(one_function("\"held(actee) and objcet.angle > 1 deg\""));
  EXPECT_THAT(e, HasSubstr(at(kWhenColumn + 1 + 16)));
}

TEST(RuleFile, SchemaErrors) {
  EXPECT_THAT(rules_error("functions:\n  - name: f\n    description: d\n    nodes:\n      - wehn: held(actee)\n"),
              HasSubstr("rules.yaml:5:9: expected one of the keys of a condition node (when, for), found 'wehn' "
                        "(did you mean 'when'?)"));
  EXPECT_THAT(rules_error("functions:\n  - name: f\n    description: d\n    requires: [g]\n    nodes:\n      - when: held(actee)\n"),
              HasSubstr("rules.yaml:4:16: expected the name of a function in this file, found 'g'"));
  EXPECT_THAT(rules_error("functions:\n  - name: f\n    description: d\n    nodes:\n      - {when: held(actee), for: 3 N}\n"),
              HasSubstr("rules.yaml:5:34: expected a time"));
  EXPECT_THAT(rules_error("functions:\n  - name: f\n    description: d\n    nodes: []\n  - name: f\n    description: d\n    nodes: []\n"),
              HasSubstr("rules.yaml:5:11: expected a function name used once, found 'f' again"));
}

TEST(RuleFile, CircularRequirementsAreAnError) {
  const std::string yaml =
      "functions:\n"
      "  - {name: a, description: d, requires: [b], nodes: [{when: held(actee)}]}\n"
      "  - {name: b, description: d, requires: [a], nodes: [{when: held(actee)}]}\n";
  EXPECT_THAT(rules_error(yaml), HasSubstr("rules.yaml:2:5: expected functions that do not require each other in a "
                                           "circle, found a requires b requires a"));
}

TEST(RuleProgram, ASubExpressionSharedByFunctionsHasOneSlot) {
  const std::string yaml =
      "functions:\n"
      "  - {name: a, description: d, nodes: [{when: 'grasping(agent, object)'}, {when: 'force(object, actee) > 10 N'}]}\n"
      "  - {name: b, description: d, nodes: [{when: 'grasping(agent, object)'},\n"
      "      {when: 'force(object, actee) > 10 N and held(actee)'}]}\n";
  const auto rules = read_rules(yaml, "rules.yaml");
  // grasping, force, 10 N, '>', held, 'and': six slots, not nine.
  EXPECT_EQ(rules->program.size(), 6u);
  int force_reads = 0;
  for (const Instr& in : rules->program) force_reads += in.op == Op::signal && std::string(in.signal->name) == "force";
  EXPECT_EQ(force_reads, 1);
}

TEST(RuleProgram, ShippedFunctionsLoadInRequirementOrder) {
  const auto rules = load_rules(std::string(AFFORD_SOURCE_DIR) + "/rules/functions.yaml");
  std::vector<std::string> names;
  for (int f = 0; f < function_count(*rules); ++f) names.push_back(function_name(*rules, f));
  for (const char* want : {"pinch", "hold", "carry", "crash"}) EXPECT_THAT(names, ::testing::Contains(want));
  const auto at = [&](const char* n) { return std::find(names.begin(), names.end(), n) - names.begin(); };
  EXPECT_LT(at("hold"), at("carry"));
  // crash: the paper's four conditions, and the actee giving way.
  const int crash = static_cast<int>(at("crash"));
  ASSERT_EQ(node_count(*rules, crash), 5);
  EXPECT_EQ(node_text(*rules, crash, 0), "grasping(agent, object)");
  EXPECT_EQ(node_text(*rules, crash, 1), "pushing(agent, object)");
  EXPECT_EQ(node_text(*rules, crash, 2), "contacts(object, actee) >= 2");
  EXPECT_EQ(node_text(*rules, crash, 3), "load(actee) > limit(actee)");
  EXPECT_EQ(node_text(*rules, crash, 4), "broken(actee)");
}

// ---------------------------------------------------------------- tracing

class Tracing : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string nut = nut_yaml(300);
    const Tool tool = tools_of_every_pattern()[0];
    model_ = std::make_unique<Model>(model_of(tool.yaml, &nut, tool.load));
    state_ = make_state(*model_);
  }

  void use(const std::string& yaml) {
    rules_ = read_rules(yaml, "rules.yaml");
    rule_state_ = make_rule_state(*rules_);
  }

  // Advances time by dt and evaluates; returns this frame's events.
  std::vector<Event> frame(double dt = 1e-3) {
    state_->t += dt;
    evaluate(*rules_, *rule_state_, *model_, *state_);
    return {events_begin(*rule_state_), events_end(*rule_state_)};
  }

  int inferred_count() const { return static_cast<int>(inferences(*rules_, *rule_state_).size()); }

  std::unique_ptr<Model> model_;
  std::unique_ptr<State> state_;
  std::shared_ptr<const RuleSet> rules_;
  RuleStatePtr rule_state_;
};

const char* kTwoNodes =
    "functions:\n"
    "  - {name: squeeze, description: d, nodes: [{when: 'grasping(agent, object)'},\n"
    "                                             {when: 'force(object, actee) > 10 N'}]}\n";

TEST_F(Tracing, NodesAreReachedInOrder) {
  use(kTwoNodes);
  state_->actee_force = 20;  // the second node holds first
  frame();
  EXPECT_EQ(inferred_count(), 0);
  EXPECT_FALSE(node_ever_reached(*rule_state_, 0, 1));
  state_->grasped = true;
  const std::vector<Event> events = frame();
  ASSERT_EQ(events.size(), 3u);  // both nodes reached, then the inference, in one frame
  EXPECT_EQ(events[0].kind, EventKind::node_reached);
  EXPECT_EQ(events[1].node, 1);
  EXPECT_EQ(events[2].kind, EventKind::inferred);
  EXPECT_EQ(inferred_count(), 1);
}

TEST_F(Tracing, AReachedNodeThatFailsSendsTheTraceBackAndTheFunctionCanRecur) {
  use(kTwoNodes);
  state_->grasped = true;
  state_->actee_force = 20;
  frame();
  frame();
  EXPECT_EQ(inferred_count(), 1);  // inferred once while it keeps holding
  state_->actee_force = 5;
  const std::vector<Event> lost = frame();
  ASSERT_EQ(lost.size(), 1u);
  EXPECT_EQ(lost[0].kind, EventKind::node_lost);
  EXPECT_EQ(lost[0].node, 1);
  state_->actee_force = 25;
  frame();
  EXPECT_EQ(inferred_count(), 2);
}

TEST_F(Tracing, ANodeMustHoldForItsDuration) {
  use("functions:\n  - {name: hold, description: d, nodes: [{when: held(actee), for: 300 ms}]}\n");
  state_->held = true;
  for (int i = 0; i < 299; ++i) frame();
  EXPECT_EQ(inferred_count(), 0);
  state_->held = false;  // a gap restarts the clock
  frame();
  state_->held = true;
  for (int i = 0; i < 300; ++i) frame();
  EXPECT_EQ(inferred_count(), 0);
  frame();
  EXPECT_EQ(inferred_count(), 1);
}

TEST_F(Tracing, ARequiredFunctionMustBeInferredAndStayInferred) {
  use("functions:\n"
      "  - {name: carry, description: d, requires: [hold], nodes: [{when: moved(actee) > 5 cm}]}\n"
      "  - {name: hold, description: d, nodes: [{when: held(actee)}]}\n");
  state_->actee_anchor = state_->actee_pose.translation();
  state_->actee_pose.translation() += Eigen::Vector3d(0.06, 0, 0);
  frame();  // moved() is 0 when not held
  EXPECT_EQ(inferred_count(), 0);
  state_->held = true;
  frame();
  const std::vector<Inference> all = inferences(*rules_, *rule_state_);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].function, "hold");
  EXPECT_EQ(all[1].function, "carry");
  EXPECT_EQ(all[1].nodes[0].text, "hold inferred");
  state_->held = false;  // hold fails: carry falls back too
  frame();
  EXPECT_FALSE(rule_state_->trace[1].completed);
}

TEST_F(Tracing, ExplanationsGiveTheValuesThatMadeEachNodeTrue) {
  use("functions:\n"
      "  - name: crash\n    description: d\n    nodes:\n"
      "      - when: grasping(agent, object)\n"
      "      - when: load(actee) > limit(actee) and contacts(object, actee) >= 2\n");
  state_->grasped = true;
  frame(0.5);
  state_->actee_load = 312;
  state_->object_actee.count = 2;
  frame(1.02);
  const std::vector<Inference> all = inferences(*rules_, *rule_state_);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_DOUBLE_EQ(all[0].t, 1.52);
  EXPECT_EQ(all[0].nodes[0].text, "grasping(agent, object)");
  EXPECT_DOUBLE_EQ(all[0].nodes[0].t, 0.5);
  EXPECT_EQ(all[0].nodes[1].text,
            "load(actee) = 312 N > limit(actee) = 300 N and contacts(object, actee) = 2 >= 2");
  EXPECT_DOUBLE_EQ(all[0].nodes[1].t, 1.52);
  // Later values do not change what was recorded.
  state_->actee_load = 500;
  frame();
  EXPECT_EQ(inferences(*rules_, *rule_state_)[0].nodes[1].text.substr(0, 22), "load(actee) = 312 N > ");
}

TEST_F(Tracing, ATrueComparisonNeverReadsFalseAfterRounding) {
  use("functions:\n"
      "  - {name: crash, description: d, nodes: [{when: load(actee) > limit(actee)}]}\n"
      "  - {name: press, description: d, nodes: [{when: load(actee) > 300 N}]}\n");
  state_->actee_load = 300.0004;  // the limit is 300 N: four digits would print "300 N > 300 N"
  frame();
  const std::vector<Inference> all = inferences(*rules_, *rule_state_);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].nodes[0].text, "load(actee) = 300.0004 N > limit(actee) = 300 N");
  EXPECT_EQ(all[1].nodes[0].text, "load(actee) = 300.0004 N > 300 N");
}

TEST(RuleVocabulary, EverySignalIsDocumented) {
  const std::vector<SignalDoc> docs = vocabulary();
  EXPECT_GE(docs.size(), 25u);
  for (const SignalDoc& d : docs) {
    EXPECT_FALSE(d.doc.empty()) << d.signature;
    EXPECT_FALSE(d.type.empty()) << d.signature;
  }
  EXPECT_EQ(docs[0].signature, "time");
}

}  // namespace
}  // namespace afford::test
