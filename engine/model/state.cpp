// State: creation, reset, the frame, and the determinism hash.
#include "state.h"

#include <cmath>
#include <cstring>

#include "stages.h"
#include "terms.h"

namespace afford {

const std::array<const char*, kTermCount> kTermNames = {
    "spring", "actee", "stop", "pivot_friction", "viscous_damping", "spring_preload", "progressive_spring",
    "arm_inertia", "gravity"};

const char* condition_name(ActeeCondition c) {
  switch (c) {
    case ActeeCondition::intact: return "intact";
    case ActeeCondition::squeezed: return "squeezed";
    case ActeeCondition::broken: return "broken";
  }
  return "?";
}

namespace {

// The actee at `world`, every field of it as at the start.
void place_actee(const Model& m, const Eigen::Isometry3d& world, State& s) {
  s.actee_pose = world;
  s.actee_start_position = world.translation();
  s.actee_in_object = s.object_pose.inverse() * world;
  s.placed_object = s.object_pose;
  s.placed_actee = s.actee_pose;
  s.between_jaws = find_contact_angle(m, s.actee_in_object, *s.query, &s.contact_angle, &s.load_distance,
                                      &s.jaw_contact) == JawFit::fits;
  if (!s.between_jaws) s.load_distance = 0;
  s.actee_thickness = thickness_across_jaws(m, s.actee_in_object);
  s.grip_margin = grip_margin(m.actee_friction, m.actee_friction, m.actee_mass, 0);
}

}  // namespace

std::unique_ptr<State> make_state(const Model& model) {
  auto state = std::make_unique<State>();
  state->query = std::make_unique<ContactQuery>();
  reset(model, *state);
  return state;
}

void reset(const Model& m, State& s) {
  std::unique_ptr<ContactQuery> query = std::move(s.query);
  s = State{};
  s.query = query ? std::move(query) : std::make_unique<ContactQuery>();
  s.object_pose = m.object_start;
  s.theta = s.theta_command = m.theta_rest;
  s.max_force = m.max_force;
  s.part_pose.resize(m.parts.size());
  s.part_box.resize(m.parts.size());
  if (m.has_actee) {
    s.jaw_contact.assign(m.parts.size(), JawContact{});
    place_actee(m, m.actee_start, s);
  }
  // The delay in whole frames and one more, to interpolate between two.
  if (m.sensor_latency > 0) {
    s.effort_history.assign(static_cast<size_t>(std::ceil(m.sensor_latency / m.timestep)) + 2, 0.0);
  }
}

void change_actee(const Model& m, State& s) {
  if (!m.has_actee) throw LogicError("change_actee() needs a model with an actee");
  s.actee_speed = 0;
  s.actee_anchor = Eigen::Vector3d::Zero();
  s.actee_in_hand = false;
  s.hand_to_actee = Eigen::Isometry3d::Identity();
  s.blocked = false;
  s.actee_force = s.actee_load = s.actee_compression = s.peak_actee_load = 0;
  s.condition = ActeeCondition::intact;
  s.broke_at = -1;
  s.held = false;
  s.object_actee = ContactSet{};
  s.actee_arms = 0;
  s.agent_actee = ContactSet{};
  for (JawContact& c : s.jaw_contact) c = JawContact{};
  place_actee(m, m.actee_on_jaw ? s.object_pose * (m.object_start.inverse() * m.actee_start) : m.actee_start, s);
}

void step(const Model& m, State& s, const Sample& sample) {
  if (!m.has_agent) throw LogicError("step() on a model compiled without an agent");
  place_bodies(m, s, sample);  // 1. sample, grasped object, held actee
  update_grasp(m, s);          // 2. the grasp, from the last frame's contacts
  solve_lever(m, s);           // 3. angle, spring, forces, torques
  update_actee(m, s);          // 4. intact, squeezed, broken; held
  find_contacts(m, s);         // 5. every contact at the solved angle
  ++s.frame;
}

namespace {

struct Hasher {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  }
  template <typename T>
  void value(const T& v) { bytes(&v, sizeof v); }
  void pose(const Eigen::Isometry3d& p) { bytes(p.matrix().data(), sizeof(double) * 16); }
  void vec(const Eigen::Vector3d& v) { bytes(v.data(), sizeof(double) * 3); }
  void contacts(const ContactSet& c) {
    value(c.count);
    for (int i = 0; i < std::min(c.count, kMaxContacts); ++i) {
      vec(c.point[static_cast<size_t>(i)].point);
      vec(c.point[static_cast<size_t>(i)].normal);
      value(c.point[static_cast<size_t>(i)].distance);
    }
  }
};

}  // namespace

std::uint64_t state_hash(const State& s) {
  Hasher h;
  h.value(s.t);
  h.value(s.frame);
  h.pose(s.object_pose);
  h.pose(s.actee_pose);
  for (const auto& f : s.fingertip) h.vec(f);
  for (double x : s.reach_short) h.value(x);
  h.contacts(s.agent_object);
  h.value(s.finger_on_arm);
  h.value(s.grasped);
  h.value(s.grasp_type);
  h.value(s.actee_in_hand);
  h.pose(s.hand_to_actee);
  h.vec(s.thumb_in_object);
  h.vec(s.thumb_proxy);
  h.vec(s.object_anchor);
  h.vec(s.actee_anchor);
  for (double x : {s.hand_speed, s.object_speed, s.actee_speed}) h.value(x);
  for (double x : {s.theta, s.omega, s.alpha, s.theta_command, s.effort_distance, s.load_distance,
                   s.thumb_speed, s.compression, s.effort_force, s.effort_excess, s.contact_angle,
                   s.actee_force, s.actee_load, s.actee_compression, s.peak_actee_load, s.broke_at,
                   s.max_force, s.omega_command, s.effort_sensed, s.actee_thickness, s.grip_margin}) {
    h.value(x);
  }
  h.value(s.torque);
  h.value(s.pattern);
  h.value(s.condition);
  for (bool b : {s.at_limit, s.blocked, s.between_jaws, s.held}) h.value(b);
  h.contacts(s.object_actee);
  h.value(s.actee_arms);
  h.contacts(s.agent_actee);
  return h.h;
}

}  // namespace afford
