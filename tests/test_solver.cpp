// The lever-spring solver: moment balance for every lever pattern, limits,
// breaking, compliance, the optional effect terms, and the grasp.
#include <gtest/gtest.h>

#include <cmath>

#include "rig.h"
#include "stages.h"

namespace afford::test {
namespace {

// Spring force from the spec alone: free at the rest angle, plus the preload.
double expected_spring_force(const ObjectSpec& o, double theta) {
  return o.spring.constant * std::abs(o.spring.position) * (o.lever.theta_rest - theta) + o.spring.preload;
}

TEST(Solver, ContactAngleMatchesWedgeGeometry) {
  // A sphere of radius R resting on the fixed jaw at r touches the moving
  // jaw's inner face when tan(theta/2) = R / r.
  const std::string nut = nut_yaml();
  for (double r : {0.030, 0.040, 0.060}) {
    const Model m = model_of(tools_of_every_pattern()[0].yaml, &nut, r);
    const auto s = make_state(m);
    ASSERT_TRUE(s->between_jaws);
    EXPECT_NEAR(s->contact_angle, 2 * std::atan(0.010 / r), 1e-9) << "r = " << r;
  }
}

TEST(Solver, MomentBalanceWithoutActeeForEveryPattern) {
  for (const Tool& tool : tools_of_every_pattern()) {
    const ObjectSpec o = object_from(tool.yaml);
    const Model m = model_of(tool.yaml, nullptr, 0);
    for (double fraction : {0.9, 0.6, 0.3}) {
      Rig rig(m, tool.effort);
      ASSERT_TRUE(rig.state().grasped) << tool.name;
      rig.close_to(fraction * m.theta_max);
      const State& s = rig.state();
      const double b = std::abs(s.effort_distance);
      EXPECT_NEAR(b, std::abs(tool.effort), 1e-4) << tool.name;
      // F_ag * D_ag = S_k * d * D_s, with nothing left for the stop.
      EXPECT_NEAR(s.effort_force * b, expected_spring_force(o, s.theta) * std::abs(o.spring.position), 1e-9)
          << tool.name << " at " << s.theta;
      EXPECT_NEAR(s.torque[kStop], 0, 1e-12) << tool.name;
      // The hand is a spring between the tracked thumb and the arm: its
      // push is f_a times how far the arm lags the thumb, along the arc.
      EXPECT_NEAR(s.effort_force, m.force_gain * b * (s.theta - s.theta_command), 1e-9) << tool.name;
      EXPECT_GT(s.theta, s.theta_command) << tool.name;  // free closing lags the thumb
      EXPECT_NEAR(s.theta_command, fraction * m.theta_max, 1e-3) << tool.name;
    }
  }
}

TEST(Solver, ActeeForceFollowsMomentBalanceForEveryPattern) {
  const std::string nut = nut_yaml(1e4);  // too strong to break here
  for (const Tool& tool : tools_of_every_pattern()) {
    const ObjectSpec o = object_from(tool.yaml);
    const Model m = model_of(tool.yaml, &nut, tool.load);
    Rig rig(m, tool.effort);
    ASSERT_TRUE(rig.state().between_jaws) << tool.name;
    // The load's lever arm is where the jaw touches the nut: a sphere resting
    // on a jaw face through the hinge is touched at its centre's distance,
    // the two tangents from the hinge being equally long.
    EXPECT_NEAR(rig.state().load_distance, tool.load, 1e-8) << tool.name;
    rig.close_to(rig.state().contact_angle);
    for (int i = 0; i < 3; ++i) {
      rig.push(0.004);  // the thumb goes on past the blocked arm
      const State& s = rig.state();
      ASSERT_TRUE(s.blocked) << tool.name;
      const double a = std::abs(s.load_distance), b = std::abs(s.effort_distance);
      const double spring_torque = expected_spring_force(o, s.theta) * std::abs(o.spring.position);
      // The actee's reaction: its stiffness times the jaw's travel into it,
      // stiffened by h / (h - deflection) (the nut is h = 20 mm across).
      const double deflection = a * (s.contact_angle - s.theta);
      EXPECT_NEAR(s.actee_thickness, 0.020, 1e-12);
      EXPECT_NEAR(s.actee_force, m.actee_stiffness * deflection * 0.020 / (0.020 - deflection), 1e-9);
      // F_ag * D_ag = S_k * d * D_s + F_acr * D_ac (the paper's eq. 5 would
      // have the ratios the other way round).
      EXPECT_NEAR(s.effort_force * b, spring_torque + s.actee_force * a, 1e-9 * (1 + s.effort_force)) << tool.name;
      EXPECT_NEAR(s.torque[kStop], 0, 1e-9);
      EXPECT_NEAR(s.actee_force, (s.effort_force * b - spring_torque) / a, 1e-6) << tool.name;
    }
    const State& s = rig.state();
    const double gain = s.actee_force / s.effort_force;
    const std::string pattern = tool.name;
    if (pattern == "type2" || pattern == "type1-power") {
      EXPECT_GT(gain, 1.1) << pattern;
    } else if (pattern == "type3" || pattern == "type1-distance") {
      EXPECT_LT(gain, 0.9) << pattern;
    } else {
      EXPECT_NEAR(gain, 1.0, 0.1) << pattern;
    }
    EXPECT_STREQ(pattern_name(s.pattern), tool.name);
  }
}

TEST(Solver, AngleLimitsHold) {
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, nullptr, 0);
  Rig rig(m, tool.effort);
  rig.push(0.30);  // far past fully closed
  EXPECT_EQ(rig.state().theta, m.theta_min);
  EXPECT_TRUE(rig.state().at_limit);
  EXPECT_GT(rig.state().torque[kStop], 0);            // the stop takes the squeeze
  EXPECT_LE(rig.state().effort_force, m.max_force);  // the hand's limit
  EXPECT_NEAR(rig.state().effort_force, m.max_force, 1e-9);
  const double to_close = m.theta_rest * std::abs(tool.effort);  // thumb travel from rest to closed
  rig.push(-(0.30 - to_close - 0.005));  // back to 5 mm past closed: still pressing, less
  EXPECT_EQ(rig.state().theta, m.theta_min);
  EXPECT_LT(rig.state().effort_force, m.max_force);
  EXPECT_GT(rig.state().torque[kStop], 0);
  rig.push(-0.02);  // and off the stop
  EXPECT_GT(rig.state().theta, m.theta_min);
  EXPECT_NEAR(rig.state().torque[kStop], 0, 1e-12);
  rig.push(-0.60);  // far past fully open: the thumb leaves the arm
  EXPECT_LE(rig.state().theta, m.theta_max);
  EXPECT_FALSE(rig.state().grasped);
  EXPECT_EQ(rig.state().theta, m.theta_rest);
}

TEST(Solver, BreaksOnTheFirstFrameAboveTheLimit) {
  const std::string nut = nut_yaml(300);
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, &nut, tool.load);
  Rig rig(m, tool.effort);
  rig.close_to(rig.state().contact_angle);
  double previous_load = 0;
  int frames = 0;
  while (rig.state().condition != ActeeCondition::broken && frames < 100000) {
    previous_load = rig.state().actee_load;
    EXPECT_LE(previous_load, 300.0);
    rig.push(1e-6, 1e-6);
    ++frames;
  }
  ASSERT_EQ(rig.state().condition, ActeeCondition::broken);
  EXPECT_LE(previous_load, 300.0);
  EXPECT_GT(rig.state().actee_load, 300.0);
  EXPECT_LT(rig.state().actee_load, 300.5);  // small steps: just above
  EXPECT_EQ(rig.state().broke_at, rig.state().t);
  rig.push(1e-4);  // the shell gave way: the jaws close freely
  EXPECT_EQ(rig.state().actee_force, 0);
  EXPECT_FALSE(rig.state().blocked);
  EXPECT_EQ(rig.state().object_actee.count, 0);
}

