// The compiled model: everything that does not change during a session,
// resolved to numbers once (MuJoCo's mjModel). Immutable after compile();
// many sessions, on many threads, may share one.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "effects.h"
#include "geometry.h"
#include "grasps.h"
#include "spec.h"

namespace afford {

// Where the actee starts: resting on the fixed jaw at a distance from the
// fulcrum, or at a pose in the world.
struct ActeePlacement {
  bool in_jaws = true;
  double distance = 0;  // m, signed distance along the fixed arm (in_jaws)
  Eigen::Isometry3d world = Eigen::Isometry3d::Identity();  // (!in_jaws)
  SourceLoc loc;  // where the placement was written, for errors
};

struct ModelOptions {
  double timestep = 1e-3;           // s, the haptic rate
  double contact_tolerance = 5e-4;  // m, closer than this counts as touching
  ActeePlacement actee;
  // The grasp taxonomy (Fig. 7, rules/grasps.yaml), in file order. Empty
  // means no taxonomy: the grasp is decided by contact alone, and the hand's
  // force limit is the agent's max_force.
  std::vector<GraspTypeSpec> grasps;
  // Effects given by a measurement file: they replace the object's or the
  // actee's effect of the same name, or add to them.
  std::vector<EffectSpec> effects;
};

struct ModelPart {
  std::string name;
  Arm arm = Arm::fixed;
  Geometry geometry;
  Eigen::Isometry3d in_arm = Eigen::Isometry3d::Identity();  // part pose in its arm's frame
  double friction = 0;  // mu of an actee on its surface; 0: the actee's own (actee_friction)
};

// An effect as a file switched it on or off, for reports; the solver reads
// the resolved numbers below (Model, "optional effects").
struct ModelEffect {
  EffectKind kind = EffectKind::pivot_friction;
  std::string name;
  bool enabled = true;
  std::array<double, 2> param{};  // SI, in the order of the manifest's parameters
  SourceLoc loc;                  // where it was written
};

struct Model {
  // options
  double timestep = 1e-3;           // s
  double contact_tolerance = 5e-4;  // m

  // acting object (Fig. 4); object frame as in spec.h
  std::string object_name;
  LeverPattern pattern = LeverPattern::type2;  // declared, checked against the regions
  double arm_from = 0, arm_to = 0;             // m, signed extent of each arm
  double theta_min = 0, theta_max = 0;         // rad, angle limits
  double theta_rest = 0;                       // rad, where the untouched tool sits
  double spring_constant = 0;                  // N/m, S_k
  double spring_position = 0;                  // m, signed S_p
  double emphasis_from = 0, emphasis_to = 0;   // m, signed
  double application_from = 0, application_to = 0;  // m, signed
  // L_is from the object's interaction_space table (derive.h); empty: the wedge
  std::vector<double> space_distances, space_gaps;  // m, signed distances; m, gaps at theta_max
  double object_mass = 0;                      // kg
  Eigen::Isometry3d object_start = Eigen::Isometry3d::Identity();  // functional pose in the world
  Eigen::Vector3d symmetry_point = Eigen::Vector3d::Zero();    // m, O_sp in the object frame
  Eigen::Vector3d symmetry_normal = Eigen::Vector3d::UnitZ();  // unit, O_sp's normal, object frame
  std::vector<ModelPart> parts;
  double arm_mass = 0;                         // kg, the moving arm's share of the mass (by volume)
  Eigen::Vector3d arm_centre = Eigen::Vector3d::Zero();  // m, its centre of gravity, moving arm frame

  // optional effects (effects.h), resolved; each is 0 (or neutral) when off
  std::vector<ModelEffect> effects;  // every effect a file names, on or off
  double friction_torque = 0;    // N*m, pivot_friction
  double damping = 0;            // N*m*s/rad, viscous_damping
  double spring_preload = 0;     // N, spring_preload: the spring's push at the rest angle
  double spring_cubic = 0;       // N/m^3, progressive_spring
  double arm_inertia = 0;        // kg*m^2, arm_inertia
  bool gravity = false;          // gravity: the moving arm's weight acts
  double gravity_extra = 0;      // N*m, gravity's extra amplitude (closing for a level fixed arm)
  double actee_exponent = 1;     // actee_compliance: power of the deflection (1: linear)
  double actee_reference = 0;    // m, actee_compliance: where the secant stiffness is actee_stiffness
  double sensor_latency = 0;     // s, sensor_latency: delay of the sensed effort

