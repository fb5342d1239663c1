// Sessions: the agent script (interpolation, carry-forward), grips placed on
// the arms' outer faces, session files and their errors (file:line:col),
// the run loop with its trace and timeline, and whole-session determinism.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <sstream>

#include "rig.h"
#include "run.h"
#include "scripted_agent.h"
#include "session.h"
#include "terms.h"
#include "test_sessions.h"
#include "trace.h"
#include "test_util.h"

namespace afford::test {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;


// ------------------------------------------------------------ helpers

std::string indent(const std::string& text, int spaces) {
  std::string out, pad(static_cast<size_t>(spaces), ' ');
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out += pad + line + "\n";
  return out;
}

// A nutcracker session with a walnut at 60 mm (test_sessions.h, lines 1 to 14).
const std::string& kSession = kNutcrackerSession;

// kSession with line `line` (1-based) replaced.
std::string with_line(int line, const std::string& text) {
  std::istringstream in(kSession);
  std::string out;
  int n = 0;
  for (std::string l; std::getline(in, l);) out += (++n == line ? text : l) + "\n";
  return out;
}

CompiledSession session_from(const std::string& yaml) { return read_session(load_yaml_string(yaml, kSessionName)); }

std::string session_error(const std::string& yaml) {
  try {
    session_from(yaml);
  } catch (const DataError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no DataError for:\n" << yaml;
  return "";
}

std::string at(int line, int column) { return "test.yaml:" + std::to_string(line) + ":" + std::to_string(column) + ": "; }

// Captures what an observer writes (open_memstream: no file on disk).
struct Capture {
  Capture() : file(open_memstream(&data, &size)) {}
  ~Capture() {
    if (file != nullptr) std::fclose(file);
    std::free(data);
  }
  std::string text() {
    std::fflush(file);
    return std::string(data, size);
  }
  char* data = nullptr;
  size_t size = 0;
  std::FILE* file;
};

struct Outputs {
  RunResult result;
  std::string trace, timeline;
};

Outputs run_with_writers(const CompiledSession& s) {
  Capture trace, timeline;
  TraceWriter trace_writer(trace.file);
  TimelineWriter timeline_writer(timeline.file);
  Observer* const observers[] = {&trace_writer, &timeline_writer};
  ScriptedAgent agent(s.script);
  Outputs out;
  out.result = run_session(s.model, *s.rules, agent, observers);
  out.trace = trace.text();
  out.timeline = timeline.text();
  return out;
}

int count_lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

std::vector<std::string> function_names(const RunResult& r) {
  std::vector<std::string> names;
  for (const Inference& i : r.inferences) names.push_back(i.function);
  return names;
}

// ------------------------------------------------------------ interpolation

Script two_keyframes() {
  Script s;
  Keyframe a, b;
  a.t = 1.0;
  b.t = 3.0;
  a.hand_position = {0.0, 0.0, 0.0};
  b.hand_position = {0.2, 0.4, -0.6};
  a.hand_rotation = Eigen::Quaterniond::Identity();
  b.hand_rotation = Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()));
  for (size_t f = 0; f < kFingers; ++f) {
    a.fingertip[f] = Eigen::Vector3d(0.1, 0.01 * static_cast<double>(f), 0.0);
    b.fingertip[f] = Eigen::Vector3d(0.3, 0.01 * static_cast<double>(f), 0.2);
    for (size_t j = 0; j < kJoints; ++j) {
      a.joint[f][j] = 0.0;
      b.joint[f][j] = 0.5 + 0.25 * static_cast<double>(j);
    }
  }
  s.keyframes = {a, b};
  return s;
}

TEST(Script, MidpointsAreExact) {
  const Script s = two_keyframes();
  ScriptedAgent agent(s);
  Sample sample;
  ASSERT_TRUE(agent.sample_at(2.0, &sample));
  EXPECT_EQ(sample.t, 2.0);
  EXPECT_EQ(sample.hand.translation(), Eigen::Vector3d(0.1, 0.2, -0.3));
  EXPECT_EQ(sample.joint[2][0], 0.25);
  EXPECT_EQ(sample.joint[2][1], 0.375);
  EXPECT_EQ(sample.joint[2][2], 0.5);
  // The fingertip halfway in the hand frame, placed by the halfway hand.
  const Eigen::Vector3d in_hand = sample.hand.inverse() * sample.fingertip[1];
  EXPECT_NEAR((in_hand - Eigen::Vector3d(0.2, 0.01, 0.1)).norm(), 0, 1e-15);
}

