// Stage 4: the actee's condition, and whether the jaws hold it.
#include <algorithm>
#include <cmath>

#include "stages.h"
#include "terms.h"

namespace afford {
namespace {

// The coefficient of friction where one arm's jaw touches the actee: a part
// with a surface of its own (rubber tips) gives its coefficient, else the
// actee's; of several parts touching, the one that slips first.
double jaw_friction(const Model& m, const State& s, Arm arm) {
  double mu = 0;
  for (size_t i = 0; i < m.parts.size(); ++i) {
    if (m.parts[i].arm != arm || i >= s.jaw_contact.size() || !s.jaw_contact[i].touching) continue;
    const double part = m.parts[i].friction > 0 ? m.parts[i].friction : m.actee_friction;
    mu = mu > 0 ? std::min(mu, part) : part;
  }
  return mu > 0 ? mu : m.actee_friction;
}

}  // namespace

void update_actee(const Model& m, State& s) {
  if (!m.has_actee) return;
  // Only the force's component along A_d counts against the limit (Fig. 6).
  const Eigen::Vector3d squeeze = s.object_pose.linear() * Eigen::Vector3d::UnitY();
  const Eigen::Vector3d direction = s.actee_pose.linear() * m.actee_direction;
  s.actee_load = s.actee_force * std::abs(squeeze.dot(direction));
  s.peak_actee_load = std::max(s.peak_actee_load, s.actee_load);
  s.grip_margin = grip_margin(jaw_friction(m, s, Arm::fixed), jaw_friction(m, s, Arm::moving), m.actee_mass, s.actee_force);
  if (s.condition == ActeeCondition::broken) return;
  if (m.actee_breaks && s.actee_load > m.actee_limit) {
    // Broken: the shell gives way and no longer holds the jaws apart.
    s.condition = ActeeCondition::broken;
    s.broke_at = s.t;
    s.held = false;  // between_jaws stays for this frame's contacts; the next frame clears it
    return;
  }
  s.condition = s.actee_force > 0 ? ActeeCondition::squeezed : ActeeCondition::intact;
  // Held: gripped between the jaws, and their friction carries its weight
  // (terms.h); it then moves with them.
  const bool held = s.blocked && s.actee_force > 0 && s.grip_margin >= 0;
  if (held && !s.held) s.actee_anchor = s.actee_pose.translation();  // picked up
  s.held = held;
}

}  // namespace afford