TEST(Solver, ExactlyAtTheLimitDoesNotBreak) {
  const std::string nut = nut_yaml(300);
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, &nut, tool.load);
  auto s = make_state(m);
  s->blocked = true;
  s->actee_force = 300.0;  // the force direction is the squeeze direction: load == force
  update_actee(m, *s);
  EXPECT_EQ(s->condition, ActeeCondition::squeezed);
  s->actee_force = std::nextafter(300.0, 1e9);
  update_actee(m, *s);
  EXPECT_EQ(s->condition, ActeeCondition::broken);
}

TEST(Solver, OnlyTheForceAlongTheActeeDirectionCounts) {
  std::string nut = nut_yaml(300);
  nut.replace(nut.find("[0, 1, 0]"), 9, "[0, 1, 1]");  // 45 degrees off the squeeze
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, &nut, tool.load);
  auto s = make_state(m);
  s->blocked = true;
  s->actee_force = 400.0;
  update_actee(m, *s);
  EXPECT_NEAR(s->actee_load, 400.0 / std::sqrt(2.0), 1e-9);
  EXPECT_EQ(s->condition, ActeeCondition::squeezed);
}

TEST(Solver, SpongeDeformsAndNeverBreaks) {
  const std::string sponge = kSpongeYaml;
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, &sponge, 0.060);
  Rig rig(m, tool.effort);
  rig.close_to(rig.state().contact_angle);
  for (int i = 0; i < 40; ++i) {
    rig.push(0.005);
    EXPECT_NE(rig.state().condition, ActeeCondition::broken);
    EXPECT_LE(rig.state().effort_force, m.max_force + 1e-9);
  }
  EXPECT_EQ(rig.state().condition, ActeeCondition::squeezed);
  EXPECT_GT(rig.state().actee_load, m.actee_limit);        // squeezed well past its limit
  EXPECT_GT(rig.state().actee_compression, 0.005);         // and visibly deformed
}

