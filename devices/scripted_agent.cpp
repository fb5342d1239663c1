#include "scripted_agent.h"

#include <algorithm>
#include <cmath>

namespace afford {

bool ScriptedAgent::sample_at(double t, Sample* out) {
  const std::vector<Keyframe>& k = script_.keyframes;
  if (k.empty() || t > script_.duration()) return false;
  // The segment [a, b] holding t; u in [0, 1] along it.
  const auto after = std::upper_bound(k.begin(), k.end(), t, [](double v, const Keyframe& f) { return v < f.t; });
  const Keyframe& b = after == k.end() ? k.back() : *after;
  const Keyframe& a = after == k.begin() ? k.front() : *(after - 1);
  const double u = (&a == &b) ? 0.0 : (t - a.t) / (b.t - a.t);
  // std::lerp: exactly a at u = 0 and b at u = 1, and exactly a wherever
  // a == b: a value the script holds stays bit for bit the same (the engine
  // compares poses bitwise to skip work).
  const auto lerp3 = [u](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
    return Eigen::Vector3d(std::lerp(x.x(), y.x(), u), std::lerp(x.y(), y.y(), u), std::lerp(x.z(), y.z(), u));
  };
  out->t = t;
  out->hand.setIdentity();
  const bool turning = !(a.hand_rotation.coeffs() == b.hand_rotation.coeffs());
  out->hand.linear() = (turning ? a.hand_rotation.slerp(u, b.hand_rotation) : a.hand_rotation).toRotationMatrix();
  out->hand.translation() = lerp3(a.hand_position, b.hand_position);
  // A squeeze turns the thumb about the pivot (script.h).
  const bool arc = a.grip && b.grip && a.thumb_rest == b.thumb_rest &&
                   a.object_in_hand.matrix() == b.object_in_hand.matrix();
  for (size_t f = 0; f < kFingers; ++f) {
    const Eigen::Vector3d in_hand = (f == 0 && arc) ? grip_thumb(a, std::lerp(a.thumb_angle, b.thumb_angle, u))
                                                    : lerp3(a.fingertip[f], b.fingertip[f]);
    out->fingertip[f] = out->hand * in_hand;
    for (size_t j = 0; j < kJoints; ++j) out->joint[f][j] = std::lerp(a.joint[f][j], b.joint[f][j], u);
  }
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
