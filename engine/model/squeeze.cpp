// Squeezes for forces (squeeze.h).
#include "squeeze.h"

#include <cmath>

#include "state.h"
#include "units.h"

namespace afford {
namespace {

// The forced balance is stepped with this step until the angle changes by
// less than kSettled: the implicit step damps any inertia, so it comes to
// rest in a few steps.
constexpr double kSettleStep = 0.01;  // s
constexpr double kSettled = 1e-12;    // rad
constexpr int kMaxSettleSteps = 10000;
constexpr int kBisections = 60;       // halvings of the effort's range: far below a micronewton

}  // namespace

ForcedLever lever_at_start(const Model& m) {
  const auto state = make_state(m);
  ForcedLever lever;
  lever.actee = m.has_actee && state->between_jaws;
  lever.load_distance = std::abs(state->load_distance);
  lever.contact_angle = state->contact_angle;
  lever.thickness = state->actee_thickness;
  lever.object_rotation = m.object_start.linear();
  return lever;
}

ForcedStep settle_under_effort(const Model& m, const ForcedLever& at_start, double thumb_m, double effort_n) {
  ForcedLever lever = at_start;
  lever.effort_distance = std::abs(thumb_m);
  ForcedStep now;
  now.theta = m.theta_rest;
  for (int i = 0; i < kMaxSettleSteps; ++i) {
    const ForcedStep step = step_forced_lever(m, lever, now.theta, now.omega, effort_n, kSettleStep);
    const bool settled = std::abs(step.theta - now.theta) < kSettled;
    now = step;
    if (settled) break;
  }
  return now;
}

double squeeze_for_effort(const Model& m, const ForcedLever& lever, double thumb_m, double effort_n) {
  const double theta = settle_under_effort(m, lever, thumb_m, effort_n).theta;
  return std::max(0.0, std::abs(thumb_m) * (m.theta_rest - theta) + effort_n / m.force_gain);
}

double effort_for_squeeze(const Model& m, const ForcedLever& lever, double thumb_m, double squeeze_m, double cap_n) {
  // The squeeze an effort needs grows with the effort: halve the range.
  if (squeeze_for_effort(m, lever, thumb_m, cap_n) <= squeeze_m) return cap_n;
  double lo = 0, hi = cap_n;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (squeeze_for_effort(m, lever, thumb_m, mid) < squeeze_m ? lo : hi) = mid;
  }
  return lo;
}

bool effort_for_actee_force(const Model& m, const ForcedLever& lever, double thumb_m, double force_n, double cap_n,
                            double* effort_n, std::string* why) {
  if (!lever.actee) {
    *why = "no actee lies between the jaws";
    return false;
  }
  if (m.actee_breaks && force_n > m.actee_limit) {
    *why = "the " + m.actee_name + " breaks at " + format_quantity(m.actee_limit, dim::force) + ", before " +
           format_quantity(force_n, dim::force);
    return false;
  }
  const double most = settle_under_effort(m, lever, thumb_m, cap_n).actee_force;
  if (most < force_n) {
    *why = "the hand's most, " + format_quantity(cap_n, dim::force) + " at " +
           format_quantity(std::abs(thumb_m), dim::length) + " from the fulcrum, gives the " + m.actee_name + " " +
           format_quantity(most, dim::force);
    return false;
  }
  // The actee's settled force grows with the effort: halve the range.
  double lo = 0, hi = cap_n;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (settle_under_effort(m, lever, thumb_m, mid).actee_force < force_n ? lo : hi) = mid;
  }
  *effort_n = hi;
  return true;
}

}  // namespace afford
