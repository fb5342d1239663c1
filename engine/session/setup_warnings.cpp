// The hand against the spring (setup_warnings.h).
#include "setup_warnings.h"

#include <cmath>

#include "derive.h"
#include "stages.h"
#include "terms.h"
#include "units.h"

namespace afford {

std::string Warning::str() const { return loc.str() + ": warning: " + message; }

std::vector<Warning> setup_warnings(const Model& m, const SourceLoc& spring) {
  std::vector<Warning> out;
  if (!m.has_agent) return out;
  const double far = std::abs(m.emphasis_to) > std::abs(m.emphasis_from) ? m.emphasis_to : m.emphasis_from;
  const std::string hand = "the agent (" + m.agent_name + ", at most " + format_quantity(m.max_force, dim::force) + ")";
  const std::string at_far = " at " + format_quantity(far, dim::length) + ", the far end of the emphasis region";
  const double to_leave_rest = effort_for_load(m, m.theta_rest, far, 0, 0);
  if (to_leave_rest > m.max_force) {
    out.push_back({spring, hand + " can never move the arm: the spring pushes " +
                               format_quantity(spring_force(m, m.theta_rest), dim::force) + " at rest (" +
                               format_quantity(m.theta_rest, dim::angle) + "), which takes " +
                               format_quantity(to_leave_rest, dim::force) + at_far});
    return out;  // closing on an actee is then out of reach too
  }
  if (!m.has_actee) return out;
  ContactQuery query;
  double theta_c = 0, load_distance = 0;
  const Eigen::Isometry3d actee_in_object = m.object_start.inverse() * m.actee_start;
  if (find_contact_angle(m, actee_in_object, query, &theta_c, &load_distance, nullptr) != JawFit::fits) return out;
  const double to_touch = effort_for_load(m, theta_c, far, 0, 0);
  if (to_touch > m.max_force) {
    out.push_back({spring, hand + " can never close the jaws on the " + m.actee_name + ": at " +
                               format_quantity(theta_c, dim::angle) + ", where they touch it, the spring pushes " +
                               format_quantity(spring_force(m, theta_c), dim::force) + ", which takes " +
                               format_quantity(to_touch, dim::force) + at_far});
  }
  return out;
}

}  // namespace afford