TEST(Script, RotationIsSlerped) {
  const Script s = two_keyframes();
  ScriptedAgent agent(s);
  Sample sample;
  for (double u : {0.25, 0.5, 0.75}) {
    ASSERT_TRUE(agent.sample_at(1.0 + 2.0 * u, &sample));
    const Eigen::AngleAxisd turn(sample.hand.linear());
    EXPECT_NEAR(turn.angle(), u * std::numbers::pi / 2, 1e-12) << u;
    EXPECT_NEAR((turn.axis() - Eigen::Vector3d::UnitZ()).norm(), 0, 1e-12) << u;
  }
}

TEST(Script, KeyframesExactlyAndTheEnds) {
  const Script s = two_keyframes();
  ScriptedAgent agent(s);
  EXPECT_EQ(agent.duration(), 3.0);
  Sample sample;
  ASSERT_TRUE(agent.sample_at(3.0, &sample));  // the last keyframe itself
  EXPECT_EQ(sample.hand.translation(), s.keyframes[1].hand_position);
  EXPECT_EQ(sample.joint[4][2], 1.0);
  ASSERT_TRUE(agent.sample_at(0.5, &sample));  // before the first: the first
  EXPECT_EQ(sample.hand.translation(), Eigen::Vector3d::Zero());
  EXPECT_EQ(sample.fingertip[0], s.keyframes[0].fingertip[0]);
  EXPECT_FALSE(agent.sample_at(3.001, &sample));  // the script is over
}

TEST(Script, LaterKeyframesCarryForwardWhatTheyOmit) {
  const CompiledSession s = session_from(kSession +
                                         "  - t: 2 s\n"
                                         "    hand: {position: [80 mm, 40 mm, 250 mm]}\n"
                                         "  - t: 3 s\n"
                                         "    posture: tripod\n");
  const std::vector<Keyframe>& k = s.script.keyframes;
  ASSERT_EQ(k.size(), 4u);
  // Keyframe 1 keeps the hand and the posture of keyframe 0.
  EXPECT_EQ(k[1].hand_position, k[0].hand_position);
  EXPECT_EQ(k[1].joint, k[0].joint);
  EXPECT_NE(k[1].fingertip[0], k[0].fingertip[0]);  // the squeeze moved the thumb
  // Keyframe 2 moves the hand and keeps the grip: the tool moves with the
  // hand, so the fingertips keep their place in the hand frame.
  EXPECT_EQ(k[2].hand_position, Eigen::Vector3d(0.08, 0.04, 0.25));
  for (size_t f = 0; f < kFingers; ++f) EXPECT_NEAR((k[2].fingertip[f] - k[1].fingertip[f]).norm(), 0, 1e-15);
  EXPECT_EQ(k[2].joint, k[0].joint);
  // Keyframe 3 changes only the posture.
  EXPECT_EQ(k[3].hand_position, k[2].hand_position);
  EXPECT_EQ(k[3].fingertip, k[2].fingertip);
  EXPECT_NE(k[3].joint, k[2].joint);
  EXPECT_EQ(classify_grasp(s.model, k[3].joint), 5);  // tripod, the sixth type
  EXPECT_EQ(classify_grasp(s.model, k[0].joint), 1);  // medium_wrap
}

TEST(Script, ASqueezeTurnsTheThumbOnTheArc) {
  const CompiledSession s = session_from(kSession);
  ScriptedAgent agent(s.script);
  const Keyframe& k = s.script.keyframes[0];
  const double r = std::hypot(k.thumb_rest.x(), k.thumb_rest.y());
  Sample sample;
  for (double t : {0.25, 0.5, 0.75}) {
    ASSERT_TRUE(agent.sample_at(t, &sample));
    const Eigen::Vector3d in_object = s.model.object_start.inverse() * sample.fingertip[0];
    // On the circle about the pivot (a chord would cut inside it), at the
    // squeeze's share of the angle.
    EXPECT_NEAR(std::hypot(in_object.x(), in_object.y()), r, 1e-12) << t;
    const double angle = std::atan2(in_object.y(), in_object.x()) - std::atan2(k.thumb_rest.y(), k.thumb_rest.x());
    EXPECT_NEAR(angle, s.model.theta_rest - t * 0.010 / 0.160, 1e-12) << t;
  }
}

