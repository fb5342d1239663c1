// The exported MuJoCo scenes in MuJoCo itself (built only where CMake finds
// MuJoCo): every shipped session's scene loads and steps, every shape sits
// where the engine has it, and the hinge under the exported spring,
// friction and hand servo (and the harness's progressive spring and
// gravity) settles where the engine's static balance puts it, with and
// without the actee in the jaws.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "derive.h"
#include "mjcf_scene.h"
#include "mujoco_harness.h"
#include "session.h"
#include "stages.h"
#include "terms.h"
#include "../test_util.h"

namespace afford {
namespace {
using test::kSource;

namespace fs = std::filesystem;


// A tool with a part of every shape, turned in the world, gravity on, a
// convex actee.
const std::string kEveryShape = kSource + "/tests/data/mjcf/every-shape.yaml";

// The shipped sessions, and the one of every shape.
std::vector<std::string> sessions_to_load() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(kSource + "/sessions")) {
    if (e.path().extension() == ".yaml") out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());
  out.push_back(kEveryShape);
  return out;
}

TEST(MjcfMujoco, EverySessionLoadsAndSteps) {
  const std::vector<std::string> sessions = sessions_to_load();
  ASSERT_FALSE(sessions.empty());
  for (const std::string& file : sessions) {
    SCOPED_TRACE(file);
    const CompiledSession session = load_session(file);
    MujocoScene scene(session);
    for (int i = 0; i < 1000; ++i) {
      scene.command(scene.scheduled(scene.data()->time));
      scene.step();
    }
    EXPECT_EQ(scene.warnings(), 0);
    for (int i = 0; i < scene.model()->nq; ++i) EXPECT_TRUE(std::isfinite(scene.data()->qpos[i]));
    EXPECT_GE(scene.theta(), session.model.theta_min - 1e-3);
    EXPECT_LE(scene.theta(), session.model.theta_max + 1e-3);
  }
}

// Every part and the actee are where the engine has them: each shape's
// centroid (MuJoCo centres a mesh on its own), and the axis of capsules and
// cylinders (the part's x, MuJoCo's z); the moving arm weighs what the
// engine's does, with its centre where the engine's is.
TEST(MjcfMujoco, EveryShapeIsWhereTheEngineHasIt) {
  const CompiledSession session = load_session(kEveryShape);
  const Model& m = session.model;
  MujocoScene scene(session);
  mj_forward(scene.model(), scene.data());
  const auto check = [&](const std::string& name, const Geometry& g, const Eigen::Isometry3d& pose) {
    SCOPED_TRACE(name);
    const int id = mj_name2id(scene.model(), mjOBJ_GEOM, name.c_str());
    ASSERT_GE(id, 0);
    const Eigen::Vector3d want = pose * g.centroid();
    const Eigen::Map<const Eigen::Vector3d> got(scene.data()->geom_xpos + 3 * id);
    EXPECT_LT((got - want).norm(), 1e-8) << got.transpose() << " vs " << want.transpose();
    const ShapeKind kind = g.spec().kind;
    if (kind == ShapeKind::capsule || kind == ShapeKind::cylinder) {
      const mjtNum* r = scene.data()->geom_xmat + 9 * id;  // row-major
      const Eigen::Vector3d axis(r[2], r[5], r[8]);
      EXPECT_LT((axis - pose.linear() * Eigen::Vector3d::UnitX()).norm(), 1e-8);
    }
  };
  for (const ModelPart& p : m.parts) {
    const Eigen::Isometry3d arm = p.arm == Arm::moving ? moving_arm_pose(m.theta_rest) : Eigen::Isometry3d::Identity();
    check("part:" + p.name, p.geometry, m.object_start * arm * p.in_arm);
  }
  check("actee", m.actee(), m.actee_start);
  // The moving arm's mass and centre are the engine's (its weight's torque).
  const int arm = mj_name2id(scene.model(), mjOBJ_BODY, "moving_arm");
  EXPECT_NEAR(scene.model()->body_mass[arm], m.arm_mass, 1e-8 * m.arm_mass);  // the scene's 9 digits
  const Eigen::Map<const Eigen::Vector3d> centre(scene.data()->xipos + 3 * arm);
  EXPECT_LT((centre - m.object_start * moving_arm_pose(m.theta_rest) * m.arm_centre).norm(), 1e-8);
}

