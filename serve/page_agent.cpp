// The hand a page drives (page_agent.h).
#include "page_agent.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "errors.h"
#include "grasps.h"

namespace afford::serve {

namespace {

Eigen::Isometry3d pose_of(const Eigen::Vector3d& position, const Eigen::Quaterniond& rotation) {
  Eigen::Isometry3d iso = Eigen::Isometry3d::Identity();
  iso.linear() = rotation.toRotationMatrix();
  iso.translation() = position;
  return iso;
}

double toward(double value, double target, double step) {
  if (value < target) return std::min(target, value + step);
  return std::max(target, value - step);
}

}  // namespace

PageGrip page_grip(const CompiledSession& session) {
  const Model& m = session.model;
  PageGrip g;
  for (const Keyframe& k : session.script.keyframes) {
    if (!k.grip || !k.grasps) continue;
    g.thumb_rest = k.thumb_rest;
    g.thumb_distance = std::abs(k.thumb_rest.x());
    g.index = k.object_in_hand.inverse() * k.fingertip[1];
    g.joint = k.joint;
    const int type = m.grasp_name.empty() ? -1 : classify_grasp(m, k.joint);
    if (type >= 0) g.posture = m.grasp_name[static_cast<size_t>(type)];
    if (g.thumb_distance > 0) return g;
  }
  // No grip in the script: the middle of the emphasis region, both fingers.
  GripSpec spec;
  spec.thumb = spec.index = 0.5 * (m.emphasis_from + m.emphasis_to);
  double angle = 0;
  try {
    grip_points(m, spec, &g.thumb_rest, &angle, &g.index);
  } catch (const DataError& e) {
    throw std::runtime_error("the session's script has no grip, and its tool cannot be gripped at the middle of "
                             "its emphasis region: " + std::string(e.what()));
  }
  g.thumb_distance = std::abs(g.thumb_rest.x());
  for (size_t i = 0; i < m.grasp_name.size(); ++i) {
    std::string why;
    JointAngles joint{};
    if (!grasp_posture(m, static_cast<int>(i), &joint, &why) || classify_grasp(m, joint) != static_cast<int>(i)) {
      continue;
    }
    g.joint = joint;
    g.posture = m.grasp_name[i];
    return g;
  }
  if (m.grasp_name.empty()) return g;  // no taxonomy: contact alone grasps
  throw std::runtime_error("the session's script has no grip, and the hand can take no grasp type of its taxonomy");
}

PageStart page_start(const CompiledSession& session) {
  if (session.script.keyframes.empty()) throw LogicError("page_start(): a session without keyframes");
  const Keyframe& k = session.script.keyframes.front();
  PageStart s;
  s.hand_position = k.hand_position;
  s.hand_rotation = k.hand_rotation;
  s.open_fingertip = k.grip ? kCurledFingertip : k.fingertip;
  s.open_joint = k.joint;
  return s;
}

CommandLimits command_limits(const Model& model, const PageGrip& grip, const PageStart& start) {
  CommandLimits l;
  l.max_squeeze = grip.thumb_distance * std::max(0.0, model.theta_rest - model.theta_min) + 0.03;
  for (int i = 0; i < 3; ++i) {
    l.hand_min[static_cast<size_t>(i)] = start.hand_position[i] - 0.3;
    l.hand_max[static_cast<size_t>(i)] = start.hand_position[i] + 0.3;
  }
  return l;
}

PageAgent::PageAgent(const Model& model, const PageGrip& grip, const PageStart& start)
    : model_(model), grip_(grip), start_(start) {
  hand_ = hand_target_ = start.hand_position;
  object_world_ = model.object_start;
}

void PageAgent::apply(const Command& c) {
  if (c.seq >= 0) applied_seq_ = c.seq;
  switch (c.kind) {
    case CommandKind::thumb:
      squeeze_target_ = c.squeeze;
      break;
    case CommandKind::grasp:
      if (closing_) break;
      closing_ = true;
      if (!holding_) object_in_hand_ = pose_of(hand_, start_.hand_rotation).inverse() * object_world_;
      break;
    case CommandKind::release:
      squeeze_target_ = 0;
      if (!closing_) break;
      closing_ = false;
      if (holding_) object_world_ = pose_of(hand_, start_.hand_rotation) * object_in_hand_;
      holding_ = false;
      break;
    case CommandKind::move:
      hand_target_ = Eigen::Vector3d(c.position[0], c.position[1], c.position[2]);
      break;
    case CommandKind::actee:
    case CommandKind::reset:
      break;  // the server's: a new trial
  }
}

void PageAgent::sample(double t, Sample* out) {
  const double dt = std::max(0.0, t - last_t_);
  last_t_ = std::max(last_t_, t);
  blend_ = closing_ ? std::min(1.0, blend_ + dt / kCloseTime) : std::max(0.0, blend_ - dt / kCloseTime);
  if (closing_ && blend_ == 1.0) holding_ = true;
  squeeze_ = toward(squeeze_, squeeze_target_, kSqueezeRate * dt);
  if (blend_ == 0.0 || blend_ == 1.0) {  // the hand stays still while the fingers close or open
    const Eigen::Vector3d to = hand_target_ - hand_;
    const double step = kHandSpeed * dt, left = to.norm();
    hand_ = left <= step ? hand_target_ : Eigen::Vector3d(hand_ + to * (step / left));
  }
  const Eigen::Isometry3d hand = pose_of(hand_, start_.hand_rotation);

  std::array<Eigen::Vector3d, kFingers> closed = kCurledFingertip;
  const double angle = model_.theta_rest - squeeze_ / grip_.thumb_distance;
  closed[0] = object_in_hand_ * (Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()) * grip_.thumb_rest);
  closed[1] = object_in_hand_ * grip_.index;

  out->t = t;
  out->hand = hand;
  for (size_t f = 0; f < kFingers; ++f) {
    const Eigen::Vector3d& a = start_.open_fingertip[f];
    const Eigen::Vector3d tip = blend_ == 1.0 ? closed[f] : blend_ == 0.0 ? a : Eigen::Vector3d(a + blend_ * (closed[f] - a));
    out->fingertip[f] = hand * tip;
    for (size_t j = 0; j < kJoints; ++j) {
      const double o = start_.open_joint[f][j], c = grip_.joint[f][j];
      out->joint[f][j] = blend_ == 1.0 ? c : blend_ == 0.0 ? o : o + blend_ * (c - o);
    }
  }
}

}  // namespace afford::serve
