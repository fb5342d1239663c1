// Holding against weight: the jaws hold an actee only when their friction,
// 2 * mu * F_acr over two contacts, carries m * g. Numbers worked by hand.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "load.h"
#include "rig.h"
#include "rule_tests.h"
#include "scripted_agent.h"
#include "stages.h"
#include "terms.h"

namespace afford::test {
namespace {

// The shipped egg: 58 g, mu = 0.35 on the jaws.
Model egg_model() {
  const ActeeSpec egg = load_actee(AFFORD_SOURCE_DIR "/actees/egg.yaml");
  EXPECT_DOUBLE_EQ(egg.friction, 0.35);
  Model m;
  m.has_actee = true;
  m.actee_mass = egg.mass;
  m.actee_friction = egg.friction;
  m.actee_limit = egg.limit;
  return m;
}

TEST(HeldByFriction, EggNeedsWeightOverTwiceMuAtTheJaws) {
  // m g = 0.058 kg * 9.80665 m/s^2 = 0.5687857 N; m g / (2 mu) = 0.5687857 / 0.7 = 0.8125510 N.
  EXPECT_NEAR(grip_margin(0.35, 0.35, 0.058, 0), -0.5687857, 1e-7);
  EXPECT_LT(grip_margin(0.35, 0.35, 0.058, 0.8125), 0);  // 0.56875 N of grip: 36 uN short
  EXPECT_NEAR(grip_margin(0.35, 0.35, 0.058, 0.8125), -3.57e-5, 1e-7);
  EXPECT_GT(grip_margin(0.35, 0.35, 0.058, 0.8126), 0);
  EXPECT_NEAR(grip_margin(0.35, 0.35, 0.058, 1.0), 0.7 - 0.5687857, 1e-7);  // 0.1312143 N to spare
  EXPECT_NEAR(grip_margin(0.35, 0.35, 0.058, 0.018), 2 * 0.35 * 0.018 - 0.5687857, 1e-9);  // issue 26: 0.018 N holds nothing
}

TEST(HeldByFriction, HeldOnlyWhenFrictionCarriesTheWeight) {
  // The stage itself, the jaws blocked on the egg with a force just below
  // and just above 0.8125510 N.
  const Model m = egg_model();
  State s;
  s.blocked = true;
  s.actee_force = 0.8125;
  update_actee(m, s);
  EXPECT_EQ(s.condition, ActeeCondition::squeezed);
  EXPECT_FALSE(s.held);
  EXPECT_LT(s.grip_margin, 0);
  s.actee_force = 0.8126;
  update_actee(m, s);
  EXPECT_TRUE(s.held);
  EXPECT_NEAR(s.grip_margin, 2 * 0.35 * 0.8126 - 0.5687857, 1e-7);
  s.actee_force = 0.5;  // the grip eases: it slips
  update_actee(m, s);
  EXPECT_FALSE(s.held);
}

// Closes the rig's jaws on its 5 g test nut in small steps: every frame
// with the jaws on it is held exactly when their friction, `mu_sum` times
// the force, carries its weight (held from m g / mu_sum), with that margin.
void expect_held_from(Rig& rig, double mu_sum) {
  rig.close_to(rig.state().contact_angle);
  const double weight = 0.005 * 9.80665, needed = weight / mu_sum;  // N
  bool seen_slipping = false, seen_held = false;
  for (int i = 0; i < 4000 && !seen_held; ++i) {
    rig.push(1e-7, 1e-7);
    const State& s = rig.state();
    if (!s.blocked || s.actee_force <= 0) continue;
    EXPECT_EQ(s.held, s.actee_force >= needed) << "F = " << s.actee_force;
    EXPECT_NEAR(s.grip_margin, mu_sum * s.actee_force - weight, 1e-12);
    seen_slipping = seen_slipping || !s.held;
    seen_held = seen_held || s.held;
  }
  EXPECT_TRUE(seen_slipping);
  EXPECT_TRUE(seen_held);
}

TEST(HeldByFriction, SqueezingTheNutHoldsItFromTheForceFrictionNeeds) {
  // The test nut: 5 g, mu = 0.4, so held from m g / (2 mu) = 0.04903325 N / 0.8
  // = 0.06129156 N at the jaws. Closing in small steps, every frame with the
  // jaws on it is held exactly when the force reaches that.
  const std::string nut = nut_yaml();
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, &nut, tool.load);
  Rig rig(m, tool.effort);
  expect_held_from(rig, 2 * 0.4);  // gripped below 0.0613 N: pressed, not held
}

TEST(HeldByFriction, ARubberJawCarriesMoreThanTheActeesOwnFriction) {
  // The moving jaw tipped with rubber (mu = 1.0), the fixed jaw bare (the
  // nut's 0.4): held from m g / (0.4 + 1.0) = 0.04903325 N / 1.4 = 0.03502375 N.
  std::string tool = tools_of_every_pattern()[0].yaml;
  const std::string jaw = "  - name: moving_jaw\n    arm: moving\n";
  const size_t at = tool.find(jaw);
  ASSERT_NE(at, std::string::npos);
  const size_t end = tool.find("\n", tool.find("position:", at)) + 1;
  tool.insert(end, "    friction: {coefficient: 1.0, source: a rubber tip}\n");
  EXPECT_DOUBLE_EQ(object_from(tool).parts[1].friction, 1.0);
  const std::string nut = nut_yaml();
  const Model m = model_of(tool, &nut, tools_of_every_pattern()[0].load);
  Rig rig(m, tools_of_every_pattern()[0].effort);
  expect_held_from(rig, 0.4 + 1.0);
}

TEST(HeldByFriction, AFrictionOutOfRangeIsAnErrorAtItsValue) {
  std::string nut = nut_yaml();
  nut.replace(nut.find("coefficient: 0.4"), 16, "coefficient: 0");
  try {
    (void)actee_from(nut);
    FAIL() << "no error";
  } catch (const DataError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("actee.yaml:9:25: expected a coefficient above 0 and at most 3, found '0'"));
  }
}

