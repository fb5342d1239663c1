// The per-session mutable state (MuJoCo's mjData), grouped by the stage of
// the frame that writes it. Sized once by make_state(); a frame allocates
// nothing.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry.h"
#include "model.h"
#include "sample.h"
#include "spec.h"

namespace afford {

inline constexpr int kMaxContacts = 16;  // per relation; more are counted, not stored

// Named torque terms about the fulcrum, N*m, positive = opening (resisting
// the agent's squeeze). The agent's torque F_ag * D_ag balances their sum
// in every frame (the inertia term is -J * alpha, d'Alembert's).
// kStop is the reaction of the angle limit when the arm rests on one; with
// it the terms balance the agent exactly in every case. The optional terms
// are named after their effects (effects.h).
enum Term {
  kSpring = 0,
  kActee,
  kStop,
  kPivotFriction,
  kViscousDamping,
  kSpringPreload,
  kProgressiveSpring,
  kArmInertia,
  kGravity,
  kTermCount
};
extern const std::array<const char*, kTermCount> kTermNames;

enum class ActeeCondition { intact, squeezed, broken };
const char* condition_name(ActeeCondition c);

// Contacts of one relation (agent-object, object-actee, agent-actee).
struct ContactSet {
  int count = 0;                                   // contact points, one per touching pair
  std::array<ContactPoint, kMaxContacts> point{};  // the first kMaxContacts of them
  void clear() { count = 0; }
  void add(const ContactPoint& p) {
    if (count < kMaxContacts) point[static_cast<size_t>(count)] = p;
    ++count;
  }
};

// Where one part touches an actee resting in the jaws, found when it was
// placed: the jaws hold it, so the contact moves with the part.
struct JawContact {
  bool touching = false;
  ContactPoint in_arm;  // point and normal in the part's arm frame
};

struct State {
  // --- time
  double t = 0;          // s, of the last sample
  std::int64_t frame = 0;

  // --- place: bodies in the world
  Eigen::Isometry3d object_pose = Eigen::Isometry3d::Identity();  // world from object frame
  Eigen::Isometry3d actee_pose = Eigen::Isometry3d::Identity();   // world from actee frame
  Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();         // world, from the sample
  FingerPoints fingertip = finger_origins();              // m, world
  std::array<double, kFingers> reach_short{};  // m, how far the sample asked each tip beyond its reach, where it stopped (reach.h); 0: within
  std::array<std::array<double, kJoints>, kFingers> joint{};      // rad
  int grasp_type = -1;  // the posture's type in the model's taxonomy this frame; -1: none
  double hand_speed = 0;    // m/s, of the hand's origin
  double object_speed = 0;  // m/s, of the object frame's origin
  double actee_speed = 0;   // m/s, of the actee's centre
  Eigen::Vector3d object_anchor = Eigen::Vector3d::Zero();  // m, world: object origin when the grasp began
  Eigen::Vector3d actee_anchor = Eigen::Vector3d::Zero();   // m, world: actee centre when last picked up

  // --- the grasp (from the last frame's agent-object and agent-actee contacts)
  bool grasped = false;  // thumb on the moving arm, another finger on the fixed arm (and a taxonomy posture)
  Eigen::Isometry3d hand_to_object = Eigen::Isometry3d::Identity();  // object in hand frame while grasped
  Eigen::Vector3d thumb_in_object = Eigen::Vector3d::Zero();  // m, last thumb position, object frame
  double max_force = 0;  // N, the largest effort force now: the agent's, capped by the grasp type's
  bool actee_in_hand = false;  // the agent grasps the actee (Sec. 4.3.3): it moves with the hand
  Eigen::Isometry3d hand_to_actee = Eigen::Isometry3d::Identity();  // actee in hand frame while in hand