// ------------------------------------------------------------ grips

// An inline session for one of the rig's tools (every lever pattern) with
// the thumb and index on the arms at the rig's effort distance.
std::string rig_session(const Tool& tool, double squeeze_mm) {
  char grip[160];
  std::snprintf(grip, sizeof grip, "    grip: {thumb: %g mm, index: %g mm, squeeze: %g mm}\n", tool.effort * 1000,
                tool.effort * 1000, squeeze_mm);
  return std::string("session: rig\ndescription: rig tool\nobject:\n") + indent(tool.yaml, 2) + "agent:\n" +
         indent(kHandYaml, 2) +
         "rules: ../rules/functions.yaml\ngrasps: ../rules/grasps.yaml\nscript:\n"
         "  - t: 0 s\n    hand: {position: [0 mm, 0 mm, 100 mm]}\n" +
         grip + "    posture: medium_wrap\n  - t: 1 s\n";
}

TEST(Grip, FingersLandOnTheOuterFacesOfEveryPattern) {
  for (const Tool& tool : tools_of_every_pattern()) {
    const CompiledSession s = session_from(rig_session(tool, 0));
    ScriptedAgent agent(s.script);
    auto state = make_state(s.model);
    Sample sample;
    for (int k = 1; k <= 3; ++k) {
      ASSERT_TRUE(agent.sample_at(k * s.model.timestep, &sample));
      step(s.model, *state, sample);
    }
    EXPECT_TRUE(state->finger_on_arm[0] & 2) << tool.name << ": thumb on the moving arm";
    EXPECT_FALSE(state->finger_on_arm[0] & 1) << tool.name;
    EXPECT_TRUE(state->finger_on_arm[1] & 1) << tool.name << ": index on the fixed arm";
    EXPECT_FALSE(state->finger_on_arm[1] & 2) << tool.name;
    for (size_t f = 2; f < kFingers; ++f) EXPECT_EQ(state->finger_on_arm[f], 0) << tool.name << " finger " << f;
    EXPECT_TRUE(state->grasped) << tool.name;
    // The thumb's centre sits one tip radius (less the press) outside the
    // 10 mm thick arm, on the side away from the other arm.
    const Eigen::Vector3d thumb =
        moving_arm_pose(s.model.theta_rest).inverse() * (s.model.object_start.inverse() * state->fingertip[0]);
    const double side = tool.effort > 0 ? 1.0 : -1.0;
    EXPECT_NEAR(thumb.x(), tool.effort, 1e-12) << tool.name;
    EXPECT_NEAR(thumb.y(), side * (kThickness + s.model.tip_radius[0] - kGripPress), 1e-12) << tool.name;
    const Eigen::Vector3d index = s.model.object_start.inverse() * state->fingertip[1];
    EXPECT_NEAR(index.y(), -side * (kThickness + s.model.tip_radius[1] - kGripPress), 1e-12) << tool.name;
  }
}

