// The optional effects as terms of the dynamics: each changes the angle, the
// actee's force or the verdict, with numbers worked out by hand in each
// test's comment. The rig's tool t2 (tools_of_every_pattern()[0]): type 2,
// spring S_k = 500 N/m at S_p = 30 mm with a 2 N preload, opens to 50 deg;
// the thumb at b = 150 mm; the hand f_a = 20000 N/m, at most 400 N.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "rig.h"
#include "terms.h"
#include "test_util.h"

namespace afford::test {
namespace {

using ::testing::HasSubstr;

constexpr double kG = 9.80665;  // m/s^2

// t2 with extra lines appended (effects) or its spring changed.
std::string t2(const std::string& effects = "", double spring_k = 500, double preload_n = 2) {
  return tool_yaml("t2", "type2", 0, 180, 50, spring_k, 30, preload_n, 110, 170, 20, 70, effects);
}

// Spring torque of t2-like tools at theta (linear part plus preload), N*m.
double spring_torque(const Model& m, double theta) {
  const SpringTorques t = spring_torques(m, theta);
  return t.linear + t.preload + t.progressive;
}

// Pushes until the actee breaks; returns the frames pushed.
int push_until_broken(Rig& rig, double step) {
  int frames = 0;
  while (rig.state().condition != ActeeCondition::broken && frames < 200000) {
    rig.push(step, step);
    ++frames;
  }
  return frames;
}

TEST(Effects, PivotFrictionDelaysTheCrack) {
  // Quasi-static, friction T only adds T to the torque the hand must give
  // while the arm closes. The shell cracks at the same arm angle (its load
  // fixes its deflection), so there the effort is higher by T/b, and the
  // hand, a spring f_a, is stretched further by T/(f_a*b): the thumb must go
  // that much further. T = 0.5 N*m, b = 0.15 m:
  //   effort at the crack + 0.5/0.15 = 3.333 N,
  //   thumb travel + 0.5/(20000*0.15) = 0.1667 mm = 166.7 frames at 1 um/frame.
  const std::string nut = nut_yaml(300);
  const Model plain = model_of(t2(), &nut, 0.040);
  const Model rough = model_of(t2("effects:\n  pivot_friction: {torque: 0.5 N*m}\n"), &nut, 0.040);
  double effort[2] = {0, 0};
  int frames[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    Rig rig(i == 0 ? plain : rough, 0.150);
    rig.close_to(rig.state().contact_angle);
    frames[i] = push_until_broken(rig, 1e-6);
    ASSERT_EQ(rig.state().condition, ActeeCondition::broken);
    effort[i] = rig.state().effort_force;
  }
  const double b = 0.150;
  // A frame's step adds about 0.08 N of load, 0.02 N of effort; the crack
  // frames are whole frames, and eq. (1) projects each step on the arm as
  // it was (about 1 % on the thumb's travel here): within 2 frames.
  EXPECT_NEAR(effort[1] - effort[0], 0.5 / b, 0.03);
  EXPECT_NEAR(frames[1] - frames[0], 0.5 / (20000 * b) / 1e-6, 2.0);
}

TEST(Effects, AStifferSpringLowersTheActeeForceAtTheSameThumbTravel) {
  // At the same hand target theta_cmd the balance is
  //   f_a b^2 (theta - theta_cmd) = K_s (rest - theta) + P + a F(delta),
  // K_s = S_k * S_p^2, P = preload * S_p, delta = a (theta_c - theta),
  // F = k delta h/(h - delta). With C = f_a b^2 (theta_c - theta_cmd)
  // - K_s (rest - theta_c) - P (the torque left at first touch) and
  // D = (f_a b^2 + K_s)/a, it is the quadratic
  //   D delta^2 - (C + D h + a k h) delta + C h = 0,
  // whose smaller root is delta. The spring's share K_s (rest - theta) + P
  // is taken from C: ten times S_k leaves the actee less.
  const std::string nut = nut_yaml(1e4);
  double force[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    const double spring_k = i == 0 ? 500 : 5000;
    const Model m = model_of(t2("", spring_k), &nut, 0.040);
    Rig rig(m, 0.150);
    rig.close_to(rig.state().contact_angle - 0.03);
    const State& s = rig.state();
    ASSERT_TRUE(s.blocked);
    ASSERT_LT(s.effort_force, m.max_force);
    const double a = 0.040, h = 0.020, k = 3e5, b = std::abs(s.effort_distance);
    const double ks = spring_k * 0.03 * 0.03, p = 2 * 0.03, rest = 50 * kDeg;
    const double hand = m.force_gain * b * b;
    const double c = hand * (s.contact_angle - s.theta_command) - ks * (rest - s.contact_angle) - p;
    const double d = (hand + ks) / a;
    const double q = c + d * h + a * k * h;
    const double delta = (q - std::sqrt(q * q - 4 * d * c * h)) / (2 * d);
    EXPECT_NEAR(s.actee_force, k * delta * h / (h - delta), 1e-6 * s.actee_force) << spring_k;
    force[i] = s.actee_force;
  }
  EXPECT_LT(force[1], force[0] - 10);  // about 171 N and 153 N
}

TEST(Effects, CoulombLoopIsTwiceTheFrictionTorqueWide) {
  // Closing, the hand gives the spring's torque plus T; opening, minus T:
  // at one angle the two efforts differ by 2T/b = 2 * 0.05 / 0.15 = 0.667 N.
  const double t = 0.05;
  const Model m = model_of(t2("effects:\n  pivot_friction: {torque: 0.05 N*m}\n"), nullptr, 0);
  Rig rig(m, 0.150);
  const State& s = rig.state();
  while (s.theta > 25 * kDeg) rig.push(2e-5);
  const double b = std::abs(s.effort_distance);
  const double closing = s.effort_force - spring_torque(m, s.theta) / b;
  EXPECT_EQ(s.torque[kPivotFriction], t);
  while (s.theta > 15 * kDeg) rig.push(2e-5);
  while (s.theta < 25 * kDeg) rig.push(-2e-5);
  const double b_open = std::abs(s.effort_distance);
  const double opening = s.effort_force - spring_torque(m, s.theta) / b_open;
  EXPECT_EQ(s.torque[kPivotFriction], -t);
  EXPECT_NEAR(closing - opening, t / b + t / b_open, 1e-8);
  EXPECT_NEAR(closing - opening, 2 * t / 0.150, 1e-3);
}

TEST(Effects, StictionHoldsTheArmWithoutChatter) {
  // Turning back, the hand's push must fall by 2T/b before the arm moves:
  // the thumb backs off 2T/(f_a b) = 2 * 0.05 / (20000 * 0.15) = 33.3 um
  // with the arm standing exactly still; after 30 um friction has gone
  // from +T to T - f_a * 30 um * b = 0.05 - 0.09 = -0.04 N*m.
  const Model m = model_of(t2("effects:\n  pivot_friction: {torque: 0.05 N*m}\n"), nullptr, 0);
  Rig rig(m, 0.150);
  const State& s = rig.state();
  while (s.theta > 25 * kDeg) rig.push(2e-5);
  const double theta = s.theta;
  const double b = std::abs(s.effort_distance);
  for (int i = 0; i < 100; ++i) rig.frame();  // the thumb still: no creep, no chatter
  EXPECT_EQ(s.theta, theta);
  EXPECT_EQ(s.omega, 0);
  // Stuck where it stopped, friction holds what the hand gives beyond the
  // spring (T, to the lever arm's change with the last step).
  const double held = s.torque[kPivotFriction];
  EXPECT_NEAR(held, 0.05, 1e-4);
  rig.push(-30e-6, 1e-6);  // within the dead band
  EXPECT_EQ(s.theta, theta);
  EXPECT_NEAR(s.torque[kPivotFriction], held - 20000 * 30e-6 * b, 1e-4 * 0.09);
  rig.push(-6e-6, 1e-6);  // past it
  EXPECT_GT(s.theta, theta);
  EXPECT_EQ(s.torque[kPivotFriction], -0.05);
}

TEST(Effects, ViscousDampingForceGrowsLinearlyWithSpeed) {
  // Closing at thumb speed v the arm turns at about v/b and the hand adds
  // c v / b^2 to the spring's share: c = 0.01 N*m*s/rad at 10 and 40 mm/s,
  // 0.0044 N and 0.0178 N.
  const double c = 0.01;
  const Model m = model_of(t2("effects:\n  viscous_damping: {coefficient: 0.01 N*m*s/rad}\n"), nullptr, 0);
  double extra[2] = {0, 0};
  const double steps[2] = {1e-5, 4e-5};  // m per frame
  for (int i = 0; i < 2; ++i) {
    Rig rig(m, 0.150);
    rig.push(0.01, steps[i]);
    const State& s = rig.state();
    const double b = std::abs(s.effort_distance);
    extra[i] = s.effort_force - spring_torque(m, s.theta) / b;
    // The balance, to the solver's tolerance (1e-13 rad times a slope of
    // at most 1e3 N*m/rad).
    EXPECT_NEAR(extra[i], s.torque[kViscousDamping] / b, 1e-9);
    // The arm turns a little slower than the thumb's target while the
    // hand's stretch grows with the spring (0.1 % here).
    EXPECT_NEAR(extra[i], c * (steps[i] / m.timestep) / (b * b), 0.005 * extra[i]);
  }
  EXPECT_NEAR(extra[1] / extra[0], 4.0, 0.01);
}

TEST(Effects, ArmInertiaGivesAForceTransient) {
  // The thumb accelerates at A = 2 m/s^2: the arm follows with
  // alpha = -A/b, so the hand pushes J A / b^2 = 2e-4 * 2 / 0.0225 = 0.0178 N
  // more than the spring needs; at constant speed that goes back to 0.
  const double j = 2e-4, acc = 2.0;
  const Model m = model_of(t2("effects:\n  arm_inertia: {inertia: 2e-4 kg*m^2}\n"), nullptr, 0);
  Rig rig(m, 0.150);
  double step = 0;
  for (int k = 0; k < 100; ++k) {  // 100 ms: 10 mm, to 0.2 m/s
    step += acc * m.timestep * m.timestep;
    rig.push(step, step);
  }
  const State& s = rig.state();
  const double b = std::abs(s.effort_distance);
  EXPECT_NEAR(s.effort_force * b - spring_torque(m, s.theta), -j * s.alpha, 1e-9);  // the balance
  EXPECT_NEAR(s.effort_force - spring_torque(m, s.theta) / b, j * acc / (b * b), 0.02 * j * acc / (b * b));
  for (int k = 0; k < 30; ++k) rig.push(step, step);  // constant speed
  EXPECT_NEAR(s.effort_force - spring_torque(m, s.theta) / b, 0, 1e-3 * j * acc / (b * b));
}

TEST(Effects, GravityFollowsTheCosineOfTheArmAngle) {
  // t2 turned so that its pivot axis is level (90 deg about x: the object's
  // y axis points up). Its two arms are equal boxes: the moving one has half
  // of the 100 g at (90 mm, 5 mm) in its frame, so its weight turns it by
  //   -g m (x cos theta - y sin theta) = -0.0441 N*m at theta = 0;
  // the 0.1 N*m extra amplitude closes it by 0.1 cos theta more.
  std::string yaml = t2("effects:\n  gravity: {extra_torque: 0.1 N*m}\n");
  yaml = replace_once(yaml, "functional_pose: {position: [0 mm, 0 mm, 0 mm]}",
                      "functional_pose: {position: [0 mm, 0 mm, 0 mm], rotation: [90 deg, 0 deg, 0 deg]}");
  const Model m = model_of(yaml, nullptr, 0);
  EXPECT_NEAR(m.arm_mass, 0.05, 1e-12);
  EXPECT_NEAR((m.arm_centre - Eigen::Vector3d(0.090, 0.005, 0)).norm(), 0, 1e-12);
  double c = 0, s = 0;
  gravity_coefficients(m, m.object_start.linear(), &c, &s);
  for (double theta : {0.0, 20 * kDeg, 45 * kDeg}) {
    const double weight = -kG * 0.05 * (0.090 * std::cos(theta) - 0.005 * std::sin(theta));
    EXPECT_NEAR(c * std::cos(theta) + s * std::sin(theta), weight - 0.1 * std::cos(theta), 1e-12) << theta;
  }
  // Turned further about its (level) hinge by phi, as a measurement may
  // hold it: the arm then hangs as if at theta + phi, weight and extra alike.
  for (double phi : {90 * kDeg, 180 * kDeg, -30 * kDeg}) {
    double ct = 0, st = 0;
    gravity_coefficients(m, m.object_start.linear(), &ct, &st, phi);
    for (double theta : {0.0, 20 * kDeg}) {
      const double a = theta + phi;
      const double weight = -kG * 0.05 * (0.090 * std::cos(a) - 0.005 * std::sin(a));
      EXPECT_NEAR(ct * std::cos(theta) + st * std::sin(theta), weight - 0.1 * std::cos(a), 1e-12) << phi << " " << theta;
    }
  }
  // Untouched, the tool settles where spring and weight balance; turned the
  // other way up, the weight opens it and the stop holds it.
  auto state = make_state(m);
  Sample away;
  for (auto& tip : away.fingertip) tip = Eigen::Vector3d(0, 0, 5.0);
  for (int k = 1; k <= 5; ++k) {
    away.t = k * m.timestep;
    step(m, *state, away);
  }
  const double theta = state->theta;
  EXPECT_LT(theta, m.theta_max);
  EXPECT_NEAR(state->torque[kGravity], c * std::cos(theta) + s * std::sin(theta), 1e-12);
  EXPECT_NEAR(spring_torque(m, theta) + state->torque[kGravity], 0, 1e-9);
  EXPECT_EQ(state->torque[kStop], 0);
}

TEST(Effects, CompliantActeeStiffensAndNeverReachesZeroThickness) {
  // The 30 mm sponge (800 N/m) in t2 at 60 mm under the 400 N hand: a
  // linear law would flatten it (400 N * 150/60 = 1000 N = 1.25 m of
  // deflection); the law's h/(h - delta) keeps it above zero thickness.
  const std::string sponge = kSpongeYaml;
  const Model m = model_of(t2(), &sponge, 0.060);
  Rig rig(m, 0.150);
  rig.close_to(rig.state().contact_angle);
  double last_secant = 0;
  for (int i = 0; i < 60; ++i) {
    rig.push(0.002);
    const State& s = rig.state();
    ASSERT_LT(s.actee_compression, s.actee_thickness) << i;
    if (s.actee_compression > 0.001 && s.effort_force < m.max_force) {  // before the hand's limit
      const double secant = s.actee_force / s.actee_compression;
      EXPECT_GE(secant, last_secant) << i;  // it stiffens
      last_secant = secant;
    }
  }
  EXPECT_NEAR(rig.state().effort_force, m.max_force, 1e-9);
  EXPECT_GT(rig.state().actee_force, 100.0);
  EXPECT_GT(rig.state().actee_compression, 0.9 * rig.state().actee_thickness);
}

TEST(Effects, PowerLawActeeFollowsItsLaw) {
  // exponent 1.5, reference 0.5 mm on the 20 mm nut (k = 3e5 N/m):
  //   F = k * 0.5 mm * (delta / 0.5 mm)^1.5 * 20/(20 - delta/mm);
  // at delta = 0.5 mm: 150 N * 20/19.5 = 153.85 N.
  std::string nut = nut_yaml(1e4) + "effects:\n  actee_compliance: {exponent: 1.5, reference: 0.5 mm}\n";
  const Model m = model_of(t2(), &nut, 0.040);
  double slope = 0;
  EXPECT_NEAR(actee_force_law(m, 0.0005, 0.020, &slope), 150.0 * 20 / 19.5, 1e-9);
  Rig rig(m, 0.150);
  rig.close_to(rig.state().contact_angle - 0.02);
  const State& s = rig.state();
  ASSERT_TRUE(s.blocked);
  const double delta = s.actee_compression;
  EXPECT_NEAR(s.actee_force, 3e5 * 0.0005 * std::pow(delta / 0.0005, 1.5) * 0.020 / (0.020 - delta), 1e-9);
  // The load's lever arm: 40 mm, where the jaw touches the sphere (its
  // centre's distance: the two tangents from the hinge are equally long).
  EXPECT_NEAR(s.effort_force * 0.150 * 0 + s.effort_force * std::abs(s.effort_distance),
              spring_torque(m, s.theta) + s.actee_force * 0.040, 1e-9);
}

TEST(Effects, ASpringTheHandCannotOvercomeKeepsTheToolOpen) {
  // A 3000 N preload at 30 mm holds with 90 N*m; the 400 N hand at 150 mm
  // gives at most 60 N*m. The tool stays open; the hand shows its limit and
  // never more; the stop takes the difference, -30 N*m.
  const Model m = model_of(t2("", 500, 3000), nullptr, 0);
  Rig rig(m, 0.150);
  for (int i = 0; i < 50; ++i) {
    rig.push(0.001);
    ASSERT_LE(rig.state().effort_force, m.max_force);
  }
  EXPECT_EQ(rig.state().theta, m.theta_max);
  EXPECT_EQ(rig.state().effort_force, m.max_force);
  EXPECT_NEAR(rig.state().torque[kStop], 400 * std::abs(rig.state().effort_distance) - 90, 1e-9);
}

TEST(Effects, TheSpringsPreloadKeyIsTheSpringPreloadEffect) {
  // `preload: 2 N` and a spring free at rest with spring_preload 2 N are
  // the same tool, frame for frame; switched off, the preload is gone.
  const Model key = model_of(t2(), nullptr, 0);
  const Model effect = model_of(t2("effects:\n  spring_preload: {force: 2 N}\n", 500, 0), nullptr, 0);
  Rig a(key, 0.150), b(effect, 0.150);
  for (int i = 0; i < 200; ++i) {
    a.push(1e-4, 1e-4);
    b.push(1e-4, 1e-4);
    ASSERT_EQ(state_hash(a.state()), state_hash(b.state())) << i;
  }
  EXPECT_NEAR(a.state().torque[kSpringPreload], 2 * 0.030, 1e-15);
  const Model off = model_of(t2("effects:\n  spring_preload: {force: 2 N, enabled: false}\n", 500, 0), nullptr, 0);
  Rig c(off, 0.150);
  c.push(0.01);
  EXPECT_EQ(c.state().torque[kSpringPreload], 0);
}

TEST(Effects, SensorLatencyDelaysTheSensedEffort) {
  // 2.5 ms at 1 ms frames: half of the effort 2 frames ago, half of 3.
  const ObjectSpec o = object_from(t2());
  const AgentSpec h = hand();
  ModelOptions options;
  EffectSpec latency;
  latency.name = "sensor_latency";
  latency.kind = EffectKind::sensor_latency;
  latency.param[0] = 0.0025;
  options.effects.push_back(latency);
  const Model m = compile(o, nullptr, &h, options);
  Rig rig(m, 0.150);
  std::vector<double> effort;
  for (int k = 0; k < 50; ++k) {
    rig.push(2e-5 * (1 + k % 7), 1e-3);  // an uneven ramp
    effort.push_back(rig.state().effort_force);
    if (k >= 3) {
      EXPECT_NEAR(rig.state().effort_sensed, 0.5 * effort[k - 2] + 0.5 * effort[k - 3], 1e-12) << k;
    }
  }
}

TEST(Effects, HandDampingAddsToTheImpedance) {
  // F = f_a b (theta - cmd) + c_h b (omega - omega_cmd), c_h = 50 N*s/m.
  const ObjectSpec o = object_from(t2());
  AgentSpec h = read_agent(load_yaml_string(replace_once(kHandYaml, "max_force: 400 N", "max_force: 400 N\ndamping: 50 N*s/m"),
                                            "hand.yaml"));
  EXPECT_DOUBLE_EQ(h.damping, 50.0);
  const Model m = compile(o, nullptr, &h, ModelOptions{});
  Rig rig(m, 0.150);
  rig.push(0.005, 1e-4);
  const State& s = rig.state();
  const double b = std::abs(s.effort_distance);
  EXPECT_NEAR(s.effort_force,
              m.force_gain * b * (s.theta - s.theta_command) + 50 * b * (s.omega - s.omega_command), 1e-9);
}

// ------------------------------------------------------------ where effects belong

std::string load_error(const std::string& yaml, bool actee) {
  try {
    if (actee) {
      (void)actee_from(yaml);
    } else {
      (void)object_from(yaml);
    }
  } catch (const DataError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no DataError for:\n" << yaml;
  return "";
}

TEST(Effects, EachEffectBelongsToOneKindOfFile) {
  EXPECT_THAT(load_error(t2("effects:\n  actee_compliance: {exponent: 1.5, reference: 1 mm}\n"), false),
              HasSubstr("expected an effect of an object file, found 'actee_compliance', which belongs in an "
                        "actee file"));
  EXPECT_THAT(load_error(nut_yaml() + "effects:\n  sensor_latency: {delay: 5 ms}\n", true),
              HasSubstr("expected an effect of an actee file, found 'sensor_latency', which belongs in a "
                        "measurement file"));
  EXPECT_THAT(load_error(nut_yaml() + "effects:\n  actee_compliance: {exponent: 50, reference: 1 mm}\n", true),
              HasSubstr("actee.yaml:11:32: expected a value from 0.1 to 10 (power of the deflection, plain number), "
                        "found '50'"));
  EXPECT_THAT(load_error(t2("effects:\n  spring_preload: {force: 2 N}\n"), false),
              HasSubstr("expected the spring's preload given once, found spring_preload here and a preload of 2 N"));
}

}  // namespace
}  // namespace afford::test
