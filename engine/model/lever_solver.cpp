// Stage 3: the lever-spring solver (paper Sec. 4.3.1-4.3.2, DESIGN.md).
//
// Moment balance about the fulcrum decides the angle every frame. Forces act
// along each point's direction of rotation and displacements are measured
// along the arc, so virtual work and moment balance agree:
//
//     F_ag * D_ag = S_k * d * D_s + F_acr * D_ac + stop + (enabled effects)
//
// The paper's eq. (5) writes F_agr = F_agr' * D_ag/D_s + F_acr * D_ag/D_ac,
// which inverts both distance ratios: a nutcracker would then weaken the
// hand. We follow the physics (as eqs. 6-8 do):
//
//     F_agr = (S_k * d * D_s + F_acr * D_ac + ...) / D_ag.
//
// How eqs. (3) and (7) are read. The device gives where the thumb wants to
// be (its motion projected on the rotation direction L_d, eq. 1), not a
// force. Eq. (3), F_ag = F_agr + f_a * v, says the hand pushes harder the
// further it moves on against the tool; read with f_a in N/m (so that the
// result does not depend on the frame rate), the hand is a spring of
// stiffness f_a between the tracked thumb and the emphasis point, with
// optional damping, its push capped by the force limit in force (the
// agent's, capped by the grasp type's). Eq. (7), F_ac = (F_ag' - S_k d)
// D_ac/D_s, then says the actee gets what the hand's torque leaves after the
// spring; here it also leaves what every other term takes. So a stiffer
// spring, a stiff pivot or a weak hand change the angle, the actee's force
// and so the verdict.
//
// Integration: implicit (backward) Euler on the angle. With the angle at
// the end of the frame as the unknown, every term is a monotone function of
// it (the hand pushes more the further the arm is behind the thumb, the
// spring and the actee push less the further the arm is open, inertia and
// damping grow with the step), so the balance has one root, found by
// Newton's method kept inside a bracket. This is stable at the 1 ms step for
// any stiffness, damping or inertia, and without inertia or damping it is
// the quasi-static balance itself. Coulomb friction is set-valued at rest:
// the arm stays while the net torque is below the friction torque (stiction,
// no chatter at zero speed) and otherwise moves with the friction against
// it.
#include <algorithm>
#include <cmath>

#include "lever.h"
#include "stages.h"
#include "forced_lever.h"
#include "terms.h"

namespace afford {
namespace {

// A thumb closer to the fulcrum than this cannot turn the lever (and would
// divide by nearly zero).
constexpr double kMinLeverArm = 1e-3;  // m

// The balance at a candidate angle theta for the end of this frame. Its
// value is the net closing torque, N*m: the agent's torque minus every
// opening term, inertia and damping included (d'Alembert), friction
// excepted; it increases with theta.
struct Balance {
  const Model& m;
  double theta0 = 0, omega0 = 0;  // rad, rad/s: the last frame
  double b = 0;                   // m, the thumb's lever arm; 0 when the hand does not hold the tool
  double cmd = 0, omega_cmd = 0;  // rad, rad/s: the hand's target and its rate
  double max_force = 0;           // N
  bool actee = false;             // the actee is between the jaws, unbroken
  double a = 0, theta_c = 0, thickness = 0;  // m, rad, m
  double g_cos = 0, g_sin = 0;    // N*m, gravity's coefficients for this frame
  double dt = m.timestep;         // s
  double forced = -1;             // N: >= 0, the hand pushes with this force whatever the angle

  double omega(double theta) const { return (theta - theta0) / dt; }

  // The hand impedance's push at the emphasis, N, and its slope, N/rad.
  double hand(double theta, double* slope) const {
    *slope = 0;
    if (b == 0) return 0;
    if (forced >= 0) return forced;
    const double f = m.force_gain * b * (theta - cmd) + m.hand_damping * b * (omega(theta) - omega_cmd);
    if (f <= 0) return 0;  // the thumb has left the arm: it pushes, never pulls
    if (f >= max_force) return max_force;
    *slope = m.force_gain * b + m.hand_damping * b / dt;
    return f;
  }

  // The actee's force, N, and its slope with theta, N/rad.
  double actee_force(double theta, double* slope) const {
    *slope = 0;
    if (!actee || theta >= theta_c) return 0;
    double law_slope = 0;
    const double f = actee_force_law(m, a * (theta_c - theta), thickness, &law_slope);
    *slope = -law_slope * a;
    return f;
  }

  double value(double theta, double* slope) const {
    double hand_slope = 0, actee_slope = 0;
    const double hand_torque = hand(theta, &hand_slope) * b;
    const SpringTorques spring = spring_torques(m, theta);
    double opening = spring.linear + spring.preload + spring.progressive + actee_force(theta, &actee_slope) * a;
    double opening_slope = spring.slope + actee_slope * a;
    if (m.gravity) {
      const double c = std::cos(theta), sn = std::sin(theta);
      opening += g_cos * c + g_sin * sn;
      opening_slope += -g_cos * sn + g_sin * c;
    }
    const double w = omega(theta);
    const double alpha = (w - omega0) / dt;
    *slope = hand_slope * b - opening_slope + m.damping / dt + m.arm_inertia / (dt * dt);
    return hand_torque - opening + m.damping * w + m.arm_inertia * alpha;
  }