// The parts are placed again only when the tool moves or its arm turns
// (contacts.cpp); at every frame of paper-tongs, which squeezes, carries and
// rests, each part's pose is exactly what placing it afresh gives.
TEST(Run, PartsArePlacedWhereTheToolAndItsAngleSay) {
  const CompiledSession s = load_session(kSource + "/sessions/paper-tongs.yaml");
  ScriptedAgent agent(s.script);
  auto state = make_state(s.model);
  Sample sample;
  int moved = 0, still = 0;
  Eigen::Isometry3d last_pose = state->object_pose;
  double last_theta = state->theta;
  for (std::int64_t k = 1; agent.sample_at(static_cast<double>(k) * s.model.timestep, &sample); ++k) {
    sample.t = static_cast<double>(k) * s.model.timestep;
    step(s.model, *state, sample);
    const bool same = state->theta == last_theta && state->object_pose.isApprox(last_pose, 0.0);
    (same ? still : moved) += 1;
    last_pose = state->object_pose;
    last_theta = state->theta;
    const Eigen::Isometry3d moving = state->object_pose * moving_arm_pose(state->theta);
    for (size_t i = 0; i < s.model.parts.size(); ++i) {
      const ModelPart& part = s.model.parts[i];
      const Eigen::Isometry3d fresh = (part.arm == Arm::moving ? moving : state->object_pose) * part.in_arm;
      ASSERT_TRUE((state->part_pose[i].matrix().array() == fresh.matrix().array()).all()) << "frame " << k << " part " << i;
    }
  }
  EXPECT_GT(moved, 1000);  // both kinds of frame were seen
  EXPECT_GT(still, 1000);
}

TEST(Grip, SqueezeClosesTheFreeLeverByItsArc) {
  const Tool tool = tools_of_every_pattern()[0];  // type 2, thumb at 150 mm, opens to 50 deg
  // Still for 1 s (the grasp starts), then 30 mm in 1 s.
  const CompiledSession s = session_from(rig_session(tool, 0) + "  - t: 2 s\n" +
                                         "    grip: {thumb: 150 mm, index: 150 mm, squeeze: 30 mm}\n");
  ScriptedAgent agent(s.script);
  auto state = make_state(s.model);
  Sample sample;
  for (int k = 1; k <= 2000; ++k) {
    ASSERT_TRUE(agent.sample_at(k * s.model.timestep, &sample));
    step(s.model, *state, sample);
  }
  ASSERT_TRUE(state->grasped);
  // The hand's target: within the first-order step of eq. 1 (each frame's
  // motion projected on the arm as it was), 1e-5 rad is 1.5 um at the thumb.
  EXPECT_NEAR(state->theta_command, s.model.theta_rest - 0.030 / 0.150, 1e-5);
  // The arm lags it by the hand impedance's stretch, which carries the
  // spring: f_a * b * (theta - command) * b = spring torque.
  const double b = std::abs(state->effort_distance);
  EXPECT_NEAR(s.model.force_gain * b * (state->theta - state->theta_command) * b, state->torque[kSpring] +
              state->torque[kSpringPreload], 1e-9);
  EXPECT_GT(state->theta - state->theta_command, 1e-4);
  EXPECT_TRUE(state->finger_on_arm[0] & 2);
}

// ------------------------------------------------------------ session errors

TEST(Run, TheTongsCarryTheirArmsWeightOnEdge) {
  // objects/tongs.yaml stands on edge, the moving arm above. Worked by hand:
  // the parts share the 140 g by volume; the moving arm is half of it,
  // 70 g, its strip (185 x 8 x 22 mm = 32,560 mm^3 at (92.5, 4) mm) and
  // head (55 x 6 x 40 mm = 13,200 mm^3 at (212.5, 3) mm) centred at
  // (127.12, 3.711) mm of its frame. At rest (18 deg) that is
  // 127.12 cos 18 - 3.711 sin 18 = 119.75 mm out from the pivot, level:
  // its weight closes the arm by 0.07 * 9.80665 * 0.11975 = 0.08220 N*m.
  const CompiledSession s = load_session(AFFORD_SOURCE_DIR "/sessions/paper-tongs.yaml");
  ASSERT_TRUE(s.model.gravity);
  const double x = (32560 * 92.5 + 13200 * 212.5) / 45760e3, y = (32560 * 4.0 + 13200 * 3.0) / 45760e3;  // m
  auto weight = [&](double theta) { return -0.07 * 9.80665 * (x * std::cos(theta) - y * std::sin(theta)); };
  const auto start = state_at(s, 0.1);  // the fingers closing, the arm at rest
  EXPECT_NEAR(start->theta, 18 * std::numbers::pi / 180, 1e-12);
  EXPECT_NEAR(start->torque[kGravity], -0.08220, 5e-6);
  EXPECT_NEAR(start->torque[kGravity], weight(start->theta), 1e-12);
  // Lifted and carried (2 to 4 s), the hand neither tips nor turns the
  // tool: the weight still acts, at the arm's angle of the moment.
  const auto carried = state_at(s, 3.0);
  EXPECT_GT(carried->object_pose.translation().z(), start->object_pose.translation().z() + 0.03);
  EXPECT_NEAR(carried->torque[kGravity], weight(carried->theta), 1e-12);
  // The nutcracker lies flat (its guide says why): even with its weight
  // switched on, none of it turns the arm about the vertical pivot.
  Model flat = load_session(AFFORD_SOURCE_DIR "/sessions/paper-nutcracker.yaml").model;
  flat.gravity = true;
  double c = 1, sn = 1;
  gravity_coefficients(flat, flat.object_start.linear(), &c, &sn);
  EXPECT_NEAR(std::hypot(c, sn), 0, 1e-15);
}

