// Where the jaws meet the actee: found once per placement by a search on
// the opening angle with distance queries, so that a frame needs none.
#include <cmath>
#include <limits>

#include "stages.h"

namespace afford {

Eigen::Isometry3d part_in_object(const ModelPart& part, double theta_rad) {
  return part.arm == Arm::moving ? moving_arm_pose(theta_rad) * part.in_arm : part.in_arm;
}

namespace {

// Where the search for the contact angle stops: the moving jaw is this
// close to the actee (m), or the angle is bracketed this tightly (rad).
constexpr double kContactGap = 1e-11;
constexpr double kAngleBracket = 1e-12;
// The gap (m) at which the load's lever arm is read: large enough that
// GJK's 1e-12 m leaves the normal known to 1e-7 (the closed forms give it
// exactly), small enough that the extrapolation to the touch errs by less
// than 1e-11 m.
constexpr double kLeverGap = 1e-5;

// The actee and the moving part nearest it at angle theta.
struct MovingGap {
  double gap = std::numeric_limits<double>::infinity();  // m, 0 when touching
  double slope = 0;  // m/rad, d gap / d theta (opening widens the gap)
  Eigen::Vector3d across = Eigen::Vector3d::Zero();  // from the part to the actee, where apart
};

// `near`: the last answer, whose direction starts the distance queries.
MovingGap moving_gap(const Model& m, const Eigen::Isometry3d& actee_in_object, ContactQuery& query, double theta,
                     const MovingGap& near = {}) {
  MovingGap g;
  for (const ModelPart& part : m.parts) {
    if (part.arm != Arm::moving) continue;
    Eigen::Vector3d on_part, on_actee;
    const double d = query.distance(part.geometry, part_in_object(part, theta), m.actee(), actee_in_object, &on_part,
                                    &on_actee, near.across);
    if (d >= g.gap) continue;
    g.across = d > 0 ? Eigen::Vector3d(on_actee - on_part) : Eigen::Vector3d::Zero();
    g.gap = d;
    // The part's nearest point turns about the hinge (z): it moves by
    // z x p per radian, and the gap changes by that along the line to
    // the actee (the nearest points stay nearest to first order).
    g.slope = d > 0 ? -(on_actee - on_part).dot(Eigen::Vector3d::UnitZ().cross(on_part)) / d : 0;
  }
  return g;
}

// The moment arm (m) about the hinge of a push along the line between
// moving `part` at theta (rad) and the actee: |(p x n).z|, p the part's
// nearest point and n the unit normal (the same in any frame turned about
// z); -1 where they touch. `gap` (m): their distance.
double push_arm(const Model& m, const ModelPart& part, const Eigen::Isometry3d& actee_in_object, ContactQuery& query,
                double theta, double* gap) {
  Eigen::Vector3d on_part, on_actee;
  *gap = query.distance(part.geometry, part_in_object(part, theta), m.actee(), actee_in_object, &on_part, &on_actee);
  if (!(*gap > 0)) return -1;
  const Eigen::Vector3d n = (on_actee - on_part) / *gap;
  return std::abs(on_part.x() * n.y() - on_part.y() * n.x());
}

// Whether every moving part is apart from the actee at theta (rad).
bool moving_apart(const Model& m, const Eigen::Isometry3d& actee_in_object, ContactQuery& query, double theta) {
  for (const ModelPart& part : m.parts) {
    if (part.arm == Arm::moving && !query.apart(part.geometry, part_in_object(part, theta), m.actee(), actee_in_object, 0))
      return false;
  }
  return true;
}

}  // namespace

JawFit find_contact_angle(const Model& m, const Eigen::Isometry3d& actee_in_object,
                          ContactQuery& query, double* theta_c, double* load_distance,
                          std::vector<JawContact>* contacts) {
  // Fully open and already touching: it does not fit in the jaws.
  if (!moving_apart(m, actee_in_object, query, m.theta_max)) return JawFit::too_large;
  // Fully closed and still apart: the moving jaw never reaches it.
  if (moving_apart(m, actee_in_object, query, m.theta_min)) return JawFit::out_of_reach;

  // Where each part touches it: asked with the pair half a tolerance apart
  // (the moving jaw a little open, the actee a little above the fixed
  // jaw's face), so that the query is a distance, not a collision, and
  // allocates nothing; the point is the middle of that small gap.
  const double half = 0.5 * m.contact_tolerance;
  const double r = std::max(std::abs(actee_in_object.translation().x()), 1e-6);
  Eigen::Isometry3d lifted = actee_in_object;
  lifted.translation().y() += half;
  // Whether part i touches it with the moving arm at theta (rad).
  auto touch = [&](size_t i, double theta) {
    const ModelPart& part = m.parts[i];
    const bool moving = part.arm == Arm::moving;
    ContactPoint c;
    const bool touching = query.contact(part.geometry, part_in_object(part, moving ? theta + half / r : theta),
                                        m.actee(), moving ? actee_in_object : lifted, m.contact_tolerance, &c);
    if (contacts == nullptr) return touching;
    JawContact& jc = (*contacts)[i];
    jc.touching = touching;
    if (touching) {
      const Eigen::Isometry3d arm = moving ? moving_arm_pose(theta) : Eigen::Isometry3d::Identity();
      jc.in_arm.point = arm.inverse() * c.point;
      jc.in_arm.normal = arm.linear().transpose() * c.normal;
      jc.in_arm.distance = c.distance;
    }
    return touching;
  };
  // The moving jaw presses the actee onto the fixed jaw; an actee not resting
  // on the fixed arm would be pushed away rather than gripped. The fixed
  // arm does not turn: this is known before the search (and spares it
  // while a tool is lifted off an actee).
  bool on_fixed = false;
  for (size_t i = 0; i < m.parts.size(); ++i)
    if (m.parts[i].arm == Arm::fixed) on_fixed = touch(i, m.theta_max) || on_fixed;
  if (!on_fixed) return JawFit::not_on_fixed_jaw;

  // Newton's method from the open side, which the gap's slope makes exact
  // to second order, aimed a little short (at a fraction `aim` of the gap)
  // so that the curvature does not carry it into the actee; where it
  // would leave the bracket, or after it did step into the actee (and
  // then aiming shorter), a bisection.
  MovingGap at_open = moving_gap(m, actee_in_object, query, m.theta_max);
  double open = m.theta_max, closed = m.theta_min;
  double aim = 1.0 / 64;
  bool overshot = false;
  for (int i = 0; i < 200 && open - closed > kAngleBracket && at_open.gap > kContactGap; ++i) {
    double next = 0.5 * (open + closed);
    if (!overshot && at_open.slope > 0) {
      const double newton = open - (1 - aim) * at_open.gap / at_open.slope;
      if (newton > closed && newton < open) next = newton;
    }
    const MovingGap g = moving_gap(m, actee_in_object, query, next, at_open);
    overshot = !(g.gap > 0);
    if (overshot) {
      closed = next;
      aim = std::min(0.5, 4 * aim);
    } else {
      open = next;
      at_open = g;
    }
  }
  // The load's lever arm: the moment about the hinge (z) of a unit force
  // along the normal where the moving jaw touches it (the nearest moving
  // part if several are close). The paper's D_ac is the actee's distance
  // along the arm, but the jaw pushes where it touches: a sphere resting on
  // the fixed jaw is touched right at its centre's distance (the two
  // tangents from the hinge are equally long), an elongated nut is not (the
  // walnut at 60 mm at 56.4 mm), and MuJoCo, which pushes at the contact,
  // agrees. Read with the jaw opened by one, two and three kLeverGap, where
  // the nearest points and their normal are well defined, and extrapolated
  // to the touch: the error is third order in that opening.
  double arm = 0, nearest = std::numeric_limits<double>::infinity();
  size_t pushing = m.parts.size();
  for (size_t i = 0; i < m.parts.size(); ++i) {
    if (m.parts[i].arm != Arm::moving) continue;
    touch(i, open);
    double gap = 0;
    const double once = push_arm(m, m.parts[i], actee_in_object, query, open + kLeverGap / r, &gap);
    if (once >= 0 && gap < nearest) {
      nearest = gap;
      arm = once;
      pushing = i;
    }
  }
  if (pushing < m.parts.size()) {
    double gap = 0;
    const ModelPart& part = m.parts[pushing];
    const double twice = push_arm(m, part, actee_in_object, query, open + 2 * kLeverGap / r, &gap);
    const double thrice = push_arm(m, part, actee_in_object, query, open + 3 * kLeverGap / r, &gap);
    if (twice >= 0 && thrice >= 0) arm = 3 * arm - 3 * twice + thrice;
  }
  // No reading (the jaw opened by kLeverGap is apart by construction):
  // the actee's own distance.
  if (!(arm > 0)) arm = std::abs(actee_in_object.translation().x());
  *theta_c = open;
  *load_distance = std::copysign(arm, actee_in_object.translation().x());
  return JawFit::fits;
}

}  // namespace afford