  // The theta in [lo, hi] where value() = target; lo or hi if it is
  // outside. `from` is lo or hi, f_from = value(from) - target (its sign
  // says the root lies towards the other end) and slope_from its slope.
  // Newton's steps from there, kept inside the bracket by bisection; the
  // other end is evaluated only when a step would pass it.
  double solve(double lo, double hi, double target, double from, double f_from, double slope_from) const {
    const bool from_hi = from == hi;
    double x = from, f = f_from, slope = slope_from;
    bool far_checked = false;
    for (int i = 0; i < 100; ++i) {
      double next = slope > 0 ? x - f / slope : (from_hi ? lo : hi);
      if (std::abs(next - x) <= 1e-13) return std::clamp(next, lo, hi);  // converged, rad
      if (!(next > lo && next < hi)) {
        if (!far_checked) {  // a step past the far end: is the root beyond it?
          far_checked = true;
          const double far = from_hi ? lo : hi;
          double far_slope = 0;
          const double f_far = value(far, &far_slope) - target;
          if (from_hi ? f_far >= 0 : f_far <= 0) return far;
        }
        next = 0.5 * (lo + hi);  // bisect
      }
      if (hi - lo <= 1e-15) return next;  // rad
      x = next;
      f = value(x, &slope) - target;
      if (f == 0) return x;
      (f < 0 ? lo : hi) = x;
    }
    return x;
  }
};

// Follows the thumb: eq. (1) projects its motion on the rotation direction
// L_d of the emphasis point, eq. (2) gives its speed. The target angle is
// where the tracked thumb would put the arm.
void follow_thumb(const Model& m, State& s) {
  const Eigen::Vector3d thumb = s.object_pose.inverse() * s.fingertip[0];
  const Eigen::Vector3d motion = thumb - s.thumb_in_object;
  s.thumb_in_object = thumb;
  const double c = std::cos(s.theta), sn = std::sin(s.theta);
  // The tracked thumb's distance along the arm turns its advance into an
  // angle; the lever arm D_ag is where it meets the arm: the tracked thumb
  // turned back by how far it was ahead (the proxy below), since it may
  // have gone on into the arm.
  const double tracked = c * thumb.x() + sn * thumb.y();
  const Eigen::Vector3d on_arm = moving_arm_pose(std::max(0.0, s.theta - s.theta_command)) * thumb;
  s.effort_distance = c * on_arm.x() + sn * on_arm.y();
  const double side = s.effort_distance >= 0 ? 1.0 : -1.0;
  s.closing_direction = Eigen::Vector3d(side * sn, -side * c, 0.0);  // L_d, unit
  const double advance = motion.dot(s.closing_direction);            // eq. 1
  s.thumb_speed = advance / m.timestep;                               // eq. 2
  const double turn = advance / std::max(std::abs(tracked), kMinLeverArm);
  s.theta_command -= turn;
  s.omega_command = -turn / m.timestep;
}

// The angle at the end of the step: implicit balance with Coulomb friction
// (stick where the net torque at rest is within the friction torque, else
// move with friction against the motion), between the limits. Fills the
// lower end of the range (an actee cannot be squeezed through: the range
// ends short of where it would be flat) and the friction torque.
double settle(const Balance& eq, double* lo_out, double* friction) {
  const Model& m = eq.m;
  double lo = m.theta_min;
  if (eq.actee && eq.a > 0 && eq.thickness > 0) {
    lo = std::max(lo, eq.theta_c - eq.thickness * (1 - 1e-9) / eq.a);
  }
  const double hi = m.theta_max;
  const double start = std::clamp(eq.theta0, lo, hi);
  *lo_out = lo;
  double slope = 0;
  const double at_rest = eq.value(start, &slope);
  const double tf = m.friction_torque;
  double theta = start;
  if (std::abs(at_rest) <= tf && start == eq.theta0) {
    *friction = at_rest;  // stiction holds the arm
  } else if (at_rest > tf) {
    *friction = tf;  // closing: friction opens
    theta = start == lo ? lo : eq.solve(lo, start, tf, start, at_rest - tf, slope);
  } else {
    *friction = -tf;
    theta = start == hi ? hi : eq.solve(start, hi, -tf, start, at_rest + tf, slope);
  }
  // On a stop at rest the stop's reaction takes it all.
  if ((theta == lo || theta == hi) && theta == start) *friction = 0;
  return theta;
}

// sensor_latency: the effort a sensor reports `delay` after it acted,
// interpolated between the two frames around it.
void sense_effort(const Model& m, State& s) {
  if (s.effort_history.empty()) {
    s.effort_sensed = s.effort_force;
    return;
  }
  const auto n = static_cast<std::int64_t>(s.effort_history.size());
  s.effort_history[static_cast<size_t>(s.history_head % n)] = s.effort_force;
  const double frames_back = m.sensor_latency / m.timestep;
  const auto whole = static_cast<std::int64_t>(frames_back);
  const double part = frames_back - static_cast<double>(whole);
  auto at = [&](std::int64_t back) {  // before the first frame the effort was 0
    const std::int64_t k = s.history_head - back;
    return k < 0 ? 0.0 : s.effort_history[static_cast<size_t>(k % n)];
  };
  s.effort_sensed = (1 - part) * at(whole) + part * at(whole + 1);
  ++s.history_head;
}

}  // namespace

ForcedStep step_forced_lever(const Model& m, const ForcedLever& lever, double theta0, double omega0,
                             double effort_n, double dt) {
  Balance eq{m};
  eq.theta0 = theta0;
  eq.omega0 = omega0;
  eq.b = lever.effort_distance;
  eq.forced = std::max(0.0, effort_n);
  eq.actee = lever.actee;
  eq.a = lever.load_distance;
  eq.theta_c = lever.contact_angle;
  eq.thickness = lever.thickness;
  eq.dt = dt;
  gravity_coefficients(m, lever.object_rotation, &eq.g_cos, &eq.g_sin, lever.turn);
  double lo = 0, friction = 0;
  ForcedStep out;
  out.theta = settle(eq, &lo, &friction);
  out.omega = eq.omega(out.theta);
  double slope = 0;
  out.actee_force = eq.actee_force(out.theta, &slope);
  return out;
}

void solve_lever(const Model& m, State& s) {
  Balance eq{m};
  eq.theta0 = s.theta;
  eq.omega0 = s.omega;
  eq.max_force = s.max_force;
  eq.actee = s.between_jaws && s.condition != ActeeCondition::broken;
  eq.a = std::abs(s.load_distance);
  eq.theta_c = s.contact_angle;
  eq.thickness = s.actee_thickness;
  gravity_coefficients(m, s.object_pose.linear(), &eq.g_cos, &eq.g_sin);
  s.thumb_speed = 0;
  if (s.grasped) {
    follow_thumb(m, s);
    eq.b = std::max(std::abs(s.effort_distance), kMinLeverArm);
    eq.cmd = s.theta_command;
    eq.omega_cmd = s.omega_command;
  } else {
    // Untouched, the hand's target is wherever the arm is.
    s.effort_distance = 0;
    s.theta_command = s.theta;
    s.omega_command = 0;
  }

  double lo = 0, friction = 0;
  const double theta = settle(eq, &lo, &friction);
  const double hi = m.theta_max;

  // The terms at the solution, each named; the stop takes what is left when
  // the arm rests on a limit (or on an actee squeezed to its last solid).
  const bool resting = theta == lo || theta == hi;
  double hand_slope = 0, actee_slope = 0;
  const SpringTorques spring = spring_torques(m, theta);
  const double omega = eq.omega(theta);
  const double alpha = (omega - eq.omega0) / m.timestep;
  s.theta = theta;
  s.omega = omega;
  s.alpha = alpha;
  s.effort_force = eq.hand(theta, &hand_slope);
  s.effort_excess = s.grasped ? std::max(0.0, eq.b * (theta - eq.cmd)) : 0.0;
  s.actee_force = eq.actee_force(theta, &actee_slope);
  s.compression = spring_compression(m, theta);
  s.torque[kSpring] = spring.linear;
  s.torque[kSpringPreload] = spring.preload;
  s.torque[kProgressiveSpring] = spring.progressive;
  s.torque[kActee] = s.actee_force * eq.a;
  s.torque[kPivotFriction] = friction;
  s.torque[kViscousDamping] = -m.damping * omega;
  s.torque[kArmInertia] = -m.arm_inertia * alpha;
  s.torque[kGravity] = m.gravity ? eq.g_cos * std::cos(theta) + eq.g_sin * std::sin(theta) : 0.0;
  double sum = 0;
  for (int t = 0; t < kTermCount; ++t) sum += t == kStop ? 0.0 : s.torque[static_cast<size_t>(t)];
  s.torque[kStop] = resting ? s.effort_force * eq.b - sum : 0.0;

  if (s.grasped) {
    // The thumb as contacts see it: held on the arm's surface, however far
    // the tracked thumb went past it (a haptic proxy, the "god object"). The
    // tracked thumb turned back about the pivot by how far it is ahead.
    const Eigen::Isometry3d back = moving_arm_pose(std::max(0.0, s.theta - s.theta_command));
    s.thumb_proxy = s.object_pose * (back * s.thumb_in_object);
  }
  s.blocked = s.actee_force > 0;
  s.actee_compression = s.blocked ? eq.a * (s.contact_angle - s.theta) : 0.0;
  s.at_limit = s.theta <= m.theta_min || s.theta >= m.theta_max;
  s.pattern = (s.grasped && eq.a > 0 && s.effort_distance != 0) ? pattern_at(s.effort_distance, s.load_distance)
                                                                 : m.pattern;
  sense_effort(m, s);
}

}  // namespace afford
