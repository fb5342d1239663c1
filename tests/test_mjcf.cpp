// The MuJoCo scene of a session (mjcf/mjcf_scene.h): its numbers, worked by
// hand for the shipped nutcracker session, and its text. That MuJoCo loads
// and steps it is tests/mujoco/.
#include <gtest/gtest.h>

#include <cmath>

#include "mjcf_scene.h"
#include "session.h"
#include "test_util.h"
#include "test_sessions.h"

namespace afford {
namespace {
using test::paper_nutcracker;
using test::kSource;
using test::kDeg;


// objects/nutcracker.yaml: S_k 2000 N/m at S_p 10 mm, preload 1.5 N, rest 30 deg.
TEST(Mjcf, HingeSpringOfTheNutcracker) {
  const HingeSpring s = hinge_spring(paper_nutcracker().model);
  EXPECT_NEAR(s.stiffness, 2000 * 0.01 * 0.01, 1e-12);               // 0.2 N*m/rad
  EXPECT_NEAR(s.springref, 30 * kDeg + 1.5 / (2000 * 0.01), 1e-12);  // 0.5986 rad
}

// agents/hand.yaml: f_a 5 N/mm, max_force 400 N, no damping; the first
// grip puts the thumb at 160 mm in the medium wrap (430 N in
// rules/grasps.yaml, so the agent's 400 N holds); the squeeze of 45 mm
// at 2.9 s commands rest - 0.045 / 0.16 rad.
TEST(Mjcf, HandServoOfTheNutcracker) {
  const HandServo h = hand_servo(paper_nutcracker());
  ASSERT_TRUE(h.present);
  EXPECT_NEAR(h.lever_arm, 0.16, 1e-12);
  EXPECT_NEAR(h.kp, 5000 * 0.16 * 0.16, 1e-9);  // 128 N*m/rad
  EXPECT_EQ(h.kv, 0);
  EXPECT_EQ(h.max_force, 400);
  EXPECT_NEAR(h.max_torque, 400 * 0.16, 1e-12);  // 64 N*m
  const double rest = 30 * kDeg;
  ASSERT_EQ(h.schedule.size(), 5u);
  const std::vector<std::pair<double, double>> want = {
      {0, 30 * kDeg}, {0.4, rest}, {2.9, rest - 0.045 / 0.16}, {3.6, rest}, {4.0, 30 * kDeg}};
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(h.schedule[i].first, want[i].first, 1e-12) << i;
    EXPECT_NEAR(h.schedule[i].second, want[i].second, 1e-12) << i;
  }
}

// sessions/push-without-grasp.yaml never holds the tool (its grips have no
// index finger on the fixed arm, then an open hand of no grasp type): the
// engine's hand never turns the lever, so the scene has no hand servo.
TEST(Mjcf, NoHandServoWhenTheScriptNeverHoldsTheTool) {
  const CompiledSession s = load_session(kSource + "/sessions/push-without-grasp.yaml");
  EXPECT_FALSE(hand_servo(s).present);
  const std::string xml = mjcf_scene(s);
  EXPECT_EQ(xml.find("<actuator>"), std::string::npos);
  EXPECT_EQ(xml.find("hand_schedule"), std::string::npos);
  EXPECT_NE(xml.find("the script never holds the tool, so there is no hand servo"), std::string::npos);
}

// The walnut: 250 N/mm, 9 g; two contacts of 500 N/mm in series.
TEST(Mjcf, ActeeContactOfTheWalnut) {
  const Model& m = paper_nutcracker().model;
  const ActeeContact c = actee_contact(m);
  EXPECT_EQ(c.impedance, 0.99);
  EXPECT_NEAR(c.stiffness, 2 * 250000 * (1 - 0.99) / 0.009, 1e-6);  // 5.56e5 1/s^2
  // omega = sqrt(2 * 250000 / 0.009) = 7454 rad/s: 8 steps of 125 us a frame.
  EXPECT_EQ(substeps_per_frame(m), 8);
}

TEST(Mjcf, SceneTextOfTheNutcracker) {
  const std::string xml = mjcf_scene(paper_nutcracker());
  for (const char* want :
       {"<option timestep=\"0.000125\" gravity=\"0 0 0\"", "range=\"0 0.523598776\"", "stiffness=\"0.2\"",
        "springref=\"0.598598776\"", "frictionloss=\"0.01\" damping=\"0\" armature=\"0\"", "gainprm=\"128\"",
        "biasprm=\"0 -128 0\"", "forcerange=\"-64 0\"", "<numeric name=\"actee_limit\" size=\"1\" data=\"378\"/>",
        "<numeric name=\"actee_breaks\" size=\"1\" data=\"1\"/>",
        "<numeric name=\"hand_schedule\" size=\"10\" data=\"0 0.523598776 0.4 0.523598776 2.9 0.242348776 3.6 "
        "0.523598776 4 0.523598776\"/>",
        "<body name=\"actee\" pos=\"0.06 0.0141 0.1\"", "type=\"ellipsoid\" size=\"0.018 0.0141 0.0141\"",
        "<geom name=\"part:moving_arm\" type=\"box\" size=\"0.0925 0.006 0.008\" pos=\"0.0925 0.006 0\""}) {
    EXPECT_NE(xml.find(want), std::string::npos) << want;
  }
  // An XML comment may not hold "--": the header stays a comment.
  const size_t end = xml.find("-->");
  EXPECT_EQ(xml.substr(4, end - 4).find("--"), std::string::npos);
  EXPECT_EQ(xml, mjcf_scene(paper_nutcracker()));  // deterministic
}

}  // namespace
}  // namespace afford
