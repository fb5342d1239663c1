// Stage 2: the grasp that lets the thumb drive the lever, and the hand's
// grasp of the actee. Both follow the contacts of the last frame (stage 5),
// so a grasp starts one frame after the fingers touch.
#include <algorithm>

#include "grasps.h"
#include "stages.h"

namespace afford {
namespace {

// Sec. 4.3.3: "If there are more than three contact points between the
// agent and the actee, and if more than three direction of normal vector at
// the contact points are opposite to Ad ..., then the actee is grasped by the
// agent and is moved with the agent." Read physically: the actee pushes back
// on each finger along the contact normal, and fingers hold it when they
// squeeze it from opposite sides. So at least three fingertips touch it
// (each fingertip gives at most one contact point) and some pair of contact
// normals opposes (negative dot product). Fingers all on one side only push.
bool fingers_hold_actee(const State& s) {
  const int n = std::min(s.agent_actee.count, kMaxContacts);
  if (n < 3) return false;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const Eigen::Vector3d& a = s.agent_actee.point[static_cast<size_t>(i)].normal;
      const Eigen::Vector3d& b = s.agent_actee.point[static_cast<size_t>(j)].normal;
      if (a.dot(b) < 0) return true;
    }
  }
  return false;
}

}  // namespace

void update_grasp(const Model& m, State& s) {
  // Sec. 4.3.1: with a taxonomy, only a posture of one of its types grasps
  // ("If the present grasp type is included in the grasp types shown in
  // Fig. 7, the agent is considered grasping the acting object").
  const bool posture_grasps = m.grasp_name.empty() || s.grasp_type >= 0;
  s.max_force = grasp_force_cap(m, s.grasp_type);

  bool finger_on_fixed = false;
  for (size_t f = 1; f < kFingers; ++f) finger_on_fixed = finger_on_fixed || (s.finger_on_arm[f] & 1);
  const bool thumb_on_moving = (s.finger_on_arm[0] & 2) != 0;
  const bool grasp = thumb_on_moving && finger_on_fixed && posture_grasps;
  if (grasp && !s.grasped) {
    // The grasp starts: from now on the arm follows the thumb (eq. 1).
    s.hand_to_object = s.hand.inverse() * s.object_pose;
    s.thumb_in_object = s.object_pose.inverse() * s.fingertip[0];
    s.theta_command = s.theta;
    s.object_anchor = s.object_pose.translation();
  }
  s.grasped = grasp;

  // The hand's grasp of the actee (broken fragments leave no contacts). The
  // actee then moves with the hand, unless the jaws hold it: it follows them
  // then, and the hand takes it on from where they leave it.
  const bool in_hand = m.has_actee && posture_grasps && fingers_hold_actee(s);
  if (in_hand && (!s.actee_in_hand || s.held)) {
    s.hand_to_actee = s.hand.inverse() * s.actee_pose;
    if (!s.actee_in_hand && !s.held) s.actee_anchor = s.actee_pose.translation();  // picked up
  }
  s.actee_in_hand = in_hand;
}

}  // namespace afford
