#include "scripted_agent.h"

#include <algorithm>
#include <cmath>

namespace afford {

ScriptedAgent::ScriptedAgent(const Script& script) : script_(script) {
  const std::vector<Keyframe>& k = script.keyframes;
  spans_.resize(k.size() + 1);
  for (size_t i = 0; i < k.size() + 1 && !k.empty(); ++i) {
    const Keyframe& a = k[i == 0 ? 0 : i - 1];
    const Keyframe& b = k[i == k.size() ? i - 1 : i];
    Span& s = spans_[i];
    s.turning = !(a.hand_rotation.coeffs() == b.hand_rotation.coeffs());
    s.rotation = a.hand_rotation.toRotationMatrix();
    s.moving = !(a.hand_position == b.hand_position);
    // A squeeze turns the thumb about the pivot (script.h).
    s.arc = a.grip && b.grip && a.thumb_rest == b.thumb_rest && a.object_in_hand.matrix() == b.object_in_hand.matrix();
    for (size_t f = 0; f < kFingers; ++f) s.tip_moves[f] = !(a.fingertip[f] == b.fingertip[f]);
    s.joints_move = !(a.joint == b.joint);
  }
}

bool ScriptedAgent::sample_at(double t, Sample* out) {
  const std::vector<Keyframe>& k = script_.keyframes;
  if (k.empty() || t > script_.duration()) return false;
  // The span holding t: the first keyframe after t is k[i] (i = size: none).
  // Frames come in order, so the last span is asked first.
  auto holds = [&](size_t i) { return (i == 0 || k[i - 1].t <= t) && (i == k.size() || t < k[i].t); };
  if (!holds(last_)) {
    const auto after = std::upper_bound(k.begin(), k.end(), t, [](double v, const Keyframe& f) { return v < f.t; });
    last_ = static_cast<size_t>(after - k.begin());
  }
  const Span& span = spans_[last_];
  const Keyframe& a = k[last_ == 0 ? 0 : last_ - 1];
  const Keyframe& b = k[last_ == k.size() ? last_ - 1 : last_];
  const double u = (&a == &b) ? 0.0 : (t - a.t) / (b.t - a.t);  // in [0, 1] along the span
  // std::lerp: exactly a at u = 0 and b at u = 1, and exactly a wherever
  // a == b: a value the script holds stays bit for bit the same (the engine
  // compares poses bitwise to skip work).
  const auto lerp3 = [u](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
    return Eigen::Vector3d(std::lerp(x.x(), y.x(), u), std::lerp(x.y(), y.y(), u), std::lerp(x.z(), y.z(), u));
  };
  out->t = t;
  out->hand.setIdentity();
  out->hand.linear() = span.turning ? a.hand_rotation.slerp(u, b.hand_rotation).toRotationMatrix() : span.rotation;
  out->hand.translation() = span.moving ? lerp3(a.hand_position, b.hand_position) : a.hand_position;
  for (size_t f = 0; f < kFingers; ++f) {
    const Eigen::Vector3d in_hand = (f == 0 && span.arc) ? grip_thumb(a, std::lerp(a.thumb_angle, b.thumb_angle, u))
                                    : span.tip_moves[f]  ? lerp3(a.fingertip[f], b.fingertip[f])
                                                         : a.fingertip[f];
    out->fingertip[f] = out->hand * in_hand;
  }
  if (!span.joints_move) {
    out->joint = a.joint;
    return true;
  }
  for (size_t f = 0; f < kFingers; ++f)
    for (size_t j = 0; j < kJoints; ++j) out->joint[f][j] = std::lerp(a.joint[f][j], b.joint[f][j], u);
  return true;
}

std::vector<Sample> script_samples(const Script& script, double timestep) {
  ScriptedAgent agent(script);
  std::vector<Sample> samples;
  Sample sample;
  for (std::int64_t k = 1; agent.sample_at(static_cast<double>(k) * timestep, &sample); ++k) {
    sample.t = static_cast<double>(k) * timestep;
    samples.push_back(sample);
  }
  return samples;
}

}  // namespace afford
