// Stage 5: the contacts of the three relations at the solved angle.
// Agent-object: fingertip spheres against the arms' parts, the thumb at its
// proxy on the arm's surface. Object-actee: from the placement's cache while
// the actee rests in the jaws, an FCL query otherwise. Agent-actee:
// fingertips against the actee. Broad boxes first, so that far pairs cost
// no query.
#include <cstring>

#include "stages.h"

namespace afford {
namespace {

// Every part's world pose and box at the solved angle, once a frame.
void place_parts(const Model& m, State& s) {
  // Most frames move neither the tool nor its arm (held still, or only
  // the fingers move): the last placement stands.
  const bool object_moved = !s.parts_placed || std::memcmp(s.object_pose.data(), s.parts_object_pose.data(),
                                                           sizeof(double) * 16) != 0;
  const bool arm_turned = object_moved || std::memcmp(&s.theta, &s.parts_theta, sizeof s.theta) != 0;
  if (!arm_turned) return;
  s.moving_arm_world = s.object_pose * moving_arm_pose(s.theta);
  for (size_t i = 0; i < m.parts.size(); ++i) {
    const ModelPart& part = m.parts[i];
    if (part.arm != Arm::moving && !object_moved) continue;
    s.part_pose[i] = (part.arm == Arm::moving ? s.moving_arm_world : s.object_pose) * part.in_arm;
    s.part_box[i] = world_box(part.geometry, s.part_pose[i]);
  }
  s.parts_object_pose = s.object_pose;
  s.parts_theta = s.theta;
  s.parts_placed = true;
}

// A fingertip sphere's world box.
WorldBox tip_box(const Model& m, size_t finger, const Eigen::Vector3d& centre) {
  return {centre, Eigen::Vector3d::Constant(m.tip_radius[finger])};
}

void agent_object(const Model& m, State& s) {
  s.agent_object.clear();
  s.finger_on_arm.fill(0);
  ContactPoint c;
  for (size_t f = 0; f < kFingers; ++f) {
    Eigen::Isometry3d tip = Eigen::Isometry3d::Identity();
    tip.translation() = (f == 0 && s.grasped) ? s.thumb_proxy : s.fingertip[f];
    const WorldBox box = tip_box(m, f, tip.translation());
    for (size_t i = 0; i < m.parts.size(); ++i) {
      if (boxes_apart(box, s.part_box[i], m.contact_tolerance)) continue;
      if (s.query->contact(m.fingertip[f], tip, m.parts[i].geometry, s.part_pose[i], m.contact_tolerance, &c)) {
        s.agent_object.add(c);
        s.finger_on_arm[f] |= static_cast<std::uint8_t>(m.parts[i].arm == Arm::moving ? 2 : 1);
      }
    }
  }
}

void object_actee(const Model& m, State& s) {
  s.object_actee.clear();
  s.actee_arms = 0;
  if (s.between_jaws) {
    // It rests on the fixed jaw; the moving jaw touches it once closed to
    // the contact angle (within the tolerance, as an angle at the actee).
    const double slack = m.contact_tolerance / std::max(std::abs(s.load_distance), 1e-6);
    const bool closed_on = s.theta <= s.contact_angle + slack;
    for (size_t i = 0; i < m.parts.size(); ++i) {
      const JawContact& jc = s.jaw_contact[i];
      const bool on_moving = m.parts[i].arm == Arm::moving;
      if (!jc.touching || (on_moving && !closed_on)) continue;
      const Eigen::Isometry3d& arm = on_moving ? s.moving_arm_world : s.object_pose;
      s.object_actee.add(ContactPoint{arm * jc.in_arm.point, arm.linear() * jc.in_arm.normal, jc.in_arm.distance});
      s.actee_arms |= static_cast<std::uint8_t>(on_moving ? 2 : 1);
    }
    return;
  }
  ContactPoint c;
  const WorldBox actee = world_box(m.actee(), s.actee_pose);
  for (size_t i = 0; i < m.parts.size(); ++i) {
    const ModelPart& part = m.parts[i];
    if (boxes_apart(s.part_box[i], actee, m.contact_tolerance)) continue;
    if (s.query->contact(part.geometry, s.part_pose[i], m.actee(), s.actee_pose, m.contact_tolerance, &c)) {
      s.object_actee.add(c);
      s.actee_arms |= static_cast<std::uint8_t>(part.arm == Arm::moving ? 2 : 1);
    }
  }
}

void agent_actee(const Model& m, State& s) {
  s.agent_actee.clear();
  ContactPoint c;
  const WorldBox actee = world_box(m.actee(), s.actee_pose);
  for (size_t f = 0; f < kFingers; ++f) {
    Eigen::Isometry3d tip = Eigen::Isometry3d::Identity();
    tip.translation() = s.fingertip[f];
    if (boxes_apart(tip_box(m, f, s.fingertip[f]), actee, m.contact_tolerance)) continue;
    if (s.query->contact(m.fingertip[f], tip, m.actee(), s.actee_pose, m.contact_tolerance, &c)) {
      s.agent_actee.add(c);
    }
  }
}

}  // namespace

void find_contacts(const Model& m, State& s) {
  place_parts(m, s);
  agent_object(m, s);
  // A broken actee is fragments: nothing left to touch or grip (from the
  // frame after the break: on that frame the jaws still touched it).
  if (!m.has_actee || (s.condition == ActeeCondition::broken && s.broke_at < s.t)) {
    s.object_actee.clear();
    s.actee_arms = 0;
    s.agent_actee.clear();
    return;
  }
  object_actee(m, s);
  agent_actee(m, s);
}

}  // namespace afford
