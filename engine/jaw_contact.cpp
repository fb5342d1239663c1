// Where the jaws meet the actee: found once per placement by bisection on
// the opening angle with FCL distance queries, so that a frame needs none.
#include "stages.h"

namespace afford {

Eigen::Isometry3d part_in_object(const ModelPart& part, double theta_rad) {
  return part.arm == Arm::moving ? moving_arm_pose(theta_rad) * part.in_arm : part.in_arm;
}

namespace {

// Distance from the actee to the nearest moving part at angle theta, m.
double moving_gap(const Model& m, const Eigen::Isometry3d& actee_in_object, ContactQuery& query,
                  double theta) {
  double gap = std::numeric_limits<double>::infinity();
  for (const ModelPart& part : m.parts) {
    if (part.arm != Arm::moving) continue;
    gap = std::min(gap, query.distance(part.geometry, part_in_object(part, theta), m.actee(),
                                       actee_in_object));
  }
  return gap;
}

}  // namespace

JawFit find_contact_angle(const Model& m, const Eigen::Isometry3d& actee_in_object,
                          ContactQuery& query, double* theta_c, std::vector<JawContact>* contacts) {
  // Fully open and already touching: it does not fit in the jaws.
  if (moving_gap(m, actee_in_object, query, m.theta_max) <= 0) return JawFit::too_large;
  // Fully closed and still apart: the moving jaw never reaches it.
  if (moving_gap(m, actee_in_object, query, m.theta_min) > 0) return JawFit::out_of_reach;
  double open = m.theta_max, closed = m.theta_min;
  for (int i = 0; i < 60 && open - closed > 1e-12; ++i) {
    const double mid = 0.5 * (open + closed);
    (moving_gap(m, actee_in_object, query, mid) > 0 ? open : closed) = mid;
  }
  // The moving jaw presses the actee onto the fixed jaw; an actee not resting
  // on the fixed arm would be pushed away rather than gripped.
  // Where each part touches it: asked with the pair half a tolerance apart
  // (the moving jaw a little open, the actee a little above the fixed
  // jaw's face), so that the query is a distance, not a collision, and
  // allocates nothing; the point is the middle of that small gap.
  const double half = 0.5 * m.contact_tolerance;
  const double r = std::max(std::abs(actee_in_object.translation().x()), 1e-6);
  Eigen::Isometry3d lifted = actee_in_object;
  lifted.translation().y() += half;
  bool on_fixed = false;
  for (size_t i = 0; i < m.parts.size(); ++i) {
    const ModelPart& part = m.parts[i];
    const bool moving = part.arm == Arm::moving;
    const Eigen::Isometry3d pose = part_in_object(part, moving ? open + half / r : open);
    ContactPoint c;
    const bool touching = query.contact(part.geometry, pose, m.actee(), moving ? actee_in_object : lifted,
                                        m.contact_tolerance, &c);
    on_fixed = on_fixed || (touching && part.arm == Arm::fixed);
    if (contacts == nullptr) continue;
    JawContact& jc = (*contacts)[i];
    jc.touching = touching;
    if (touching) {
      const Eigen::Isometry3d arm = part.arm == Arm::moving ? moving_arm_pose(open) : Eigen::Isometry3d::Identity();
      jc.in_arm.point = arm.inverse() * c.point;
      jc.in_arm.normal = arm.linear().transpose() * c.normal;
      jc.in_arm.distance = c.distance;
    }
  }
  if (!on_fixed) return JawFit::not_on_fixed_jaw;
  *theta_c = open;
  return JawFit::fits;
}

}  // namespace afford
