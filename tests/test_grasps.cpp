// The grasp taxonomy (paper Fig. 7): loading and its errors, the shipped
// rules/grasps.yaml, classifying postures, the object grasp that needs a
// posture of the taxonomy, the grasp type's force limit, and the hand's
// grasp of an actee (Sec. 4.3.3).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_util.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <unistd.h>

#include "grasps.h"
#include "rig.h"
#include "validate.h"

namespace afford::test {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

using Posture = std::array<std::array<double, kJoints>, kFingers>;

// A small valid taxonomy; line numbers in the comments.
const std::string kTwoTypes =
    "grasps:\n"                                  // 1
    "  - name: wrap\n"                           // 2
    "    kind: power\n"                          // 3
    "    description: A wrap.\n"                 // 4
    "    max_force: 400 N\n"                     // 5
    "    fingers:\n"                             // 6
    "      thumb: {distal: [0 deg, 40 deg]}\n"   // 7
    "      index:\n"                             // 8
    "        distal: [10 deg, 60 deg]\n"         // 9
    "        proximal: [40 deg, 80 deg]\n"       // 10
    "  - name: pinch\n"                          // 11
    "    kind: precision\n"                      // 12
    "    description: A pinch.\n"                // 13
    "    max_force: 60 N\n"                      // 14
    "    fingers:\n"                             // 15
    "      thumb: {distal: [40 deg, 80 deg]}\n";  // 16


std::string grasps_error(const std::string& text) {
  try {
    (void)read_grasps(load_yaml_string(text, "bad.yaml"));
  } catch (const DataError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a DataError, nothing was thrown";
  return "";
}

std::vector<GraspTypeSpec> shipped() { return load_grasps(kSource + "/rules/grasps.yaml"); }

int index_of(const std::vector<GraspTypeSpec>& grasps, const std::string& name) {
  for (size_t i = 0; i < grasps.size(); ++i) {
    if (grasps[i].name == name) return static_cast<int>(i);
  }
  ADD_FAILURE() << "no grasp type " << name;
  return -1;
}

// The middle of every listed range; free joints straight.
Posture middle_of(const GraspTypeSpec& g) {
  Posture p{};
  for (size_t f = 0; f < kFingers; ++f) {
    for (size_t j = 0; j < kJoints; ++j) {
      if (g.range[f][j]) p[f][j] = 0.5 * (g.range[f][j]->min + g.range[f][j]->max);
    }
  }
  return p;
}

Posture posture_of(const std::vector<GraspTypeSpec>& grasps, const std::string& name) {
  return middle_of(grasps[static_cast<size_t>(index_of(grasps, name))]);
}

// The rig's type 2 tool (no actee) with the test hand and a taxonomy.
Model tool_model(const std::vector<GraspTypeSpec>& grasps) {
  const ObjectSpec o = object_from(tools_of_every_pattern()[0].yaml);
  const AgentSpec h = hand();
  ModelOptions options;
  options.grasps = grasps;
  return compile(o, nullptr, &h, options);
}

// ---------------------------------------------------------------- loading

TEST(GraspsLoad, ValidDocument) {
  const auto g = read_grasps(load_yaml_string(kTwoTypes, "good.yaml"));
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].name, "wrap");
  EXPECT_EQ(g[0].kind, GraspKind::power);
  EXPECT_EQ(g[1].kind, GraspKind::precision);
  EXPECT_DOUBLE_EQ(g[0].max_force, 400.0);
  ASSERT_TRUE(g[0].range[1][1].has_value());
  EXPECT_NEAR(g[0].range[1][1]->min, 40 * kDeg, 1e-15);
  EXPECT_NEAR(g[0].range[1][1]->max, 80 * kDeg, 1e-15);
  EXPECT_FALSE(g[0].range[1][2].has_value());  // index metacarpal: free
  EXPECT_FALSE(g[0].range[2][0].has_value());  // middle finger: free
  EXPECT_EQ(g[1].loc.str(), "good.yaml:11:5");
}