// Turns the command from the rest angle to `command` over half a second,
// as a script's squeeze does (a step would set the arm ringing on the
// undamped hand: the engine's arm has no inertia, MuJoCo's has its mass),
// holds it for a second and returns the settled angle.
double settle(MujocoScene& scene, double rest, double command) {
  constexpr double kRamp = 0.5, kHold = 1.0;  // s
  while (scene.data()->time < kRamp + kHold) {
    const double w = std::min(scene.data()->time / kRamp, 1.0);
    scene.command((1 - w) * rest + w * command);
    scene.step();
  }
  return scene.theta();
}

// The angle where the hand's closing torque kp (theta - command) meets the
// engine's opening torque (effort_for_load at the thumb, times b) plus
// `extra` N*m (friction), by bisection on [lo, hi].
template <typename Opening>
double balance(double kp, double command, double lo, double hi, Opening opening) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (kp * (mid - command) - opening(mid) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// The engine's opening torque about the hinge with the jaws empty (terms.h:
// the spring's linear, preload and progressive terms, gravity), N*m.
double opening_torque(const Model& m, double theta) {
  const SpringTorques t = spring_torques(m, theta);
  double c = 0, s = 0;
  gravity_coefficients(m, m.object_start.linear(), &c, &s);
  return t.linear + t.preload + t.progressive + c * std::cos(theta) + s * std::sin(theta);
}

// Squeezed 20 mm at the thumb with the jaws empty, the arm settles where
// the hand's torque meets the engine's opening torque, within the band the
// pivot's friction allows (plus 1e-5 rad for MuJoCo's soft friction), and
// the servo's torque is the engine's opening torque at that angle within
// the friction torque. On the nutcracker the spring's share (0.04 N*m, 3e-4
// rad of servo stretch) is four times the friction's (0.01 N*m): a wrong
// stiffness or springref fails; on the tool of every shape the progressive
// spring (0.08 N*m) and gravity's extra torque (0.02 N*m), which the
// harness applies from the scene's numerics, must be right too.
void expect_hinge_balance(const std::string& file) {
  SCOPED_TRACE(file);
  const CompiledSession session = load_session(file);
  const Model& m = session.model;
  MujocoScene scene(session);
  scene.drop_actee();
  const HandServo hand = hand_servo(session);
  const double command = m.theta_rest - 0.020 / hand.lever_arm;
  const double theta = settle(scene, m.theta_rest, command);
  ASSERT_EQ(scene.warnings(), 0);
  const double tf = m.friction_torque;
  const auto opening = [&m](double extra) { return [&m, extra](double th) { return opening_torque(m, th) + extra; }; };
  const double lo = balance(hand.kp, command, m.theta_min, m.theta_max, opening(-tf));
  const double hi = balance(hand.kp, command, m.theta_min, m.theta_max, opening(tf));
  constexpr double kAngleTolerance = 1e-5;  // rad
  EXPECT_GE(theta, lo - kAngleTolerance);
  EXPECT_LE(theta, hi + kAngleTolerance);
  EXPECT_NEAR(-scene.hand_torque(), opening_torque(m, theta), tf + 1e-3) << "N*m";
}

TEST(MjcfMujoco, HingeSettlesWhereTheEngineBalances) {
  expect_hinge_balance(kSource + "/sessions/paper-nutcracker.yaml");
  expect_hinge_balance(kEveryShape);
}

// With the jaws empty the engine's effort at the thumb (derive.h) is the
// opening torque over the lever arm: the balance above is the one
// `afford describe` and the guides use.
TEST(MjcfMujoco, OpeningTorqueIsTheEffortForNoLoad) {
  const CompiledSession session = load_session(kSource + "/sessions/paper-nutcracker.yaml");
  const double b = hand_servo(session).lever_arm;
  for (double th : {0.1, 0.3, 0.5}) {
    EXPECT_NEAR(opening_torque(session.model, th), effort_for_load(session.model, th, b, 0, 0) * b, 1e-12);
  }
}

// Squeezed on the walnut to about half its limit, the scene agrees with the
// engine's static balance (terms.h actee_force_law, derive.h
// effort_for_load):
// - the walnut's law seen in MuJoCo (its load at the penetration of its two
//   contacts, which the walnut's turning in the jaws does not change; the
//   harness sets the contacts to the law's secant stiffness) is the
//   actee's within 5 % (measured 1.6 % stiffer: the load is the moving
//   jaw's push, which is larger than the fixed jaw's where the jaws are not
//   parallel; with MuJoCo's soft friction it was 4.8 % softer);
// - MuJoCo's jaw pushes it where the engine's does: the lever arm (the
//   torque over the load) is the engine's load distance, 56.4 mm and not
//   the centre's 60 mm, within 1 % (measured 0.7 %: the walnut turns a
//   little in MuJoCo's jaws);
// - the torque the walnut takes about the hinge is the engine's within 5 %
//   (measured 1.2 %);
// - each contact pushes with the force its penetration gives (below).
TEST(MjcfMujoco, ActeeLoadMatchesTheEngine) {
  const CompiledSession session = load_session(kSource + "/sessions/paper-nutcracker.yaml");
  const Model& m = session.model;
  MujocoScene scene(session);
  const HandServo hand = hand_servo(session);
  const Eigen::Isometry3d in_object = m.object_start.inverse() * m.actee_start;
  ContactQuery query;
  double theta_c = 0, a = 0;  // a: m, the engine's load distance, where the jaw touches the walnut
  ASSERT_EQ(find_contact_angle(m, in_object, query, &theta_c, &a, nullptr), JawFit::fits);
  const double thickness = thickness_across_jaws(m, in_object);
  const auto load = [&](double th) {
    double slope = 0;
    return actee_force_law(m, a * (theta_c - th), thickness, &slope);
  };
  // The command that puts half the limit on the walnut in the engine.
  const double target = 0.5 * m.actee_limit;
  const double theta_target = theta_c - target / m.actee_stiffness / a;
  const double command =
      theta_target - effort_for_load(m, theta_target, hand.lever_arm, a, target) * hand.lever_arm / hand.kp;
  const double theta = settle(scene, m.theta_rest, command);
  ASSERT_EQ(scene.warnings(), 0);
  const double tf = m.friction_torque;
  const auto opening = [&](double extra) {
    return [&, extra](double th) {
      return effort_for_load(m, th, hand.lever_arm, a, load(th)) * hand.lever_arm + extra;
    };
  };
  const double engine_theta = 0.5 * (balance(hand.kp, command, m.theta_min, m.theta_max, opening(-tf)) +
                                     balance(hand.kp, command, m.theta_min, m.theta_max, opening(tf)));
  const double engine_torque = load(engine_theta) * a;  // N*m, the walnut's about the hinge

  // MuJoCo's: the hand's torque less the spring's (friction is at rest).
  const HingeSpring spring = hinge_spring(m);
  const double torque = -scene.hand_torque() - spring.stiffness * (spring.springref - theta);
  const double walnut = scene.actee_load();
  ASSERT_GT(walnut, 0);
  const double lever = torque / walnut;  // m, where the jaw touches it
  EXPECT_NEAR(lever, a, 0.01 * a) << "m";
  double penetration = 0;  // m, of the walnut's contacts with both jaws
  const int walnut_geom = mj_name2id(scene.model(), mjOBJ_GEOM, "actee");
  for (int i = 0; i < scene.data()->ncon; ++i) {
    const mjContact& c = scene.data()->contact[i];
    if (c.geom1 == walnut_geom || c.geom2 == walnut_geom) penetration -= c.dist;
  }
  // At rest each contact pushes with MuJoCo's steady soft-constraint force,
  // aref / R: the walnut does not creep. With soft friction (impratio 1)
  // the pushes fell 4 % (fixed jaw) and 9 % (moving jaw) short.
  for (int i = 0; i < scene.data()->ncon; ++i) {
    const mjContact& c = scene.data()->contact[i];
    if (c.geom1 != walnut_geom && c.geom2 != walnut_geom) continue;
    const int row = c.efc_address;
    const double steady = scene.data()->efc_aref[row] / scene.data()->efc_R[row];  // N
    EXPECT_NEAR(scene.data()->efc_force[row], steady, 0.01 * steady) << "contact " << i;
  }
  double slope = 0;
  const double law = actee_force_law(m, penetration, thickness, &slope);  // N
  EXPECT_NEAR(walnut, law, 0.05 * law) << "N";
  EXPECT_NEAR(torque, engine_torque, 0.05 * engine_torque + tf) << "N*m; MuJoCo at " << theta << " rad, the engine at "
                                                               << engine_theta << " rad";
}

}  // namespace
}  // namespace afford
