// The hand's reach: planar finger chains within the joint ranges (reach.h).
#include "reach.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "model.h"

namespace afford {
namespace {

constexpr size_t kDistal = 0, kProximal = 1, kMetacarpal = 2;  // joint order of the agent file
constexpr double kGrid = 0.05 * std::numbers::pi / 180;         // rad, the proximal angle's step

// The proximal and distal angles (rad) where the tip is nearest to and
// farthest from the base. With l1, l2, l3 the links the metacarpal,
// proximal and distal joints turn,
//   D^2 = l1^2 + l2^2 + l3^2 + 2 l1 l2 cos q2 + 2 l2 l3 cos q3 + 2 l1 l3 cos(q2 + q3)
//       = c(q2) + R(q2) cos(q3 + psi(q2)),
// so for each q2 the extremes in q3 are at the range's ends or where
// q3 + psi is a multiple of pi.
struct Extremes {
  double nearest2 = std::numeric_limits<double>::infinity(), farthest2 = -1;  // m^2
  std::array<double, 2> near_q{}, far_q{};  // rad, {proximal, distal}
};

Extremes chain_extremes(const std::array<double, kJoints>& link, const std::array<double, kJoints>& lo,
                        const std::array<double, kJoints>& hi) {
  const double l1 = link[kMetacarpal], l2 = link[kProximal], l3 = link[kDistal];
  const double c0 = l1 * l1 + l2 * l2 + l3 * l3;
  const double span = hi[kProximal] - lo[kProximal];
  const int steps = std::max(1, static_cast<int>(std::ceil(span / kGrid)));
  Extremes e;
  auto consider = [&](double q2, double q3, double d2) {
    if (d2 < e.nearest2) {
      e.nearest2 = d2;
      e.near_q = {q2, q3};
    }
    if (d2 > e.farthest2) {
      e.farthest2 = d2;
      e.far_q = {q2, q3};
    }
  };
  for (int k = 0; k <= steps; ++k) {
    const double q2 = lo[kProximal] + span * static_cast<double>(k) / static_cast<double>(steps);
    const double c = c0 + 2 * l1 * l2 * std::cos(q2);
    const double re = 2 * l2 * l3 + 2 * l1 * l3 * std::cos(q2), im = 2 * l1 * l3 * std::sin(q2);
    const double r = std::hypot(re, im), psi = std::atan2(im, re);
    for (double q3 : {lo[kDistal], hi[kDistal]}) consider(q2, q3, c + r * std::cos(q3 + psi));
    for (int j = -4; j <= 4; ++j) {
      const double q3 = -psi + j * std::numbers::pi;
      if (q3 > lo[kDistal] && q3 < hi[kDistal]) consider(q2, q3, c + r * std::cos(q3 + psi));
    }
  }
  return e;
}

// A unit vector across u, toward the palm (-z of the hand frame) if it can be.
Eigen::Vector3d palmward_across(const Eigen::Vector3d& u) {
  Eigen::Vector3d w = -Eigen::Vector3d::UnitZ() + u.z() * u;  // -z minus its part along u
  if (w.norm() < 1e-9) w = Eigen::Vector3d::UnitX() - u.x() * u;
  return w.normalized();
}

}  // namespace

double chain_distance(const std::array<double, kJoints>& link, double proximal_rad, double distal_rad) {
  const double l1 = link[kMetacarpal], l2 = link[kProximal], l3 = link[kDistal];
  const double d2 = l1 * l1 + l2 * l2 + l3 * l3 + 2 * l1 * l2 * std::cos(proximal_rad) +
                    2 * l2 * l3 * std::cos(distal_rad) + 2 * l1 * l3 * std::cos(proximal_rad + distal_rad);
  return std::sqrt(std::max(0.0, d2));
}

void chain_range(const std::array<double, kJoints>& link, const std::array<double, kJoints>& lo,
                 const std::array<double, kJoints>& hi, double* nearest, double* farthest) {
  const Extremes e = chain_extremes(link, lo, hi);
  *nearest = std::sqrt(std::max(0.0, e.nearest2));
  *farthest = std::sqrt(std::max(0.0, e.farthest2));
}

void compile_reach(const AgentSpec& a, Model& m) {
  m.has_reach = a.has_reach;
  m.agent_file = a.file;
  if (!a.has_reach) return;
  for (size_t f = 0; f < kFingers; ++f) {
    const FingerSpec& finger = a.fingers[f];
    m.finger_base[f] = finger.base;
    m.link[f] = finger.link;
    chain_range(finger.link, finger.joint_min, finger.joint_max, &m.chain_min[f], &m.chain_max[f]);
    // The palm turns about the wrist: the base anywhere on its sphere.
    const double b = finger.base.norm();
    m.reach_max[f] = b + m.chain_max[f];
    m.reach_min[f] = std::max({0.0, m.chain_min[f] - b, b - m.chain_max[f]});
  }
}

double reach_short(const Model& m, int finger, const Eigen::Vector3d& tip) {
  const size_t f = static_cast<size_t>(finger);
  const double r = tip.norm();
  return std::max({0.0, r - m.reach_max[f], m.reach_min[f] - r});
}

Eigen::Vector3d nearest_reachable(const Model& m, int finger, const Eigen::Vector3d& tip) {
  const size_t f = static_cast<size_t>(finger);
  const double r = tip.norm();
  const double kept = std::clamp(r, m.reach_min[f], m.reach_max[f]);
  if (kept == r) return tip;
  const Eigen::Vector3d dir = r > 0 ? Eigen::Vector3d(tip / r) : Eigen::Vector3d::UnitX();
  return kept * dir;
}

FingerChain finger_chain(const Model& m, int finger, const Eigen::Vector3d& tip) {
  const size_t f = static_cast<size_t>(finger);
  FingerChain c;
  const Eigen::Vector3d target = nearest_reachable(m, finger, tip);
  c.short_by = (tip - target).norm();
  // Turn the base about the wrist, in the plane of base and target, until
  // the chain can span the distance.
  Eigen::Vector3d base = m.finger_base[f];
  double d = (target - base).norm();
  if (d > m.chain_max[f] || d < m.chain_min[f]) {
    const double span = d > m.chain_max[f] ? m.chain_max[f] : m.chain_min[f];
    const double b = base.norm(), r = target.norm();
    if (b > 0 && r > 0) {
      const Eigen::Vector3d along = target / r;
      Eigen::Vector3d side = base - base.dot(along) * along;
      side = side.norm() > 1e-12 ? Eigen::Vector3d(side.normalized()) : along.unitOrthogonal();
      const double cos_b = std::clamp((b * b + r * r - span * span) / (2 * b * r), -1.0, 1.0);
      base = b * (cos_b * along + std::sqrt(1 - cos_b * cos_b) * side);
    }
    d = (target - base).norm();
  }
  // The proximal and distal angles that span d: on the line from the
  // straightest posture to the most curled one (the distance runs from the
  // farthest to the nearest along it, so bisection finds a crossing).
  const Extremes e = chain_extremes(m.link[f], m.joint_min[f], m.joint_max[f]);
  double s_lo = 0, s_hi = 1;
  auto at = [&](double s, size_t i) { return e.far_q[i] + s * (e.near_q[i] - e.far_q[i]); };
  // At full stretch the distance is flat in the angles: take it as it is
  // (kStretched: the rounding of the base's turn).
  constexpr double kStretched = 1e-12;  // m
  const bool stretched = chain_distance(m.link[f], at(0, 0), at(0, 1)) <= d + kStretched;
  for (int i = 0; i < 60 && !stretched; ++i) {
    const double s = 0.5 * (s_lo + s_hi);
    (chain_distance(m.link[f], at(s, 0), at(s, 1)) > d ? s_lo : s_hi) = s;
  }
  const double q2 = at(s_lo, 0), q3 = at(s_lo, 1);
  // The chain in its plane (x along the first link, y toward the palm),
  // then turned so that its tip lies on the line from base to target.
  const std::array<double, kJoints> l = m.link[f];
  const Eigen::Vector2d p1(l[kMetacarpal], 0);
  const Eigen::Vector2d p2 = p1 + l[kProximal] * Eigen::Vector2d(std::cos(q2), std::sin(q2));
  const Eigen::Vector2d p3 = p2 + l[kDistal] * Eigen::Vector2d(std::cos(q2 + q3), std::sin(q2 + q3));
  const Eigen::Vector3d u = d > 0 ? Eigen::Vector3d((target - base) / d) : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d w = palmward_across(u);
  const double alpha = std::atan2(p3.y(), p3.x());
  const Eigen::Vector3d ex = std::cos(alpha) * u - std::sin(alpha) * w;  // the first link's direction
  const Eigen::Vector3d ey = std::sin(alpha) * u + std::cos(alpha) * w;
  auto place = [&](const Eigen::Vector2d& p) { return Eigen::Vector3d(base + p.x() * ex + p.y() * ey); };
  c.point = {base, place(p1), place(p2), place(p3)};
  c.angle[kDistal] = q3;
  c.angle[kProximal] = q2;
  c.angle[kMetacarpal] = std::acos(std::clamp(ex.x(), -1.0, 1.0));
  return c;
}

}  // namespace afford