const AgentFactory kScripted = [](const Script& script) -> std::unique_ptr<SampleSource> {
  return std::make_unique<ScriptedAgent>(script);
};

TEST(HeldByFriction, HoldsExplanationGivesTheGripMargin) {
  // paper-tongs: the egg held with 19.0 N at the jaws when hold is inferred:
  // 2 * 0.35 * 19.0 N - 0.569 N = 12.73 N to spare.
  const CaseRun run = run_case_session(load_session(AFFORD_SOURCE_DIR "/sessions/paper-tongs.yaml"), kScripted);
  const Inference* hold = nullptr;
  for (const Inference& inf : run.inferences) {
    if (inf.function == "hold" && hold == nullptr) hold = &inf;
  }
  ASSERT_NE(hold, nullptr);
  ASSERT_EQ(hold->node_details.size(), hold->nodes.size());
  EXPECT_EQ(hold->node_details[0], "");  // grasping(agent, object): nothing to add
  EXPECT_THAT(hold->nodes[1].text, ::testing::HasSubstr("load(actee) = 19 N"));
  EXPECT_EQ(hold->node_details[1], "grip_margin(actee) = 12.73 N");
}

TEST(HeldByFriction, AGripThatSlipsSaysByHowMuch) {
  // The greased egg (mu = 0.01) is never held: hold's closest approach is
  // its firmest grip, 17.39 N at 1.5 s, and the grip margin there,
  // 2 * 0.01 * 17.39 N - 0.5688 N = -0.2210 N.
  const CaseRun run = run_case_session(
      compile_rule_case(load_rule_case(AFFORD_SOURCE_DIR "/tests/rules/tongs-greased-egg-slips.yaml")), kScripted);
  for (const FunctionProgress& p : run.progress) {
    if (p.function != "hold") continue;
    EXPECT_EQ(p.furthest, 1);
    EXPECT_THAT(p.stopped_at, ::testing::HasSubstr("closest at 1.500 s: held(actee) = false and load(actee) = 17.39 N"));
    EXPECT_THAT(p.stopped_at, ::testing::HasSubstr("; grip_margin(actee) = -0.2209 N"));
  }
}

}  // namespace
}  // namespace afford::test
