// Sessions with several actees (session.h `actees:`, a keyframe's
// `actee:`): each is cracked at its own limit, the next is put on the tool
// where the tool is now, and the mistakes are located.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "load.h"
#include "run.h"
#include "scripted_agent.h"
#include "session.h"
#include "test_sessions.h"
#include "trace.h"
#include "test_util.h"

namespace afford::test {
namespace {

using ::testing::HasSubstr;


// Each break: which actee, when, and the load it broke at.
struct Breaks : Observer {
  struct Break {
    std::string actee;
    double t = 0, load = 0;
  };
  std::vector<Break> breaks;
  ActeeCondition last = ActeeCondition::intact;
  void on_frame(const Model& m, const State& s, const RuleSet&, const RuleState&) override {
    if (s.condition == ActeeCondition::broken && last != ActeeCondition::broken) {
      breaks.push_back({m.actee_name, s.t, s.peak_actee_load});
    }
    last = s.condition;
  }
};

TEST(SeveralActees, EachCracksAtItsOwnLimit) {
  const CompiledSession s = load_session(kSource + "/sessions/walnut-then-hazelnut.yaml");
  ASSERT_EQ(s.actee_models.size(), 2u);
  EXPECT_EQ(s.actee_changes.size(), 1u);
  EXPECT_DOUBLE_EQ(s.actee_changes[0].t, 2.6);
  Breaks breaks;
  Observer* const observers[] = {&breaks};
  ScriptedAgent agent(s.script);
  const RunResult r = run_session(s, *s.rules, agent, observers);
  // The walnut's limit is 378 N, the hazelnut's 431 N (actees/*.yaml).
  ASSERT_EQ(breaks.breaks.size(), 2u);
  EXPECT_EQ(breaks.breaks[0].actee, "walnut");
  EXPECT_NEAR(breaks.breaks[0].load, 378, 2);
  EXPECT_LT(breaks.breaks[0].t, 2.6);
  EXPECT_EQ(breaks.breaks[1].actee, "hazelnut");
  EXPECT_NEAR(breaks.breaks[1].load, 431, 2);
  EXPECT_GT(breaks.breaks[1].t, 2.6);
  int crashes = 0;
  for (const Inference& i : r.inferences) crashes += i.function == "crash" ? 1 : 0;
  EXPECT_EQ(crashes, 2);
}

// The nutcracker gripped at the start (test_sessions.h).
std::string session_yaml(const std::string& actees, const std::string& keyframes) {
  return nutcracker_session(actees, keyframes);
}

const std::string kTwo =
    "actees:\n"                                                   // 4
    "  - {file: ../actees/walnut.yaml, at: 60 mm}\n"              // 5
    "  - {file: ../actees/hazelnut.yaml, at: 50 mm, name: nut}\n";  // 6

std::string actees_error(const std::string& yaml) {
  try {
    (void)read_session(load_yaml_string(yaml, kSessionName));
  } catch (const DataError& e) {
    return e.what();
  }
  return "no error";
}

// Where the actee is, frame by frame.
struct Where : Observer {
  std::vector<double> t, actee_z, object_z;
  std::vector<std::string> actee;
  void on_frame(const Model& m, const State& s, const RuleSet&, const RuleState&) override {
    t.push_back(s.t);
    actee_z.push_back(s.actee_pose.translation().z());
    object_z.push_back(s.object_pose.translation().z());
    actee.push_back(m.actee_name);
  }
};

TEST(SeveralActees, TheNextGoesOnTheToolWhereTheToolIsNow) {
  // The hand lifts the grasped tool 50 mm, then the hazelnut (50 mm along
  // the jaw) takes the walnut's place: on the jaw of the lifted tool, 50 mm
  // above where the session placed it.
  const CompiledSession s = read_session(load_yaml_string(
      session_yaml(kTwo, "  - after: 1 s\n"
                         "    hand: {position: [80 mm, 40 mm, 240 mm]}\n"
                         "  - after: 0.5 s\n"
                         "    actee: nut\n"),
      kSessionName));
  const double placed_z = s.actee_models[1].actee_start.translation().z();
  Where where;
  Observer* const observers[] = {&where};
  ScriptedAgent agent(s.script);
  (void)run_session(s, *s.rules, agent, observers);
  ASSERT_FALSE(where.t.empty());
  EXPECT_EQ(where.actee.front(), "walnut");
  EXPECT_EQ(where.actee.back(), "hazelnut");
  // The tool rose with the hand but for the 0.1 mm the hand rose before
  // the grasp began (its second frame); the hazelnut with the tool.
  const double rise = where.object_z.back() - s.model.object_start.translation().z();
  EXPECT_NEAR(rise, 0.050, 2e-4);
  EXPECT_NEAR(where.actee_z.back(), placed_z + rise, 1e-9);
  // It changes at the keyframe's frame, 1.5 s, not before.
  for (size_t i = 0; i < where.t.size(); ++i) {
    EXPECT_EQ(where.actee[i], where.t[i] < 1.5 - 1e-9 ? "walnut" : "hazelnut") << where.t[i];
  }
}

TEST(SeveralActees, MistakesAreLocated) {
  EXPECT_THAT(actees_error(session_yaml(kTwo, "  - after: 1 s\n    actee: hazlenut\n")),
              HasSubstr("test.yaml:16:12: expected an actee of the session's 'actees:' (walnut, nut), found "
                        "'hazlenut'"));
  EXPECT_THAT(actees_error(session_yaml(kWalnutAt60, "  - after: 1 s\n    actee: walnut\n")),
              HasSubstr("test.yaml:14:12: expected no 'actee:' here (the session lists no 'actees:'"));
  EXPECT_THAT(actees_error(session_yaml("actee: {file: ../actees/walnut.yaml, at: 60 mm}\n" + kTwo, "")),
              HasSubstr("expected either 'actee' or 'actees' (several), found both"));
  EXPECT_THAT(actees_error(session_yaml("actees:\n  - {file: ../actees/walnut.yaml, at: 60 mm}\n"
                                    "  - {file: ../actees/walnut.yaml, at: 55 mm}\n",
                                    "")),
              HasSubstr("test.yaml:6:5: expected an actee named apart from the others (give it a 'name'), found "
                        "'walnut' again"));
  EXPECT_THAT(actees_error(session_yaml("actees:\n  - {file: ../actees/walnut.yaml, at: 60 mm, nmae: a}\n", "")),
              HasSubstr("test.yaml:5:"));
  EXPECT_THAT(actees_error(session_yaml("actees: []\n", "")), HasSubstr("expected a sequence of actees"));
  // A squeeze until an actee's force is the actee's on the tool then.
  EXPECT_THAT(actees_error(session_yaml(kTwo, "  - after: 1 s\n"
                                          "    grip: {thumb: 160 mm, index: 160 mm, squeeze: {until: actee_force, "
                                          "value: 400 N}}\n")),
              HasSubstr("found 400 N: the walnut breaks at 378 N, before 400 N"));
  // The hazelnut (431 N) takes it.
  EXPECT_EQ(actees_error(session_yaml(kTwo, "  - after: 1 s\n    actee: nut\n"
                                        "  - after: 1 s\n"
                                        "    grip: {thumb: 160 mm, index: 160 mm, squeeze: {until: actee_force, "
                                        "value: 400 N}}\n")),
            "no error");
}

// The timeline says when another actee was taken, and when a fingertip
// was stopped at its reach (the script moved off its checked keyframes).
std::string timeline_of(const CompiledSession& s) {
  std::FILE* file = std::tmpfile();
  TimelineWriter writer(file);
  Observer* const observers[] = {&writer};
  ScriptedAgent agent(s.script);
  (void)run_session(s, *s.rules, agent, observers);
  std::rewind(file);
  std::string text;
  for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) text += static_cast<char>(c);
  std::fclose(file);
  return text;
}

TEST(SeveralActees, TheTimelineSaysWhenAnotherIsTaken) {
  const CompiledSession s = load_session(kSource + "/sessions/walnut-then-hazelnut.yaml");
  EXPECT_THAT(timeline_of(s), HasSubstr("{\"t\":2.600000,\"event\":\"actee\",\"actee\":\"hazelnut\"}\n"));
}

TEST(SeveralActees, TheTimelineSaysWhenAFingerIsStoppedAtItsReach) {
  // The hand 0.5 m above its place at 1 s: the thumb (reach 131.5 mm from
  // the wrist, agents/hand.yaml) is stopped short, then let back.
  CompiledSession s = read_session(load_yaml_string(
      session_yaml("actee: {file: ../actees/walnut.yaml, at: 60 mm}\n",
                   "  - t: 1 s\n    fingertips: {thumb: [60 mm, 30 mm, -30 mm], index: [70 mm, 10 mm, -30 mm], middle: "
                   "[72 mm, -8 mm, -30 mm], ring: [68 mm, -25 mm, -28 mm], little: [60 mm, -40 mm, -25 mm]}\n"
                   "  - t: 2 s\n  - t: 3 s\n"),
      kSessionName));
  s.script.keyframes[2].fingertip[0] = Eigen::Vector3d(0.4, 0, 0);  // 400 mm from the wrist
  const std::string timeline = timeline_of(s);
  EXPECT_THAT(timeline, HasSubstr("\"event\":\"out_of_reach\",\"finger\":\"thumb\",\"short_m\":"));
  EXPECT_THAT(timeline, HasSubstr("\"event\":\"within_reach\",\"finger\":\"thumb\"}"));
}

}  // namespace
}  // namespace afford::test