TEST(GraspsLoad, UnknownKeyWithDidYouMean) {
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "    max_force: 400 N", "    max_forse: 400 N")),
            "bad.yaml:5:5: expected one of the keys of a grasp type (name, kind, description, max_force, "
            "fingers), found 'max_forse' (did you mean 'max_force'?)");
  EXPECT_THAT(grasps_error(replace_once(kTwoTypes, "      index:", "      indx:")),
              StartsWith("bad.yaml:8:7: expected one of the keys of the fingers of wrap"));
  EXPECT_THAT(grasps_error(replace_once(kTwoTypes, "      index:", "      indx:")),
              HasSubstr("found 'indx' (did you mean 'index'?)"));
  EXPECT_THAT(grasps_error(replace_once(kTwoTypes, "        proximal:", "        proximl:")),
              StartsWith("bad.yaml:10:9: expected one of the keys of the index of wrap (distal, proximal, "
                         "metacarpal), found 'proximl' (did you mean 'proximal'?)"));
  EXPECT_THAT(grasps_error(replace_once(kTwoTypes, "grasps:", "grasp:")),
              StartsWith("bad.yaml:1:1: expected one of the keys of a grasps file (grasps), found 'grasp' "
                         "(did you mean 'grasps'?)"));
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "kind: precision", "kind: precison")),
            "bad.yaml:12:11: expected one of power, precision, found 'precison' (did you mean 'precision'?)");
}

TEST(GraspsLoad, MinimumMustBeBelowMaximum) {
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "distal: [10 deg, 60 deg]", "distal: [60 deg, 10 deg]")),
            "bad.yaml:9:26: expected a maximum above the minimum (60 deg), found '10 deg'");
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "distal: [10 deg, 60 deg]", "distal: [60 deg, 60 deg]")),
            "bad.yaml:9:26: expected a maximum above the minimum (60 deg), found '60 deg'");
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "distal: [10 deg, 60 deg]", "distal: [10 deg]")),
            "bad.yaml:9:17: expected a pair [min, max] of angles, found a sequence of 1");
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "distal: [10 deg, 60 deg]", "distal: [10 deg, 4 rad]")),
            "bad.yaml:9:26: expected an angle between -180 deg and 180 deg, found '4 rad'");
}

TEST(GraspsLoad, DuplicateName) {
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "  - name: pinch", "  - name: wrap")),
            "bad.yaml:11:11: expected a grasp type name not used before, found 'wrap' again (first at "
            "bad.yaml:2:5)");
}

TEST(GraspsLoad, WrongUnits) {
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "proximal: [40 deg, 80 deg]", "proximal: [40 mm, 80 deg]")),
            "bad.yaml:10:20: expected an angle (e.g. '30 deg'), found '40 mm', a length (e.g. '18 mm')");
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "proximal: [40 deg, 80 deg]", "proximal: [40, 80 deg]")),
            "bad.yaml:10:20: expected an angle (e.g. '30 deg'), found '40', a number without a unit");
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "max_force: 60 N", "max_force: 60 deg")),
            "bad.yaml:14:16: expected a force (e.g. '30 N'), found '60 deg', an angle (e.g. '30 deg')");
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "max_force: 60 N", "max_force: 0 N")),
            "bad.yaml:14:16: expected a value greater than zero, found '0 N'");
}

TEST(GraspsLoad, StructureErrors) {
  // A type that constrains nothing would take the open hand for a grasp.
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "    fingers:\n      thumb: {distal: [40 deg, 80 deg]}\n",
                                      "    fingers: {}\n")),
            "bad.yaml:15:14: expected at least one finger with a joint range, found none");
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "thumb: {distal: [40 deg, 80 deg]}", "thumb: {}")),
            "bad.yaml:16:14: expected at least one of distal, proximal, metacarpal, found none");
  EXPECT_EQ(grasps_error(replace_once(kTwoTypes, "    description: A pinch.\n", "")),
            "bad.yaml:11:5: expected key 'description' in a grasp type, found no such key");
  EXPECT_EQ(grasps_error("grasps: []\n"), "bad.yaml:1:9: expected a sequence of grasp types, found a sequence of 0");
}

