#include "point_session.h"

#include <algorithm>
#include <cmath>

#include "errors.h"
#include "squeeze.h"

namespace afford {
namespace {

// The hand's wrist sits this far behind the thumb along the arm and this far
// above the middle of the arm's height (tool frame): clear of the tool, as
// in the shipped sessions.
constexpr double kWristBehind = 0.07;  // m
constexpr double kWristAbove = 0.09;   // m


KeyframeSpec grip_keyframe(double t, double thumb, double squeeze) {
  KeyframeSpec k;
  k.t = t;
  k.fingers = FingerSource::grip;
  k.grip.thumb = thumb;
  k.grip.index = thumb;
  k.grip.squeeze = squeeze;
  return k;
}

}  // namespace

Script point_script(const Model& m, const ForcedLever& jaws, const PointDrive& drive, const PointTiming& timing) {
  if (!m.has_agent) throw LogicError("point_script() needs a model with its agent");
  const double r = drive.thumb;
  double face_y = 0, mid_z = 0, index_y = 0, index_z = 0;
  arm_outer_face(m, Arm::moving, r, &face_y, &mid_z);
  arm_outer_face(m, Arm::fixed, r, &index_y, &index_z);
  // The wrist midway across between the thumb (on the moving arm at rest,
  // turned about the hinge's z) and the index, so that a wide-open tool
  // keeps both within the fingers' reach (engine/model/reach.h).
  const double c = std::cos(m.theta_rest), s = std::sin(m.theta_rest);
  const double across = 0.5 * (r * s + face_y * c + index_y);  // m, tool frame y
  const double behind = r >= 0 ? -kWristBehind : kWristBehind;
  const Eigen::Vector3d wrist = m.object_start * Eigen::Vector3d(r + behind, across, mid_z + kWristAbove);
  const Eigen::Matrix3d palm_down = m.object_start.linear();

  // Where the jaws touch the actee, as a thumb advance; all of the effort's
  // squeeze when there is nothing between them.
  const double touch = jaws.actee ? std::max(0.0, std::abs(r) * (m.theta_rest - jaws.contact_angle)) : 0.0;
  const double push = squeeze_for_effort(m, jaws, r, drive.effort);

  ScriptSpec spec;
  double t = 0;
  KeyframeSpec first = grip_keyframe(t, r, 0);
  first.has_hand = true;
  first.hand.position = wrist;
  first.hand.rotation = palm_down;
  if (drive.grasp >= 0) {
    first.posture = PostureSource::named;
    first.posture_name = m.grasp_name[static_cast<size_t>(drive.grasp)];
  } else {
    // Without a taxonomy any posture grasps: the agent's relaxed one.
    first.posture = PostureSource::angles;
    for (size_t f = 0; f < kFingers; ++f) {
      for (size_t j = 0; j < kJoints; ++j) first.joint[f][j] = 0.5 * (m.joint_min[f][j] + m.joint_max[f][j]);
    }
  }
  spec.keyframes.push_back(first);
  spec.keyframes.push_back(grip_keyframe(t += timing.close, r, std::min(touch, push)));
  spec.keyframes.push_back(grip_keyframe(t += timing.squeeze, r, push));
  spec.keyframes.push_back(grip_keyframe(t += timing.hold, r, push));
  KeyframeSpec lifted = grip_keyframe(t += timing.lift, r, push);
  lifted.has_hand = true;
  lifted.hand.position = wrist + Eigen::Vector3d(0, 0, kLiftHeight);  // up, in the world
  lifted.hand.rotation = palm_down;
  spec.keyframes.push_back(lifted);
  KeyframeSpec still = lifted;
  still.t = t += timing.rest;
  spec.keyframes.push_back(still);
  return compile_script(spec, m);
}

}  // namespace afford