TEST(SessionErrors, UnknownKeySaysDidYouMean) {
  const std::string e = session_error(with_line(8, "scirpt:"));
  EXPECT_THAT(e, HasSubstr(at(8, 1) + "expected one of the keys of a session file"));
  EXPECT_THAT(e, HasSubstr("found 'scirpt' (did you mean 'script'?)"));
}

TEST(SessionErrors, MissingFileIsReportedAtItsKey) {
  const std::string e = session_error(with_line(3, "object: ../objects/nutcraker.yaml"));
  EXPECT_THAT(e, HasSubstr(at(3, 1) + "expected a readable file '../objects/nutcraker.yaml' (relative to the "
                                      "session's folder), found none"));
  EXPECT_THAT(session_error(with_line(4, "actee: {file: ../actees/wallnut.yaml, at: 60 mm}")),
              HasSubstr(at(4, 9) + "expected a readable file '../actees/wallnut.yaml'"));
  EXPECT_THAT(session_error(with_line(6, "rules: ../rules")), HasSubstr(at(6, 1) + "expected a readable file '../rules' "
                                                                         "(relative to the session's folder), found a directory"));
}

TEST(SessionErrors, AMistakeInANamedFileNamesThatFile) {
  const std::string e = session_error(with_line(5, "agent: ../actees/walnut.yaml"));
  EXPECT_THAT(e, HasSubstr("/actees/walnut.yaml:19:1: expected one of the keys of an agent file"));
}

TEST(SessionErrors, TimesMustIncrease) {
  const std::string e = session_error(with_line(13, "  - t: 0 s"));
  EXPECT_THAT(e, HasSubstr(at(13, 8) + "expected a time after the previous keyframe's (0 s), found '0 s'"));
  EXPECT_THAT(session_error(with_line(13, "  - t: 1 mm")), HasSubstr(at(13, 8) + "expected a time"));
}

TEST(SessionErrors, GripOffTheArm) {
  const std::string e = session_error(with_line(14, "    grip: {thumb: 200 mm, index: 160 mm, squeeze: 10 mm}"));
  EXPECT_THAT(e, HasSubstr(at(14, 19) + "expected a distance on the moving arm (its parts cover 0 mm to 185 mm), "
                                        "found 200 mm"));
  EXPECT_THAT(session_error(with_line(11, "    grip: {thumb: 160 mm, index: -5 mm, squeeze: 0 mm}")),
              HasSubstr(at(11, 34) + "expected a distance on the fixed arm"));
  EXPECT_THAT(session_error(with_line(11, "    grip: {thumb: 160 mm, index: 160 mm, squeeze: -1 mm}")),
              HasSubstr(at(11, 51) + "expected a value of zero or more"));
}

TEST(SessionErrors, UnknownPostureSaysDidYouMean) {
  const std::string e = session_error(with_line(12, "    posture: medium_warp"));
  EXPECT_THAT(e, HasSubstr(at(12, 14) + "expected a grasp type of the taxonomy (small_wrap, medium_wrap"));
  EXPECT_THAT(e, HasSubstr("found 'medium_warp' (did you mean 'medium_wrap'?)"));
}