TEST(Solver, ThumbSpeedIsItsAdvanceAlongTheRotationDirection) {
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, nullptr, 0);
  Rig rig(m, tool.effort);
  const double theta = rig.state().theta;
  const double c = std::cos(theta), s = std::sin(theta);
  const double command = rig.state().theta_command;
  rig.sample().fingertip[0] += Eigen::Vector3d(s, -c, 0) * 3e-5;  // along L_d
  rig.frame();
  EXPECT_NEAR(rig.state().thumb_speed, 3e-5 / m.timestep, 1e-9);  // eq. 2
  EXPECT_NEAR(rig.state().theta_command, command - 3e-5 / std::abs(rig.state().effort_distance), 1e-12);
  EXPECT_LT(rig.state().theta, theta);  // the arm follows, through the hand
  // Motion along the arm does not move the hand's target (eq. 1 projects it away).
  const double theta2 = rig.state().theta;
  const double command2 = rig.state().theta_command;
  rig.sample().fingertip[0] += Eigen::Vector3d(std::cos(theta2), std::sin(theta2), 0) * 1e-4;
  rig.frame();
  EXPECT_NEAR(rig.state().theta_command, command2, 1e-12);
}

TEST(Solver, GraspedObjectAndHeldActeeMoveWithTheHand) {
  const std::string nut = nut_yaml(1e4);
  const Tool tool = tools_of_every_pattern()[1];  // tongs
  const Model m = model_of(tool.yaml, &nut, tool.load);
  Rig rig(m, tool.effort);
  rig.close_to(rig.state().contact_angle);
  rig.push(0.003);
  ASSERT_TRUE(rig.state().held);
  const Eigen::Vector3d actee_before = rig.state().actee_pose.translation();
  const Eigen::Vector3d move(0.05, 0.0, 0.10);
  for (int i = 1; i <= 100; ++i) {
    Sample& sample = rig.sample();
    sample.hand.translation() += move / 100;
    for (auto& tip : sample.fingertip) tip += move / 100;
    rig.frame();
  }
  EXPECT_TRUE(rig.state().grasped);
  EXPECT_TRUE(rig.state().held);
  EXPECT_NEAR((rig.state().actee_pose.translation() - actee_before - move).norm(), 0, 1e-9);
  EXPECT_EQ(rig.state().object_actee.count, 2);  // one contact per jaw
}

TEST(Solver, NoGraspWithoutAFingerOnTheFixedArm) {
  const Tool tool = tools_of_every_pattern()[0];
  const Model m = model_of(tool.yaml, nullptr, 0);
  Rig rig(m, tool.effort);
  rig.sample().fingertip[1] = Eigen::Vector3d(0, 0, 2.0);  // the index lets go
  rig.frame();  // no contact any more
  rig.frame();  // so no grasp
  EXPECT_FALSE(rig.state().grasped);
  rig.push(0.02);
  EXPECT_EQ(rig.state().theta, m.theta_rest);  // pushing an ungrasped tool does not close it
}

}  // namespace
}  // namespace afford::test
