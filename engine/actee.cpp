// Stages 4 and 5: the actee's condition, and the contacts that involve it.
#include <cmath>

#include "stages.h"

namespace afford {

void update_actee(const Model& m, State& s) {
  if (!m.has_actee) return;
  // Only the force's component along A_d counts against the limit (Fig. 6).
  const Eigen::Vector3d squeeze = s.object_pose.linear() * Eigen::Vector3d::UnitY();
  const Eigen::Vector3d direction = s.actee_pose.linear() * m.actee_direction;
  s.actee_load = s.actee_force * std::abs(squeeze.dot(direction));
  s.peak_actee_load = std::max(s.peak_actee_load, s.actee_load);
  if (s.condition == ActeeCondition::broken) return;
  if (m.actee_breaks && s.actee_load > m.actee_limit) {
    // Broken: the shell gives way and no longer holds the jaws apart.
    s.condition = ActeeCondition::broken;
    s.broke_at = s.t;
    s.between_jaws = false;
    s.held = false;
    return;
  }
  s.condition = s.actee_force > 0 ? ActeeCondition::squeezed : ActeeCondition::intact;
  // Held: gripped between the jaws with some force; it then moves with them.
  s.held = s.blocked && s.actee_force > 0;
}

void find_actee_contacts(const Model& m, State& s) {
  s.object_actee.clear();
  s.agent_actee.clear();
  // A broken actee is fragments: nothing left to touch or grip.
  if (!m.has_actee || s.condition == ActeeCondition::broken) return;
  const double tol = m.contact_tolerance;
  const Eigen::Isometry3d moving = s.object_pose * moving_arm_pose(s.theta);
  ContactPoint c;
  for (const ModelPart& part : m.parts) {
    const Eigen::Isometry3d pose = (part.arm == Arm::moving ? moving : s.object_pose) * part.in_arm;
    if (boxes_apart(part.geometry, pose, m.actee(), s.actee_pose, tol)) continue;
    if (s.query->contact(part.geometry, pose, m.actee(), s.actee_pose, tol, &c)) s.object_actee.add(c);
  }
  for (size_t f = 0; f < kFingers; ++f) {
    Eigen::Isometry3d tip = Eigen::Isometry3d::Identity();
    tip.translation() = s.fingertip[f];
    if (boxes_apart(m.fingertip[f], tip, m.actee(), s.actee_pose, tol)) continue;
    if (s.query->contact(m.fingertip[f], tip, m.actee(), s.actee_pose, tol, &c)) s.agent_actee.add(c);
  }
}

}  // namespace afford
