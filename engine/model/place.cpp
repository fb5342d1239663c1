// Stage 1: place the bodies, and keep the actee's contact angle current.
#include "reach.h"
#include "stages.h"

namespace afford {
namespace {

// The jaws' contact angle depends only on where the actee sits relative to
// the object; recompute it (a bisection of FCL queries) only when that moves.
void refresh_contact_angle(const Model& m, State& s) {
  if (!m.has_actee || s.condition == ActeeCondition::broken) {
    s.between_jaws = false;
    return;
  }
  // Compared bit for bit on the world poses: the relative pose, computed
  // again, would differ in its last bits and trigger needless bisections.
  if (s.object_pose.matrix() == s.placed_object.matrix() && s.actee_pose.matrix() == s.placed_actee.matrix()) {
    return;
  }
  s.placed_object = s.object_pose;
  s.placed_actee = s.actee_pose;
  const Eigen::Isometry3d rel = s.object_pose.inverse() * s.actee_pose;
  s.actee_in_object = rel;
  // Far from every part, open or closed, it cannot be between the jaws: no
  // bisection while the hand carries it about.
  bool near = false;
  for (const ModelPart& part : m.parts) {
    for (double theta : {m.theta_min, m.theta_max}) {
      near = near || !boxes_apart(part.geometry, part_in_object(part, theta), m.actee(), rel, m.contact_tolerance);
    }
  }
  if (!near) {
    s.between_jaws = false;
    s.load_distance = 0;
    return;
  }
  s.between_jaws = find_contact_angle(m, rel, *s.query, &s.contact_angle, &s.load_distance, &s.jaw_contact) ==
                   JawFit::fits;
  if (!s.between_jaws) s.load_distance = 0;
  s.actee_thickness = thickness_across_jaws(m, rel);
}

// A fingertip stops at its reach (reach.h): a sample beyond it (from a
// device, a recording, or a generated script; a session's keyframes are
// checked when it loads) leaves the tip at the nearest point the finger
// can take, and reach_short says how far the sample asked. While the hand
// grasps the tool the thumb's sample is the hand impedance's target, which
// runs ahead of the arm by design (agents/README.md), not a place: kept.
void keep_within_reach(const Model& m, State& s) {
  s.reach_short.fill(0.0);
  if (!m.has_reach) return;
  const Eigen::Isometry3d to_hand = s.hand.inverse();
  for (int f = s.grasped ? 1 : 0; f < kFingers; ++f) {
    const size_t i = static_cast<size_t>(f);
    const Eigen::Vector3d tip = to_hand * s.fingertip[i];
    s.reach_short[i] = reach_short(m, f, tip);
    if (s.reach_short[i] > 0) s.fingertip[i] = s.hand * nearest_reachable(m, f, tip);
  }
}

}  // namespace

double thickness_across_jaws(const Model& m, const Eigen::Isometry3d& actee_in_object) {
  const Eigen::Vector3d across = actee_in_object.linear().transpose() * Eigen::Vector3d::UnitY();
  return m.actee().support(across) + m.actee().support(-across);
}

void place_bodies(const Model& m, State& s, const Sample& sample) {
  const Eigen::Vector3d hand_before = s.hand.translation();
  const Eigen::Vector3d object_before = s.object_pose.translation();
  const Eigen::Vector3d actee_before = s.actee_pose.translation();
  s.t = sample.t;
  s.hand = sample.hand;
  s.fingertip = sample.fingertip;
  keep_within_reach(m, s);
  // Fig. 7; -1 without a taxonomy. A posture held from the last frame keeps its type.
  const bool posture_changed = s.frame == 0 || !(sample.joint == s.joint);
  s.joint = sample.joint;
  if (posture_changed) s.grasp_type = classify_grasp(m, s.joint);
  // A grasped object moves with the hand (Sec. 4.3.1: fingers move, posture
  // kept); a held actee moves with the object; an actee in the hand (Sec.
  // 4.3.3) but not in the jaws moves with the hand.
  if (s.grasped) s.object_pose = s.hand * s.hand_to_object;
  if (s.held) {
    s.actee_pose = s.object_pose * s.actee_in_object;
  } else {
    if (s.actee_in_hand && s.condition != ActeeCondition::broken) s.actee_pose = s.hand * s.hand_to_actee;
    refresh_contact_angle(m, s);
  }
  // Speeds over the frame (the first frame starts from rest).
  const double dt = m.timestep;
  s.hand_speed = s.frame > 0 ? (s.hand.translation() - hand_before).norm() / dt : 0.0;
  s.object_speed = (s.object_pose.translation() - object_before).norm() / dt;
  s.actee_speed = (s.actee_pose.translation() - actee_before).norm() / dt;
}

}  // namespace afford