TEST(SessionErrors, JointAnglesOutsideTheAgentsRange) {
  const std::string e = session_error(with_line(
      12, "    posture: {thumb: [0 deg, 0 deg, 90 deg], index: [0 deg, 0 deg, 0 deg], middle: [0 deg, 0 deg, 0 deg], "
          "ring: [0 deg, 0 deg, 0 deg], little: [0 deg, 0 deg, 0 deg]}"));
  EXPECT_THAT(e, HasSubstr(at(12, 37) + "expected an angle within the agent's range (thumb metacarpal between 0 deg "
                                        "and 70 deg), found 90 deg"));
}

TEST(SessionErrors, TheFirstKeyframeGivesEverything) {
  const std::string e = session_error(with_line(12, "    # no posture"));
  EXPECT_THAT(e, HasSubstr(at(9, 5) + "expected key 'posture' in the first keyframe"));
  EXPECT_THAT(session_error(with_line(11, "    fingertips: {thumb: [0 mm, 0 mm, 0 mm]}")),
              HasSubstr(at(11, 17) + "expected key 'index' in the fingertips"));
}

TEST(SessionErrors, GripAndFingertipsAreExclusive) {
  const std::string e = session_error(kSession + "    fingertips: {}\n");
  EXPECT_THAT(e, HasSubstr(at(15, 5) + "expected either grip or fingertips in one keyframe, found both"));
}

TEST(SessionErrors, ActeePlacement) {
  EXPECT_THAT(session_error(with_line(4, "actee: {file: ../actees/walnut.yaml, at: 60 mm, position: [0 mm, 0 mm, 0 mm]}")),
              HasSubstr(at(4, 49) + "expected either 'at' (on the fixed jaw) or 'position' (in the world), found both"));
  EXPECT_THAT(session_error(with_line(4, "actee: {file: ../actees/walnut.yaml, at: 20 cm}")),
              HasSubstr(at(4, 42) + "expected a distance on the arm, between 0 mm and 185 mm, found 200 mm"));
  EXPECT_THAT(session_error(with_line(4, "actee: {file: ../actees/coconut.yaml, at: 60 mm}")),
              HasSubstr(at(4, 43) + "expected an actee that fits between the jaws"));
}

TEST(SessionErrors, Options) {
  EXPECT_THAT(session_error(kSession + "timestep: 0 ms\n"), HasSubstr(at(15, 11) + "expected a value greater than zero"));
  EXPECT_THAT(session_error(kSession + "contact_tolerance: 1 s\n"), HasSubstr(at(15, 20) + "expected a length"));
}

TEST(Session, ReadsEveryFileAndDefaults) {
  const CompiledSession s = session_from(kSession);
  EXPECT_EQ(s.name, "test");
  EXPECT_EQ(s.model.timestep, 1e-3);
  EXPECT_EQ(s.model.contact_tolerance, 5e-4);
  EXPECT_TRUE(s.model.has_actee);
  ASSERT_EQ(s.files.size(), 6u);
  EXPECT_EQ(s.files[0], kSessionName);
  EXPECT_EQ(s.files[1], kSource + "/objects/nutcracker.yaml");
  EXPECT_EQ(s.files[5], kSource + "/rules/grasps.yaml");
  EXPECT_EQ(s.script.duration(), 1.0);
  const CompiledSession t = session_from(kSession + "timestep: 2 ms\ncontact_tolerance: 0.2 mm\n");
  EXPECT_EQ(t.model.timestep, 2e-3);
  EXPECT_EQ(t.model.contact_tolerance, 2e-4);
}

TEST(Session, InlineFilesAndNoActee) {
  std::string yaml = kSession;
  yaml.replace(yaml.find("actee: {file: ../actees/walnut.yaml, at: 60 mm}\n"), 48, "");
  yaml.replace(yaml.find("agent: ../agents/hand.yaml\n"), 27, "agent:\n" + indent(kHandYaml, 2));
  const CompiledSession s = session_from(yaml);
  EXPECT_FALSE(s.model.has_actee);
  EXPECT_EQ(s.model.agent_name, "test_hand");
  EXPECT_EQ(s.files.size(), 4u);  // session, object, rules, grasps
}

