// The hand's reach (engine/model/reach.h): planar finger chains within the joint
// ranges of agents/hand.yaml, and sessions that ask for more.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "load.h"
#include "reach.h"
#include "script.h"
#include "session.h"
#include "state.h"
#include "test_sessions.h"
#include "test_util.h"

namespace afford {
namespace {
using test::kSource;
using test::kSessionName;
using test::kDeg;

using ::testing::HasSubstr;
using test::replace_once;
using test::thrown;

constexpr double kMm = 1e-3;

// Joint order [distal, proximal, metacarpal], as in the agent file.
using Joints = std::array<double, kJoints>;

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Model shipped_hand() { return compile_agent_only(load_agent(kSource + "/agents/hand.yaml")); }

// A two-link finger (no distal link) of L1 = 40 mm and L2 = 30 mm reaches
// |L1 - L2| <= d <= L1 + L2 when its proximal joint may fold back on
// itself: 10 mm to 70 mm.
TEST(Reach, TwoLinksSpanTheDifferenceToTheSumOfTheirLengths) {
  const Joints link{0.0, 30 * kMm, 40 * kMm};
  double nearest = 0, farthest = 0;
  chain_range(link, {0, 0, 0}, {0, 180 * kDeg, 0}, &nearest, &farthest);
  EXPECT_NEAR(nearest, 10 * kMm, 1e-9);
  EXPECT_NEAR(farthest, 70 * kMm, 1e-9);
}

// The joint's range limits it: folded at most 90 deg the nearest is the
// hypotenuse sqrt(40^2 + 30^2) = 50 mm; from 30 deg to 90 deg the farthest
// is at 30 deg, sqrt(40^2 + 30^2 + 2*40*30*cos 30) = sqrt(4578.46) = 67.664 mm.
TEST(Reach, TheJointRangeLimitsTheSpan) {
  const Joints link{0.0, 30 * kMm, 40 * kMm};
  double nearest = 0, farthest = 0;
  chain_range(link, {0, 0, 0}, {0, 90 * kDeg, 0}, &nearest, &farthest);
  EXPECT_NEAR(nearest, 50 * kMm, 1e-9);
  EXPECT_NEAR(farthest, 70 * kMm, 1e-9);
  chain_range(link, {0, 30 * kDeg, 0}, {0, 90 * kDeg, 0}, &nearest, &farthest);
  EXPECT_NEAR(farthest, 67.664 * kMm, 1e-6);
  EXPECT_NEAR(nearest, 50 * kMm, 1e-9);
  // The metacarpal range turns the whole chain: it changes nothing.
  double n2 = 0, f2 = 0;
  chain_range(link, {0, 30 * kDeg, -1}, {0, 90 * kDeg, 1}, &n2, &f2);
  EXPECT_EQ(n2, nearest);
  EXPECT_EQ(f2, farthest);
}

// The shipped index (links 43, 25, 16 mm; proximal 0-100 deg, distal
// 0-90 deg): straight it spans 84 mm; most curled, at (100 deg, 90 deg),
// D^2 = 43^2 + 25^2 + 16^2 + 2*43*25 cos 100 + 2*25*16 cos 90
//       + 2*43*16 cos 190 = 2730 - 373.34 + 0 - 1355.10 = 1001.56 mm^2,
// D = 31.65 mm. Its base at (90, 25, 0) mm is 93.41 mm from the wrist, so
// with the palm free about the wrist the tip reaches 93.41 - 84 = 9.41 mm
// to 93.41 + 84 = 177.41 mm from it.
TEST(Reach, TheShippedIndexWorkedByHand) {
  const Model m = shipped_hand();
  ASSERT_TRUE(m.has_reach);
  EXPECT_NEAR(m.chain_max[1], 84 * kMm, 1e-9);
  EXPECT_NEAR(m.chain_min[1], 31.65 * kMm, 0.01 * kMm);
  EXPECT_NEAR(chain_distance(m.link[1], 100 * kDeg, 90 * kDeg), 31.647 * kMm, 0.001 * kMm);
  EXPECT_NEAR(m.reach_max[1], 177.41 * kMm, 0.01 * kMm);
  EXPECT_NEAR(m.reach_min[1], 9.41 * kMm, 0.01 * kMm);
}

// The shipped thumb (links 46, 32, 20 mm; MCP 0-50 deg, IP -20-80 deg)
// spans 98 mm straight; its CMC at (25, 20, -10) mm is sqrt(1125) =
// 33.54 mm from the wrist: it reaches 131.54 mm.
TEST(Reach, TheShippedThumbWorkedByHand) {
  const Model m = shipped_hand();
  EXPECT_NEAR(m.chain_max[0], 98 * kMm, 1e-9);
  EXPECT_NEAR(m.reach_max[0], 131.54 * kMm, 0.01 * kMm);
  // 200 mm out along any line from the wrist: 68.46 mm beyond its reach,
  // and the nearest reachable point is 131.54 mm along the same line.
  const Eigen::Vector3d far(0, 0.12, -0.16);  // 200 mm
  EXPECT_NEAR(reach_short(m, 0, far), 68.46 * kMm, 0.01 * kMm);
  EXPECT_NEAR((nearest_reachable(m, 0, far) - far * (m.reach_max[0] / 0.2)).norm(), 0, 1e-12);
  const Eigen::Vector3d near(0.06, 0.03, -0.03);
  EXPECT_EQ(reach_short(m, 0, near), 0);
  EXPECT_EQ(nearest_reachable(m, 0, near), near);
}

// finger_chain() draws the finger: links of their lengths, angles within
// the joint ranges, the tip on the target when it is within reach.
TEST(Reach, TheChainEndsOnAReachableTarget) {
  const Model m = shipped_hand();
  for (int f = 0; f < kFingers; ++f) {
    const size_t i = static_cast<size_t>(f);
    // Within the chain about the unturned base, and one that needs the palm turned.
    const Eigen::Vector3d targets[] = {m.finger_base[i] + Eigen::Vector3d(0.03, 0.0, -0.05),
                                       Eigen::Vector3d(0.04, -0.06, -0.09)};
    for (const Eigen::Vector3d& target : targets) {
      ASSERT_EQ(reach_short(m, f, target), 0) << kFingerNames[i];
      const FingerChain c = finger_chain(m, f, target);
      EXPECT_NEAR((c.point[3] - target).norm(), 0, 1e-7) << kFingerNames[i];
      EXPECT_EQ(c.short_by, 0);
      EXPECT_NEAR(c.point[0].norm(), m.finger_base[i].norm(), 1e-12);  // turned about the wrist, never moved
      EXPECT_NEAR((c.point[1] - c.point[0]).norm(), m.link[i][2], 1e-12);
      EXPECT_NEAR((c.point[2] - c.point[1]).norm(), m.link[i][1], 1e-12);
      EXPECT_NEAR((c.point[3] - c.point[2]).norm(), m.link[i][0], 1e-12);
      for (size_t j = 0; j < 2; ++j) {
        EXPECT_GE(c.angle[j], m.joint_min[i][j] - 1e-12);
        EXPECT_LE(c.angle[j], m.joint_max[i][j] + 1e-12);
      }
    }
  }
}

// A target 2 m away: the finger is drawn stretched toward it, its tip at
// its reach, and says how far short it stops.
TEST(Reach, TheChainStopsAtItsReach) {
  const Model m = shipped_hand();
  const Eigen::Vector3d target(2.0, 0, 0);
  const FingerChain c = finger_chain(m, 1, target);
  EXPECT_NEAR(c.short_by, 2.0 - 0.17741, 1e-5);
  EXPECT_NEAR((c.point[3] - Eigen::Vector3d(m.reach_max[1], 0, 0)).norm(), 0, 1e-7);
  EXPECT_EQ(c.angle[0], 0);  // straight
  EXPECT_EQ(c.angle[1], 0);
}

// ------------------------------------------------------------ sessions

const std::string& kSession = test::kNutcrackerSession;  // lines 1 to 14

std::string session_error(const std::string& yaml) {
  return thrown<DataError>([&] { (void)read_session(load_yaml_string(yaml, kSessionName)); });
}

TEST(ReachSession, TheShippedPlacementIsWithinReach) {
  EXPECT_EQ(session_error(kSession), "");
}

// The session: the hand 2 m from a nutcracker it grips. The thumb
// at 160 mm on the moving arm's face (12 mm), its centre 10.5 - 0.1 mm
// out, at the rest angle 30 deg: x = 160 cos 30 - 22.4 sin 30 = 127.364 mm,
// y = 160 sin 30 + 22.4 cos 30 = 99.399 mm, z = 100 mm (the tool's pose).
// From the wrist at (2000, 0, 0) mm: (-1872.636, 99.399, 100) mm,
// 1877.94 mm; the thumb reaches 131.54 mm: 1746.4 mm out of reach.
TEST(ReachSession, AHandTwoMetresAwayIsAnErrorAtItsPosition) {
  const std::string e =
      session_error(replace_once(kSession, "[80 mm, 40 mm, 190 mm]", "[2000 mm, 0 mm, 0 mm]"));
  EXPECT_THAT(e, HasSubstr("test.yaml:10:22: expected a hand within reach"));
  EXPECT_THAT(e, HasSubstr("the thumb's tip reaches 33.33 mm to 131.5 mm from the wrist"));
  EXPECT_THAT(e, HasSubstr("found the thumb's tip 1878 mm from the wrist at 0 s (keyframe at line 9): "
                           "1746 mm out of its reach"));
}

// A hand that lifts the tool it grasps keeps its fingertips (the tool
// moves with it); one that lets go of the fixed arm (`index: none`, no
// grasp) and rises 310 mm leaves the tool behind: the thumb's tip would be
// 310 mm further below the wrist, beyond reach. The error names that
// keyframe's hand.
TEST(ReachSession, AHandMovedAwayLaterIsAnErrorThere) {
  EXPECT_EQ(session_error(kSession +
                          "  - t: 2 s\n"
                          "    hand: {position: [80 mm, 40 mm, 500 mm]}\n"),
            "");
  const std::string e = session_error(kSession +
                                      "  - t: 2 s\n"                                                 // 15
                                      "    hand: {position: [80 mm, 40 mm, 500 mm]}\n"               // 16
                                      "    grip: {thumb: 160 mm, index: none, squeeze: 0 mm}\n");    // 17
  EXPECT_THAT(e, HasSubstr("test.yaml:16:22: expected a hand within reach"));
  EXPECT_THAT(e, HasSubstr("at 2 s (keyframe at line 15)"));
}

// Squeezing past the arm's limit is force, not a place: the thumb is
// checked where the arm stops (the nutcracker closes at 0 deg), so a
// squeeze far past it is no reach error.
TEST(ReachSession, ASqueezePastTheStopIsNoReachError) {
  EXPECT_EQ(session_error(replace_once(kSession, "squeeze: 10 mm", "squeeze: 150 mm")), "");
}

// An agent without `reach` (a test rig) has no limit.
TEST(ReachSession, AnAgentWithoutChainsIsNotLimited) {
  std::string hand = file_text(kSource + "/agents/hand.yaml");
  hand = hand.substr(0, hand.find("\nreach:\n") + 1);
  const std::string yaml = replace_once(replace_once(kSession, "agent: ../agents/hand.yaml\n", "agent:\n" + [&] {
    std::string indented;
    std::istringstream in(hand);
    for (std::string l; std::getline(in, l);) {
      if (!l.empty() && l[0] != '#') indented += "  " + l + "\n";
    }
    return indented;
  }()), "[80 mm, 40 mm, 190 mm]", "[2000 mm, 0 mm, 0 mm]");
  const CompiledSession s = read_session(load_yaml_string(yaml, kSessionName));
  EXPECT_FALSE(s.model.has_reach);
}

// ------------------------------------------------------------ the frame

// A sample beyond reach stops at its reach: the thumb asked 200 mm from
// the wrist is 68.46 mm beyond and stays 131.54 mm out along the same line;
// the index asked at the wrist itself is 9.41 mm inside its nearest reach
// and stops 9.41 mm out along +x (no line to follow from the wrist).
TEST(ReachFrame, ATipBeyondReachStopsThereAndSaysHowFar) {
  const CompiledSession s = read_session(load_yaml_string(kSession, kSessionName));
  auto state = make_state(s.model);
  Sample sample;
  sample.t = s.model.timestep;
  sample.hand = Eigen::Isometry3d::Identity();
  sample.hand.translation() = Eigen::Vector3d(1.0, 1.0, 1.0);  // clear of the tool
  for (size_t f = 0; f < kFingers; ++f) sample.fingertip[f] = sample.hand * kCurledFingertip[f];
  sample.fingertip[0] = sample.hand * Eigen::Vector3d(0, 0.12, -0.16);
  sample.fingertip[1] = sample.hand.translation();
  step(s.model, *state, sample);
  EXPECT_NEAR(state->reach_short[0], 68.46 * kMm, 0.01 * kMm);
  EXPECT_NEAR(state->reach_short[1], 9.41 * kMm, 0.01 * kMm);
  for (size_t f = 2; f < kFingers; ++f) {
    EXPECT_EQ(state->reach_short[f], 0) << kFingerNames[f];
    EXPECT_EQ(state->fingertip[f], sample.fingertip[f]) << kFingerNames[f];
  }
  const Eigen::Vector3d thumb = state->hand.inverse() * state->fingertip[0];
  EXPECT_NEAR((thumb - Eigen::Vector3d(0, 0.6, -0.8) * 131.54 * kMm).norm(), 0, 0.01 * kMm);
  const Eigen::Vector3d index = state->hand.inverse() * state->fingertip[1];
  EXPECT_NEAR((index - Eigen::Vector3d(9.41 * kMm, 0, 0)).norm(), 0, 0.01 * kMm);
}

// The hand, 2 m away, driven frame by frame as a device would: its
// fingertips stop at their reach, nowhere near the tool, and nothing grasps.
TEST(ReachFrame, AHandTwoMetresAwayCannotGrasp) {
  const CompiledSession s = read_session(load_yaml_string(kSession, kSessionName));
  auto state = make_state(s.model);
  Sample sample;
  sample.hand = Eigen::Isometry3d::Identity();
  sample.hand.translation() = Eigen::Vector3d(2.0, 0, 0);
  // Where the session's grip puts thumb and index, in the world.
  const Keyframe& grip = s.script.keyframes[0];
  const Eigen::Isometry3d at_keyframe = Eigen::Translation3d(0.08, 0.04, 0.19) * Eigen::Isometry3d::Identity();
  for (size_t f = 0; f < kFingers; ++f) sample.fingertip[f] = sample.hand * kCurledFingertip[f];
  sample.fingertip[0] = at_keyframe * grip.fingertip[0];
  sample.fingertip[1] = at_keyframe * grip.fingertip[1];
  for (int k = 1; k <= 20; ++k) {
    sample.t = k * s.model.timestep;
    step(s.model, *state, sample);
    EXPECT_FALSE(state->grasped);
  }
  EXPECT_NEAR(state->reach_short[0], (1877.94 - 131.54) * kMm, 0.01 * kMm);
  EXPECT_EQ(state->agent_object.count, 0);
}

// ------------------------------------------------------------ the agent file

std::string agent_error(const std::string& yaml) {
  return thrown<DataError>([&] { (void)read_agent(load_yaml_string(yaml, "bad.yaml")); });
}

TEST(ReachAgentFile, MistakesAreLocated) {
  const std::string hand = file_text(kSource + "/agents/hand.yaml");
  EXPECT_EQ(agent_error(hand), "");
  EXPECT_THAT(agent_error(replace_once(hand, "links: {metacarpal: 43 mm,", "lenks: {metacarpal: 43 mm,")),
              HasSubstr("expected one of the keys of the reach of the index (base, links), found 'lenks' "
                        "(did you mean 'links'?)"));
  // Located at the value: the line and column of "28 mm" in the file.
  const size_t at = hand.find("proximal: 28 mm") + std::string("proximal: ").size();
  const size_t line_start = hand.rfind('\n', at) + 1;
  const std::string where = "bad.yaml:" + std::to_string(std::count(hand.begin(), hand.begin() + at, '\n') + 1) +
                            ":" + std::to_string(at - line_start + 1) + ": ";
  EXPECT_THAT(agent_error(replace_once(hand, "proximal: 28 mm", "proximal: 0 mm")),
              HasSubstr(where + "expected a value greater than zero, found '0 mm'"));
  EXPECT_THAT(agent_error(replace_once(hand, "base: [76 mm, -31 mm, 0 mm]", "base: [76 mm, -31 mm]")),
              HasSubstr("bad.yaml:"));
  EXPECT_THAT(agent_error(replace_once(hand, "  little:\n    base:", "  pinkie:\n    base:")),
              HasSubstr("found 'pinkie'"));
}

}  // namespace
}  // namespace afford