TEST(GraspsLoad, CheckAcceptsGraspFiles) {
  EXPECT_EQ(validate_file(kSource + "/rules/grasps.yaml"), "grasp taxonomy, 6 types");
  const auto path = std::filesystem::temp_directory_path() / ("afford_grasps_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(path) << replace_once(kTwoTypes, "max_force: 60 N", "max_force: 60 deg");
  try {
    (void)validate_file(path.string());
    ADD_FAILURE() << "expected a DataError";
  } catch (const DataError& e) {
    EXPECT_THAT(e.what(), StartsWith(path.string() + ":14:16: expected a force"));
  }
  std::filesystem::remove(path);
}

// ---------------------------------------------------------------- the shipped taxonomy

TEST(GraspsShipped, LoadsWithPlausibleForces) {
  const auto g = shipped();
  ASSERT_EQ(g.size(), 6u);
  for (const char* name : {"small_wrap", "medium_wrap", "power_sphere", "lateral_pinch", "tip_pinch", "tripod"}) {
    EXPECT_GE(index_of(g, name), 0);
  }
  for (const GraspTypeSpec& t : g) {
    EXPECT_GT(t.max_force, 40.0) << t.name;
    EXPECT_LT(t.max_force, 610.0) << t.name;  // Crosby & Wehbe's men's best grip
    for (size_t f = 0; f < kFingers; ++f) {
      for (size_t j = 0; j < kJoints; ++j) {
        if (!t.range[f][j]) continue;
        // Within the shipped hand's joint limits (agents/hand.yaml).
        EXPECT_GE(t.range[f][j]->min, (f == 0 ? (j == 0 ? -20 : 0) : (j == 2 ? -45 : 0)) * kDeg - 1e-12) << t.name;
        EXPECT_LE(t.range[f][j]->max, (f == 0 ? std::array{80, 50, 70}[j] : std::array{90, 100, 90}[j]) * kDeg + 1e-12)
            << t.name;
      }
    }
  }
  // Each description is whole: a plain ' #' would start a YAML comment
  // and cut it at "Cutkosky 1989"; every one ends its sentence.
  for (const GraspTypeSpec& t : g) EXPECT_TRUE(t.description.ends_with(".")) << t.name << ": " << t.description;
  // Pinches are far weaker than grips (Mathiowetz 1985).
  EXPECT_LT(g[static_cast<size_t>(index_of(g, "tip_pinch"))].max_force,
            g[static_cast<size_t>(index_of(g, "lateral_pinch"))].max_force);
  EXPECT_LT(g[static_cast<size_t>(index_of(g, "lateral_pinch"))].max_force,
            g[static_cast<size_t>(index_of(g, "medium_wrap"))].max_force);
}

TEST(GraspsShipped, EveryTypesMiddleClassifiesAsItself) {
  const auto g = shipped();
  const Model m = tool_model(g);
  for (size_t i = 0; i < g.size(); ++i) {
    EXPECT_EQ(classify_grasp(m, middle_of(g[i])), static_cast<int>(i)) << g[i].name;
  }
}

TEST(GraspsShipped, OpenHandAndFistAreNoGrasp) {
  const Model m = tool_model(shipped());
  EXPECT_EQ(classify_grasp(m, Posture{}), -1);  // straight fingers
  Posture fist{};
  fist[0] = {80 * kDeg, 50 * kDeg, 0};
  for (size_t f = 1; f < kFingers; ++f) fist[f] = {90 * kDeg, 100 * kDeg, 90 * kDeg};
  EXPECT_EQ(classify_grasp(m, fist), -1);  // nothing to hold: the thumb's end joint is folded over
}

// ---------------------------------------------------------------- classification

TEST(GraspsClassify, FirstMatchingTypeInFileOrder) {
  const auto g = read_grasps(load_yaml_string(kTwoTypes, "good.yaml"));
  const Model m = tool_model(g);
  Posture p{};
  p[0][0] = 20 * kDeg;                   // thumb distal: the wrap's
  p[1] = {30 * kDeg, 60 * kDeg, 0};      // index distal, proximal
  EXPECT_EQ(classify_grasp(m, p), 0);
  p[1][1] = 85 * kDeg;                   // index proximal out of the wrap's range
  EXPECT_EQ(classify_grasp(m, p), -1);
  p[0][0] = 60 * kDeg;                   // the pinch lists only the thumb
  EXPECT_EQ(classify_grasp(m, p), 1);
  p[0][0] = 40 * kDeg;                   // on both ranges' ends: the first type
  p[1][1] = 60 * kDeg;
  EXPECT_EQ(classify_grasp(m, p), 0);
  p[4] = {1.0, -0.5, 1.5};               // free fingers do not matter
  EXPECT_EQ(classify_grasp(m, p), 0);
  p[0][0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(classify_grasp(m, p), -1);
  // Without a taxonomy nothing is classified.
  EXPECT_EQ(classify_grasp(tool_model({}), middle_of(g[0])), -1);
}

TEST(GraspsClassify, ModelHoldsTheTaxonomyFlat) {
  const auto g = shipped();
  const Model m = tool_model(g);
  ASSERT_EQ(m.grasp_name.size(), g.size());
  EXPECT_EQ(m.grasp_name[1], "medium_wrap");
  EXPECT_EQ(m.grasp_kind[4], GraspKind::precision);
  EXPECT_EQ(m.grasp_joint_min.size(), g.size() * kFingers * kJoints);
  EXPECT_EQ(m.grasp_joint_max.size(), g.size() * kFingers * kJoints);
  EXPECT_TRUE(std::isinf(m.grasp_joint_min[static_cast<size_t>(index_of(g, "tip_pinch")) * 15 + 2 * 3]));
}

// ---------------------------------------------------------------- the object grasp

TEST(GraspsObject, OpenHandOnTheArmsDoesNotGrasp) {
  const auto g = shipped();
  const Model m = tool_model(g);
  Rig open(m, tools_of_every_pattern()[0].effort);  // the rig's hand is straight
  ASSERT_GE(open.state().agent_object.count, 2);      // thumb and index on the arms
  EXPECT_EQ(open.state().grasp_type, -1);
  EXPECT_FALSE(open.state().grasped);
  open.push(0.01);
  EXPECT_EQ(open.state().theta, m.theta_rest);  // the lever does not follow the thumb

  Rig wrap(m, tools_of_every_pattern()[0].effort);
  wrap.sample().joint = posture_of(g, "medium_wrap");
  wrap.frame();
  EXPECT_EQ(wrap.state().grasp_type, index_of(g, "medium_wrap"));
  EXPECT_TRUE(wrap.state().grasped);
  wrap.push(0.01);
  EXPECT_LT(wrap.state().theta, m.theta_rest - 0.05);
  // Opening the hand lets go.
  wrap.sample().joint = Posture{};
  wrap.frame();
  EXPECT_FALSE(wrap.state().grasped);

  // Without a taxonomy the contacts alone decide (the paper's default).
  const Model plain = tool_model({});
  Rig contact_only(plain, tools_of_every_pattern()[0].effort);
  EXPECT_TRUE(contact_only.state().grasped);
}

TEST(GraspsObject, GraspTypeCapsTheEffortForce) {
  const auto g = shipped();
  const Model m = tool_model(g);
  const double effort = tools_of_every_pattern()[0].effort;
  struct Case {
    const char* type;
    double cap;  // N
  };
  // The test hand's max_force is 400 N; a medium wrap allows 430 N.
  for (const Case& c : {Case{"tip_pinch", 65.0}, Case{"lateral_pinch", 90.0}, Case{"medium_wrap", 400.0}}) {
    Rig rig(m, effort);
    rig.sample().joint = posture_of(g, c.type);
    rig.frame();
    ASSERT_TRUE(rig.state().grasped) << c.type;
    EXPECT_DOUBLE_EQ(rig.state().max_force, c.cap) << c.type;
    // Closed onto the stop, then 30 mm on: f_a = 20 N/mm would make 600 N.
    rig.push(effort * (m.theta_rest - m.theta_min) + 0.03, 5e-5);
    EXPECT_TRUE(rig.state().at_limit) << c.type;
    EXPECT_NEAR(rig.state().effort_force, c.cap, 1e-9) << c.type;
  }
}

// ---------------------------------------------------------------- the hand's grasp of an actee

class ActeeInHand : public ::testing::Test {
 protected:
  // A free nut (radius 10 mm) 0.5 m above the tool, out of its reach.
  Model model(bool taxonomy) const {
    const ObjectSpec o = object_from(tools_of_every_pattern()[0].yaml);
    const ActeeSpec a = actee_from(nut_yaml());
    const AgentSpec h = hand();
    ModelOptions options;
    options.actee.in_jaws = false;
    options.actee.world.translation() = kCentre;
    if (taxonomy) options.grasps = shipped();
    return compile(o, &a, &h, options);
  }

  // Fingertips at the given angles (deg) about the nut's z axis, touching
  // it; unplaced fingers far away. The hand's origin is at the nut's centre.
  static Sample around(const Model& m, std::initializer_list<std::pair<int, double>> fingers) {
    Sample s;
    s.hand.translation() = kCentre;
    for (size_t f = 0; f < kFingers; ++f) s.fingertip[f] = kCentre + Eigen::Vector3d(0, 0, 1.0 + 0.1 * static_cast<double>(f));
    for (const auto& [f, deg] : fingers) {
      const double reach = 0.010 + m.tip_radius[static_cast<size_t>(f)] - 1e-4;
      s.fingertip[static_cast<size_t>(f)] =
          kCentre + reach * Eigen::Vector3d(std::cos(deg * kDeg), std::sin(deg * kDeg), 0);
    }
    return s;
  }

  // Runs two frames in place (touch, then grasp), then moves the hand and
  // the fingertips by `move` over 100 frames. Returns how far the nut went.
  static Eigen::Vector3d carry(const Model& m, State& st, Sample s, const Eigen::Vector3d& move) {
    for (int i = 0; i < 2; ++i) {
      s.t += m.timestep;
      step(m, st, s);
    }
    const Eigen::Vector3d before = st.actee_pose.translation();
    for (int i = 0; i < 100; ++i) {
      s.t += m.timestep;
      s.hand.translation() += move / 100;
      for (auto& tip : s.fingertip) tip += move / 100;
      step(m, st, s);
    }
    return st.actee_pose.translation() - before;
  }

  static inline const Eigen::Vector3d kCentre{0.05, 0.0, 0.5};
  const Eigen::Vector3d move_{0.05, 0.0, 0.10};
};

TEST_F(ActeeInHand, ThreeOpposedFingertipsInATaxonomyPostureCarryIt) {
  const auto g = shipped();
  const Model m = model(true);
  auto st = make_state(m);
  Sample s = around(m, {{0, 180.0}, {1, 30.0}, {2, -30.0}});  // thumb against index and middle
  s.joint = posture_of(g, "tripod");
  const Eigen::Vector3d moved = carry(m, *st, s, move_);
  EXPECT_TRUE(st->actee_in_hand);
  EXPECT_EQ(st->grasp_type, index_of(g, "tripod"));
  EXPECT_NEAR((moved - move_).norm(), 0, 1e-12);
  EXPECT_EQ(st->agent_actee.count, 3);  // the fingers still touch it where it went
  EXPECT_FALSE(st->grasped);            // the tool is elsewhere

  // The fingers let go: the nut stays where it was put down.
  s = around(m, {});
  s.hand.translation() = st->hand.translation();
  for (auto& tip : s.fingertip) tip += move_;
  const Eigen::Vector3d after = carry(m, *st, s, move_);
  EXPECT_FALSE(st->actee_in_hand);
  EXPECT_NEAR(after.norm(), 0, 1e-15);
}

TEST_F(ActeeInHand, TwoFingertipsDoNotGraspIt) {
  const auto g = shipped();
  const Model m = model(true);
  auto st = make_state(m);
  Sample s = around(m, {{0, 180.0}, {1, 0.0}});
  s.joint = posture_of(g, "tip_pinch");
  const Eigen::Vector3d moved = carry(m, *st, s, move_);
  EXPECT_FALSE(st->actee_in_hand);
  EXPECT_EQ(moved.norm(), 0);
}

TEST_F(ActeeInHand, ThreeFingertipsOnOneSideDoNotGraspIt) {
  const auto g = shipped();
  const Model m = model(true);
  auto st = make_state(m);
  Sample s = around(m, {{0, 150.0}, {1, 180.0}, {2, -150.0}});  // 60 deg apart at most: they only push
  s.joint = posture_of(g, "tripod");
  const Eigen::Vector3d moved = carry(m, *st, s, move_);
  EXPECT_EQ(st->agent_actee.count, 0);  // the hand moved away from it
  EXPECT_FALSE(st->actee_in_hand);
  EXPECT_EQ(moved.norm(), 0);
}

TEST_F(ActeeInHand, PostureMustBeInTheTaxonomyWhenThereIsOne) {
  // Open hand, fingertips around the nut: no grasp with a taxonomy ...
  {
    const Model m = model(true);
    auto st = make_state(m);
    const Eigen::Vector3d moved = carry(m, *st, around(m, {{0, 180.0}, {1, 30.0}, {2, -30.0}}), move_);
    EXPECT_FALSE(st->actee_in_hand);
    EXPECT_EQ(moved.norm(), 0);
  }
  // ... and contact alone decides without one.
  {
    const Model m = model(false);
    auto st = make_state(m);
    const Eigen::Vector3d moved = carry(m, *st, around(m, {{0, 180.0}, {1, 30.0}, {2, -30.0}}), move_);
    EXPECT_TRUE(st->actee_in_hand);
    EXPECT_NEAR((moved - move_).norm(), 0, 1e-12);
  }
}

TEST_F(ActeeInHand, HashSeesTheHandsGrasp) {
  const Model m = model(false);
  auto a = make_state(m);
  auto b = make_state(m);
  Sample s = around(m, {{0, 180.0}, {1, 30.0}, {2, -30.0}});
  for (int i = 0; i < 2; ++i) {
    s.t += m.timestep;
    step(m, *a, s);
    step(m, *b, s);
  }
  ASSERT_TRUE(a->actee_in_hand);
  EXPECT_EQ(state_hash(*a), state_hash(*b));
  b->actee_in_hand = false;
  EXPECT_NE(state_hash(*a), state_hash(*b));
}

}  // namespace
}  // namespace afford::test