TEST(Session, InlineActeeInTheJaws) {
  const Tool tool = tools_of_every_pattern()[0];  // type 2, load at 40 mm
  std::string yaml = rig_session(tool, 0);
  yaml.insert(yaml.find("agent:\n"), "actee:\n  file:\n" + indent(nut_yaml(), 4) + "  at: 40 mm\n");
  const CompiledSession s = session_from(yaml);
  ASSERT_TRUE(s.model.has_actee);
  EXPECT_EQ(s.model.actee_name, "nut");
  EXPECT_NEAR(s.model.actee_start.translation().x(), 0.040, 1e-15);
  EXPECT_EQ(s.files.size(), 3u);  // session, rules, grasps
}

// ------------------------------------------------------------ run, trace, timeline

TEST(Run, TraceHasTheHeaderAndOneRowPerFrame) {
  const CompiledSession s = session_from(kSession);
  const Outputs out = run_with_writers(s);
  EXPECT_EQ(out.result.frames, 1000);
  EXPECT_DOUBLE_EQ(out.result.end_time, 1.0);
  EXPECT_THAT(out.trace, StartsWith("# units: t s, angle rad, effort_force N, actee_force N, effort_pos m, "
                                    "broken 0/1, grasped 0/1, held 0/1, contacts_object_actee count, actee_load N\n"
                                    "t,angle,effort_force,actee_force,effort_pos,broken,grasped,held,"
                                    "contacts_object_actee,actee_load\n0.001000,"));
  EXPECT_EQ(count_lines(out.trace), 1002);
  EXPECT_THAT(out.trace, HasSubstr("\n1.000000,"));
}

// The trace's rows are the same bytes as printf's "%.6f" and "%.9g", for
// ordinary and extreme values alike.
TEST(Run, TraceRowsAreTheBytesPrintfWouldWrite) {
  const std::vector<double> values = {0.0, -0.0, 1.0, -1.0, 0.1, 1.0 / 3, 2.0 / 3, 123456789.0, 1234567890123.0,
                                      1e-5, 1e-300, 5e-324, -2.5e-7, 1e15, 1e16, 1e308, -1.7976931348623157e308,
                                      0.5235987755982988, 378.00000000001, 999999999.5, 0.0000005,
                                      std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  std::mt19937_64 random(7);
  std::vector<double> all = values;
  for (int i = 0; i < 2000; ++i) {
    const double mantissa = std::uniform_real_distribution<double>(-10, 10)(random);
    all.push_back(std::ldexp(mantissa, std::uniform_int_distribution<int>(-60, 60)(random)));
  }
  // Each row twice and then with its fields swapped: the writer copies the
  // text of a value that has not changed since the row before.
  TraceWriter writer(nullptr);
  char row[TraceWriter::kMaxRow], expected[1024];
  for (size_t i = 0; i < all.size(); ++i) {
    const double a = all[i], b = all[(i * 7 + 3) % all.size()];
    const int n = static_cast<int>(i % 5) - 1;
    for (int pass = 0; pass < 3; ++pass) {
      const double x = pass < 2 ? a : b, y = pass < 2 ? b : a;
      const size_t len = writer.format_row(row, sizeof row, x, y, x, y, -x, 1, 0, n, static_cast<int>(i), y);
      std::snprintf(expected, sizeof expected, "%.6f,%.9g,%.9g,%.9g,%.9g,%d,%d,%d,%d,%.9g\n", x, y, x, y, -x, 1, 0,
                    n, static_cast<int>(i), y);
      ASSERT_EQ(std::string(row, len), std::string(expected)) << x << " " << y;
    }
  }
}

TEST(Run, TimelineHasOneJsonLinePerEvent) {
  const CompiledSession s = session_from(kSession);
  const Outputs out = run_with_writers(s);
  EXPECT_THAT(out.timeline,
              StartsWith("{\"t\":0.002000,\"event\":\"node_reached\",\"function\":\"pinch\",\"node\":0,"
                         "\"text\":\"grasping(agent, object)\"}\n"));
  EXPECT_THAT(out.timeline, HasSubstr("\"event\":\"inferred\",\"function\":\"pinch\",\"node\":2,"));
}

TEST(Run, PaperTongsInfersPinchHoldCarryCrashInOrder) {
  const Outputs out = run_with_writers(load_session(kSource + "/sessions/paper-tongs.yaml"));
  EXPECT_EQ(function_names(out.result), (std::vector<std::string>{"pinch", "hold", "carry", "crash"}));
}

TEST(Run, NothingIsInferredWithoutAnActeeInTheJawsOrWithoutAGrasp) {
  for (const char* name : {"too-large", "push-without-grasp"}) {
    const Outputs out = run_with_writers(load_session(kSource + "/sessions/" + name + ".yaml"));
    EXPECT_TRUE(out.result.inferences.empty()) << name;
  }
}

TEST(Run, TheSpongeIsCarriedAndNeverBreaks) {
  const Outputs out = run_with_writers(load_session(kSource + "/sessions/sponge-tongs.yaml"));
  const std::vector<std::string> names = function_names(out.result);
  EXPECT_THAT(names, ::testing::IsSupersetOf({"pinch", "hold", "carry"}));
  // Column 6 of every row is `broken`.
  std::istringstream rows(out.trace);
  std::string row;
  std::getline(rows, row);  // the units
  std::getline(rows, row);  // the header
  int n = 0;
  while (std::getline(rows, row)) {
    size_t comma = 0;
    for (int c = 0; c < 5; ++c) comma = row.find(',', comma) + 1;
    ASSERT_EQ(row[comma], '0') << row;
    ++n;
  }
  EXPECT_EQ(n, out.result.frames);
}

TEST(Run, AWholeSessionIsDeterministic) {
  const CompiledSession s = load_session(kSource + "/sessions/paper-tongs.yaml");
  const Outputs first = run_with_writers(s);
  const Outputs second = run_with_writers(s);
  EXPECT_GT(first.trace.size(), 100000u);
  EXPECT_EQ(first.trace, second.trace);
  EXPECT_EQ(first.timeline, second.timeline);
  // A session loaded again gives the same bytes too.
  EXPECT_EQ(run_with_writers(load_session(kSource + "/sessions/paper-tongs.yaml")).trace, first.trace);
}

}  // namespace
}  // namespace afford::test

