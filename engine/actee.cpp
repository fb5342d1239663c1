// Stage 4: the actee's condition, and whether the jaws hold it.
#include <cmath>

#include "stages.h"

namespace afford {

void update_actee(const Model& m, State& s) {
  if (!m.has_actee) return;
  // Only the force's component along A_d counts against the limit (Fig. 6).
  const Eigen::Vector3d squeeze = s.object_pose.linear() * Eigen::Vector3d::UnitY();
  const Eigen::Vector3d direction = s.actee_pose.linear() * m.actee_direction;
  s.actee_load = s.actee_force * std::abs(squeeze.dot(direction));
  s.peak_actee_load = std::max(s.peak_actee_load, s.actee_load);
  if (s.condition == ActeeCondition::broken) return;
  if (m.actee_breaks && s.actee_load > m.actee_limit) {
    // Broken: the shell gives way and no longer holds the jaws apart.
    s.condition = ActeeCondition::broken;
    s.broke_at = s.t;
    s.held = false;  // between_jaws stays for this frame's contacts; the next frame clears it
    return;
  }
  s.condition = s.actee_force > 0 ? ActeeCondition::squeezed : ActeeCondition::intact;
  // Held: gripped between the jaws with some force; it then moves with them.
  const bool held = s.blocked && s.actee_force > 0;
  if (held && !s.held) s.actee_anchor = s.actee_pose.translation();  // picked up
  s.held = held;
}

}  // namespace afford