  // actee (Fig. 6); absent when has_actee is false
  bool has_actee = false;
  std::string actee_name;
  std::vector<Geometry> actee_geometry;  // one element when has_actee
  Eigen::Vector3d actee_direction = Eigen::Vector3d::UnitY();  // A_d, unit, actee frame
  double actee_limit = 0;       // N, A_pv
  double actee_stiffness = 0;   // N/m
  bool actee_breaks = true;
  double actee_mass = 0;        // kg
  double actee_friction = 0;    // mu, static, of the actee on the jaws: the grip that carries its weight
  Eigen::Isometry3d actee_start = Eigen::Isometry3d::Identity();  // world
  bool actee_on_jaw = false;    // placed on the fixed jaw (`at:`), not at a pose in the world
  ActeeLook actee_look;         // how the renderer draws it (actee_look.h)

  // agent (Fig. 8); absent when has_agent is false
  bool has_agent = false;
  std::string agent_name;
  double force_gain = 0;  // N/m, f_a of eq. 3: the hand impedance's stiffness
  double hand_damping = 0;  // N*s/m, the hand impedance's damping
  double max_force = 0;   // N, largest effort force
  std::array<double, kFingers> tip_radius{};  // m
  std::vector<Geometry> fingertip;            // one sphere per finger
  std::array<std::array<double, kJoints>, kFingers> joint_min{}, joint_max{};  // rad
  // Reach (reach.h); has_reach false: the agent file gives no chains and
  // the fingertips are not limited.
  bool has_reach = false;
  std::string agent_file;                                      // where the chains were written, for errors
  FingerPoints finger_base = finger_origins();         // m, hand frame: the chain's first joint
  std::array<std::array<double, kJoints>, kFingers> link{};    // m, [distal, proximal, metacarpal]
  std::array<double, kFingers> chain_min{}, chain_max{};       // m, the tip's distance from the base
  std::array<double, kFingers> reach_min{}, reach_max{};       // m, the tip's distance from the wrist

  // grasp taxonomy (Fig. 7), per type in file order; empty: none (the grasp
  // is decided by contact alone). See classify_grasp() in grasps.h.
  std::vector<std::string> grasp_name;
  std::vector<GraspKind> grasp_kind;
  std::vector<double> grasp_max_force;  // N, the largest effort force in the type
  std::vector<double> grasp_joint_min;  // rad, kFingers*kJoints per type, [type][finger][joint];
  std::vector<double> grasp_joint_max;  // a free joint is [-inf, +inf]

  const Geometry& actee() const { return actee_geometry.front(); }
};

// Compiles specs into a model. The actee is optional (nullptr: none); so is
// the agent, for models that are only looked at (describe, guides) and never
// stepped.
// Cross-file problems (a placement off the arm) are DataErrors naming the
// spec's location.
Model compile(const ObjectSpec& object, const ActeeSpec* actee, const AgentSpec* agent,
              const ModelOptions& options);

// A model of the actee alone (its law, limit and effects, and those the
// options give), for a measurement between plates. Not for step().
Model compile_actee_only(const ActeeSpec& actee, const ModelOptions& options);

// A model of the hand alone (no object, no actee): what a device's report
// decoder checks samples against. Not for step().
Model compile_agent_only(const AgentSpec& agent);

// Pose of the moving arm's frame in the object frame at opening angle theta.
Eigen::Isometry3d moving_arm_pose(double theta_rad);

// The resolved parameters of an effect if it is on, else nullptr.
const ModelEffect* enabled_effect(const Model& m, EffectKind kind);

}  // namespace afford