  // --- lever-spring solver
  double theta = 0;          // rad, opening angle
  double omega = 0;          // rad/s, d theta / dt
  double alpha = 0;          // rad/s^2
  double theta_command = 0;  // rad, where the tracked thumb would put the arm (eq. 1): the hand's target
  double omega_command = 0;  // rad/s, its rate
  double effort_distance = 0;  // m, D_ag: signed distance of the thumb along the moving arm
  double load_distance = 0;    // m, D_ac: the load's signed lever arm, where the moving jaw touches the actee
  LeverPattern pattern = LeverPattern::type2;  // as the effort and load sit now (Step 2-1)
  double thumb_speed = 0;        // m/s, v of eq. 2, along L_d, closing positive
  double compression = 0;        // m, spring compression d of eq. 4
  std::array<double, kTermCount> torque{};  // N*m, opening positive
  double effort_force = 0;       // N, F_ag = F_agr at the emphasis, along L_d: the hand impedance's force
  double effort_excess = 0;      // m, the hand impedance's stretch: how far the thumb is past the arm
  double effort_sensed = 0;      // N, effort_force as a sensor with sensor_latency reports it
  Eigen::Vector3d closing_direction = Eigen::Vector3d::Zero();  // L_d at the emphasis, unit, object frame
  Eigen::Vector3d thumb_proxy = Eigen::Vector3d::Zero();  // m, world: the thumb kept on the arm's surface
  bool at_limit = false;         // the arm rests on theta_min or theta_max
  bool blocked = false;          // the actee stops the arm

  // --- actee
  bool between_jaws = false;     // the moving jaw can close on the actee
  double contact_angle = 0;      // rad, theta at which the jaws touch the actee (between_jaws)
  double actee_thickness = 0;    // m, its extent across the jaws (between_jaws)
  Eigen::Isometry3d actee_in_object = Eigen::Isometry3d::Identity();  // while held or for contact_angle
  Eigen::Isometry3d placed_object = Eigen::Isometry3d::Identity();    // world poses contact_angle was found for
  Eigen::Isometry3d placed_actee = Eigen::Isometry3d::Identity();
  double actee_force = 0;        // N, F_acr: force between jaws and actee
  double actee_load = 0;         // N, its component along A_d, compared with the limit
  double actee_compression = 0;  // m
  double peak_actee_load = 0;    // N, largest actee_load so far
  ActeeCondition condition = ActeeCondition::intact;
  double broke_at = -1;          // s, when it broke; -1 if it has not
  double grip_margin = 0;        // N, 2*mu*F_acr - m*g: weight the jaws' friction could carry beyond the actee's
  bool held = false;             // gripped between both jaws, firmly enough to carry its weight
  Eigen::Vector3d actee_start_position = Eigen::Vector3d::Zero();  // m, world

  std::vector<JawContact> jaw_contact;  // per model part, sized once by reset()

  // --- contacts at the solved angle
  ContactSet agent_object;
  std::array<std::uint8_t, kFingers> finger_on_arm{};  // bit 0: fixed arm, bit 1: moving arm
  ContactSet object_actee;
  std::uint8_t actee_arms = 0;  // arms touching the actee: bit 0 fixed, bit 1 moving
  ContactSet agent_actee;

  // --- sensing: the last efforts, for sensor_latency (sized once by reset())
  std::vector<double> effort_history;  // N, a ring, one per frame
  std::int64_t history_head = 0;       // frames written

  // --- scratch: not part of the simulated state
  Eigen::Isometry3d moving_arm_world = Eigen::Isometry3d::Identity();  // the moving arm's frame, world, this frame
  std::vector<Eigen::Isometry3d> part_pose;  // per model part, world, this frame (sized once by reset())
  std::vector<WorldBox> part_box;            // their world boxes
  // The object's pose and the angle the parts were last placed at: placed
  // again only when one of them changed (bit for bit), the fixed arm's
  // parts only when the object moved.
  Eigen::Isometry3d parts_object_pose = Eigen::Isometry3d::Identity();
  double parts_theta = 0;  // rad
  bool parts_placed = false;
  std::unique_ptr<ContactQuery> query;
};

// A fresh state for the model: bodies at their start poses, lever at rest.
std::unique_ptr<State> make_state(const Model& model);
void reset(const Model& model, State& state);

// Another actee takes the last one's place (a session with several
// actees, when its script takes the next): every actee field as reset()
// leaves it. One placed on the fixed jaw goes there on the tool as the
// tool is now (the subject puts it into the tool wherever it is); one
// placed in the world, there. The tool and the hand go on as they were.
// `model` is the new actee's (the same tool and hand). Allocates nothing.
void change_actee(const Model& model, State& state);

// One frame (paper Sec. 4.3): place, the grasp, the lever-spring solver,
// the actee, then the contacts at the solved angle.
// Allocates nothing. The same model, state and samples give the same state,
// bit for bit.
void step(const Model& model, State& state, const Sample& sample);

// FNV-1a hash over every simulated field of the state, for determinism tests.
std::uint64_t state_hash(const State& state);

}  // namespace afford
