// Keyframes by force (script.h, squeeze.h): the squeeze a grip needs for
// an effort or an actee's force, worked by hand on the rig's type 2 tool;
// a session squeezed "until the effort is 40 N" settles there; `after`,
// `hold` and `release`; and their located errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "rig.h"
#include "run.h"
#include "scripted_agent.h"
#include "session.h"
#include "squeeze.h"
#include "test_sessions.h"

namespace afford::test {
namespace {

using ::testing::HasSubstr;

// t2: spring 500 N/m at 30 mm with a 2 N preload, rest 50 deg; the hand's
// force_gain 20000 N/m (rig.h); no friction.
const std::string kTool = tool_yaml("t2", "type2", 0, 180, 50, 500, 30, 2, 110, 170, 20, 70);

TEST(SqueezeUntil, AnEffortOnTheSpringAloneWorkedByHand) {
  const Model m = model_of(kTool, nullptr, 0);
  // 1 N at 150 mm is 0.15 N*m; the spring gives (2 N + 500 N/m * 0.03 m *
  // dtheta) * 0.03 m = 0.06 + 0.45 dtheta N*m, so dtheta = 0.2 rad. The
  // thumb goes 0.15 m * 0.2 rad = 30 mm with the arm and 1 N / 20000 N/m =
  // 0.05 mm further.
  const ForcedLever lever = lever_at_start(m);
  EXPECT_NEAR(settle_under_effort(m, lever, 0.150, 1.0).theta, 50 * kDeg - 0.2, 1e-9);
  EXPECT_NEAR(squeeze_for_effort(m, lever, 0.150, 1.0), 0.03005, 1e-9);
  // Below the preload's 0.06 N*m (0.4 N at 150 mm) the arm stays at rest:
  // only the hand's own give, 0.3 N / 20000 N/m.
  EXPECT_NEAR(squeeze_for_effort(m, lever, 0.150, 0.3), 1.5e-5, 1e-12);
}

TEST(SqueezeUntil, AnActeeForceWorkedByHand) {
  const std::string nut = nut_yaml(300, 3e5);
  const Model m = model_of(kTool, &nut, 0.040);
  // The nut (radius 10 mm) on the fixed jaw's face at 40 mm: its centre at
  // (40, 10) mm. The moving jaw's face, a line through the hinge at theta,
  // touches it where 0.04 sin(theta) - 0.01 cos(theta) = 0.01: theta =
  // 2 atan(1/4) = 28.07 deg, the load's arm the tangent's length,
  // sqrt(0.04^2 + 0.01^2 - 0.01^2) = 40 mm.
  const ForcedLever lever = lever_at_start(m);
  ASSERT_TRUE(lever.actee);
  EXPECT_NEAR(lever.contact_angle, 2 * std::atan(0.25), 1e-6);
  EXPECT_NEAR(lever.load_distance, 0.040, 1e-6);
  // 20 N at 150 mm is 3 N*m. At the contact the spring is compressed by
  // 0.03 m * (50 - 28.07) deg = 0.03 * 0.38272 rad, 7.741 N with the
  // preload: 0.23223 N*m. The nut's 0.23 mm of give (F / 3e5 N/m) turns
  // the arm 0.00576 rad further: 0.0026 N*m more. The nut takes the rest:
  // (3 - 0.23223 - 0.0026) / 0.040 = 69.13 N.
  double effort = 0;
  std::string why;
  ASSERT_TRUE(effort_for_actee_force(m, lever, 0.150, 69.13, 400, &effort, &why)) << why;
  EXPECT_NEAR(effort, 20.0, 0.01);
  EXPECT_NEAR(settle_under_effort(m, lever, 0.150, 20.0).actee_force, 69.13, 0.02);
  // Past its limit, or past what the hand can push, it says why.
  EXPECT_FALSE(effort_for_actee_force(m, lever, 0.150, 350, 400, &effort, &why));
  EXPECT_THAT(why, HasSubstr("breaks at 300 N, before 350 N"));
  EXPECT_FALSE(effort_for_actee_force(m, lever, 0.150, 250, 20, &effort, &why));
  EXPECT_THAT(why, HasSubstr("the hand's most, 20 N at 150 mm from the fulcrum, gives the nut 69."));
}

// The nutcracker with a walnut at 60 mm, gripped from the start, then
// `keyframes` (test_sessions.h: from line 13).
std::string session_yaml(const std::string& keyframes) { return nutcracker_session(kWalnutAt60, keyframes); }

std::string squeeze_error(const std::string& keyframes) {
  try {
    (void)read_session(load_yaml_string(session_yaml(keyframes), kSessionName));
  } catch (const DataError& e) {
    return e.what();
  }
  return "no error";
}

// The last frame's state of a session.
struct Last : Observer {
  double effort = 0, actee = 0, t = 0;
  bool grasped = false;
  void on_frame(const Model&, const State& s, const RuleSet&, const RuleState&) override {
    effort = s.effort_force;
    actee = s.actee_force;
    grasped = s.grasped;
    t = s.t;
  }
};

Last run(const std::string& keyframes) {
  const CompiledSession s = read_session(load_yaml_string(session_yaml(keyframes), kSessionName));
  Last last;
  Observer* const observers[] = {&last};
  ScriptedAgent agent(s.script);
  (void)run_session(s.model, *s.rules, agent, observers);
  return last;
}

TEST(SqueezeUntil, ASessionSettlesAtTheEffortAskedFor) {
  const Last effort = run("  - after: 1 s\n"
                          "    grip: {thumb: 160 mm, index: 160 mm, squeeze: {until: effort, value: 40 N}}\n"
                          "  - hold: 0.5 s\n");
  EXPECT_NEAR(effort.t, 1.5, 1e-9);
  EXPECT_TRUE(effort.grasped);
  // The static balance is the frame's at rest; the grip closed at the
  // start, so the grasp counted none of an approach (script.h).
  EXPECT_NEAR(effort.effort, 40.0, 0.4);
  const Last actee = run("  - after: 1 s\n"
                         "    grip: {thumb: 160 mm, index: 160 mm, squeeze: {until: actee_force, value: 200 N}}\n"
                         "  - hold: 0.5 s\n");
  // Within a few per cent: the balance keeps the load's arm where the jaws
  // first touch the walnut, the run follows the contact as the jaw turns.
  EXPECT_NEAR(actee.actee, 200.0, 8.0);
}

TEST(SqueezeUntil, ReleaseTakesTheFingersOffTheTool) {
  const Last released = run("  - after: 0.5 s\n"
                            "    grip: {thumb: 160 mm, index: 160 mm, squeeze: 5 mm}\n"
                            "  - after: 0.4 s\n"
                            "    release: true\n"
                            "  - hold: 0.2 s\n");
  EXPECT_FALSE(released.grasped);
  EXPECT_NEAR(released.effort, 0.0, 1e-12);
}

TEST(SqueezeUntil, MistakesAreLocated) {
  EXPECT_THAT(squeeze_error("  - after: 1 s\n"
                       "    grip: {thumb: 160 mm, index: 160 mm, squeeze: {until: actee_force, value: 500 N}}\n"),
              HasSubstr("test.yaml:14:"));
  EXPECT_THAT(squeeze_error("  - after: 1 s\n"
                       "    grip: {thumb: 160 mm, index: 160 mm, squeeze: {until: actee_force, value: 500 N}}\n"),
              HasSubstr("found 500 N: the walnut breaks at 378 N, before 500 N"));
  EXPECT_THAT(squeeze_error("  - after: 1 s\n"
                       "    grip: {thumb: 160 mm, index: 160 mm, squeeze: {until: effort, value: 450 N}}\n"),
              HasSubstr("expected an effort within the agent's largest, 400 N, found 450 N"));
  EXPECT_THAT(squeeze_error("  - after: 1 s\n"
                       "    grip: {thumb: 160 mm, index: 160 mm, squeeze: {until: torque, value: 1 N}}\n"),
              HasSubstr("test.yaml:14:"));
  EXPECT_THAT(squeeze_error("  - t: 1 s\n    after: 1 s\n"), HasSubstr("one of t, after and hold"));
  EXPECT_THAT(squeeze_error("  - hold: 1 s\n    posture: medium_wrap\n"), HasSubstr("nothing beside 'hold'"));
  EXPECT_THAT(squeeze_error("  - hand: {position: [80 mm, 40 mm, 190 mm]}\n"), HasSubstr("key 't' (or 'after' or 'hold'"));
  EXPECT_THAT(squeeze_error("  - after: 1 s\n    release: false\n"), HasSubstr("found false"));
  EXPECT_THAT(squeeze_error("  - after: 1 s\n    release: true\n    grip: {thumb: 160 mm, index: 160 mm, squeeze: 0 mm}\n"),
              HasSubstr("release with grip or fingertips"));
  EXPECT_THAT(squeeze_error("  - after: -1 s\n"), HasSubstr("test.yaml:13:"));
}

}  // namespace
}  // namespace afford::test
