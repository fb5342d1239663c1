#include "truth.h"

namespace gapcheck {

std::vector<std::string> Truth::names() const {
  std::vector<std::string> n;
  if (friction != 0) n.push_back("pivot_friction");
  if (damping != 0) n.push_back("viscous_damping");
  if (preload != 0) n.push_back("spring_preload");
  if (cubic != 0) n.push_back("progressive_spring");
  if (inertia != 0) n.push_back("arm_inertia");
  if (weight != 0) n.push_back("gravity");
  if (latency != 0) n.push_back("sensor_latency");
  if (actee_exponent != 0) n.push_back("actee_compliance");
  return n;
}

}  // namespace gapcheck
