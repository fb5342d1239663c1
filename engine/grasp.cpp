// Stage 2: agent-object contacts (fingertip spheres against the arms' parts)
// and the grasp that lets the thumb drive the lever.
#include "stages.h"

namespace afford {

void find_grasp(const Model& m, State& s) {
  s.agent_object.clear();
  s.finger_on_arm.fill(0);
  const Eigen::Isometry3d moving = s.object_pose * moving_arm_pose(s.theta);
  for (size_t f = 0; f < kFingers; ++f) {
    Eigen::Isometry3d tip = Eigen::Isometry3d::Identity();
    tip.translation() = s.fingertip[f];
    for (const ModelPart& part : m.parts) {
      const Eigen::Isometry3d pose =
          (part.arm == Arm::moving ? moving : s.object_pose) * part.in_arm;
      if (boxes_apart(m.fingertip[f], tip, part.geometry, pose, m.contact_tolerance)) continue;
      ContactPoint c;
      if (s.query->contact(m.fingertip[f], tip, part.geometry, pose, m.contact_tolerance, &c)) {
        s.agent_object.add(c);
        s.finger_on_arm[f] |= static_cast<std::uint8_t>(part.arm == Arm::moving ? 2 : 1);
      }
    }
  }
  bool finger_on_fixed = false;
  for (size_t f = 1; f < kFingers; ++f) finger_on_fixed = finger_on_fixed || (s.finger_on_arm[f] & 1);
  const bool thumb_on_moving = (s.finger_on_arm[0] & 2) != 0;
  const bool grasp = thumb_on_moving && finger_on_fixed;
  if (grasp && !s.grasped) {
    // The grasp starts: from now on the arm follows the thumb (eq. 1).
    s.hand_to_object = s.hand.inverse() * s.object_pose;
    s.thumb_in_object = s.object_pose.inverse() * s.fingertip[0];
    s.theta_command = s.theta;
  }
  s.grasped = grasp;
}

}  // namespace afford