namespace afford::test {
namespace {

// Watches every frame: the hand's push never above the limit in force.
struct HandLimitWatch : Observer {
  int frames = 0, over = 0, free_closing = 0;
  double peak = 0;
  void on_frame(const Model&, const State& s, const RuleSet&, const RuleState&) override {
    ++frames;
    if (s.effort_force > s.max_force) ++over;
    if (s.grasped && !s.blocked && s.omega < 0) ++free_closing;
    peak = std::max(peak, s.effort_force);
  }
};

TEST(HandLimit, NeverExceededInAnyFrameOfAnyShippedSession) {
  // From trace.csv (the effort column against the agent's max_force) and
  // from the state (against the limit in force, capped by the grasp type).
  int sessions = 0, free_closing = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(AFFORD_SOURCE_DIR) + "/sessions")) {
    if (entry.path().extension() != ".yaml") continue;
    const CompiledSession s = load_session(entry.path().string());
    ScriptedAgent agent(s.script);
    Capture trace;
    TraceWriter writer(trace.file);
    HandLimitWatch watch;
    Observer* observers[] = {&writer, &watch};
    run_session(s.model, *s.rules, agent, observers);
    const std::string csv = trace.text();
    std::istringstream rows(csv);
    std::string row;
    std::getline(rows, row);  // # units: ...
    std::getline(rows, row);  // header: t,angle,effort_force,...
    int checked = 0;
    while (std::getline(rows, row)) {
      const size_t a = row.find(','), b = row.find(',', a + 1), c = row.find(',', b + 1);
      ASSERT_LE(std::stod(row.substr(b + 1, c - b - 1)), s.model.max_force) << entry.path() << ": " << row;
      ++checked;
    }
    EXPECT_EQ(checked, watch.frames) << entry.path();
    EXPECT_EQ(watch.over, 0) << entry.path();
    free_closing += watch.free_closing;
    ++sessions;
  }
  EXPECT_GE(sessions, 5);
  EXPECT_GT(free_closing, 100);  // the sessions close the tools freely too
}

}  // namespace
}  // namespace afford::test
