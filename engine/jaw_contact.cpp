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

bool find_contact_angle(const Model& m, const Eigen::Isometry3d& actee_in_object,
                        ContactQuery& query, double* theta_c) {
  // Fully open and already touching: it does not fit in the jaws.
  if (moving_gap(m, actee_in_object, query, m.theta_max) <= 0) return false;
  // Fully closed and still apart: the moving jaw never reaches it.
  if (moving_gap(m, actee_in_object, query, m.theta_min) > 0) return false;
  double open = m.theta_max, closed = m.theta_min;
  for (int i = 0; i < 60 && open - closed > 1e-12; ++i) {
    const double mid = 0.5 * (open + closed);
    (moving_gap(m, actee_in_object, query, mid) > 0 ? open : closed) = mid;
  }
  // The moving jaw presses the actee onto the fixed jaw; an actee not resting
  // on the fixed arm would be pushed away rather than gripped.
  for (const ModelPart& part : m.parts) {
    if (part.arm == Arm::fixed &&
        query.distance(part.geometry, part.in_arm, m.actee(), actee_in_object) <= m.contact_tolerance) {
      *theta_c = open;
      return true;
    }
  }
  return false;
}

}  // namespace afford
