// Stage 2: the grasp that lets the thumb drive the lever. It follows the
// contacts of the last frame (stage 5), so a grasp starts one frame after
// the fingers touch.
#include "stages.h"

namespace afford {

void update_grasp(const Model&, State& s) {
  bool finger_on_fixed = false;
  for (size_t f = 1; f < kFingers; ++f) finger_on_fixed = finger_on_fixed || (s.finger_on_arm[f] & 1);
  const bool thumb_on_moving = (s.finger_on_arm[0] & 2) != 0;
  const bool grasp = thumb_on_moving && finger_on_fixed;
  if (grasp && !s.grasped) {
    // The grasp starts: from now on the arm follows the thumb (eq. 1).
    s.hand_to_object = s.hand.inverse() * s.object_pose;
    s.thumb_in_object = s.object_pose.inverse() * s.fingertip[0];
    s.theta_command = s.theta;
    s.object_anchor = s.object_pose.translation();
  }
  s.grasped = grasp;
}

}  // namespace afford
