// Stage 3: the lever-spring solver (paper Sec. 4.3.1-4.3.2, DESIGN.md).
//
// Quasi-static moment balance about the fulcrum. Forces act along each
// point's direction of rotation and displacements are measured along the
// arc, so virtual work and moment balance agree:
//
//     F_ag * D_ag = S_k * d * D_s + F_acr * D_ac + (optional terms)
//
// The paper's eq. (5) writes F_agr = F_agr' * D_ag/D_s + F_acr * D_ag/D_ac,
// which inverts both distance ratios: a nutcracker would then weaken the
// hand. We follow the physics (as eqs. 6-8 do):
//
//     F_agr = (S_k * d * D_s + F_acr * D_ac) / D_ag.
#include <algorithm>
#include <cmath>

#include "lever.h"
#include "stages.h"

namespace afford {
namespace {

// A thumb closer to the fulcrum than this cannot turn the lever (and would
// divide by nearly zero).
constexpr double kMinLeverArm = 1e-3;  // m

// Fills the torques that depend only on the lever's motion (spring and the
// optional effects), N*m, opening positive; returns their sum.
double motion_torques(const Model& m, State& s) {
  const double d = spring_compression(m, s.theta);
  const double ds = std::abs(m.spring_position);
  s.compression = d;
  s.torque[kSpring] = m.spring_constant * d * ds;  // eq. 4 times the spring's lever arm
  s.torque[kPivotFriction] = s.torque[kViscousDamping] = 0;
  s.torque[kProgressiveSpring] = s.torque[kArmInertia] = 0;
  for (const ModelEffect& e : m.effects) {
    if (!e.enabled) continue;
    switch (e.kind) {
      case EffectKind::pivot_friction:
        // Coulomb: against the motion; undetermined (taken as 0) at rest.
        s.torque[kPivotFriction] = s.omega > 0 ? -e.param : (s.omega < 0 ? e.param : 0.0);
        break;
      case EffectKind::viscous_damping:
        s.torque[kViscousDamping] = -e.param * s.omega;
        break;
      case EffectKind::progressive_spring:
        s.torque[kProgressiveSpring] = d > 0 ? e.param * d * d * d * ds : 0.0;
        break;
      case EffectKind::arm_inertia:
        s.torque[kArmInertia] = -e.param * s.alpha;
        break;
    }
  }
  return s.torque[kSpring] + s.torque[kPivotFriction] + s.torque[kViscousDamping] +
         s.torque[kProgressiveSpring] + s.torque[kArmInertia];
}

// Follows the thumb: eq. (1) projects its motion on the rotation direction
// L_d of the emphasis point, eq. (2) gives its speed.
void follow_thumb(const Model& m, State& s) {
  const Eigen::Vector3d thumb = s.object_pose.inverse() * s.fingertip[0];
  const Eigen::Vector3d motion = thumb - s.thumb_in_object;
  s.thumb_in_object = thumb;
  const double c = std::cos(s.theta), sn = std::sin(s.theta);
  s.effort_distance = c * thumb.x() + sn * thumb.y();  // along the moving arm
  const double side = s.effort_distance >= 0 ? 1.0 : -1.0;
  s.closing_direction = Eigen::Vector3d(side * sn, -side * c, 0.0);  // L_d, unit
  const double advance = motion.dot(s.closing_direction);            // eq. 1
  s.thumb_speed = advance / m.timestep;                      // eq. 2
  s.theta_command -= advance / std::max(std::abs(s.effort_distance), kMinLeverArm);
}

}  // namespace

void solve_lever(const Model& m, State& s) {
  const double theta_before = s.theta;
  const double omega_before = s.omega;
  double theta = m.theta_rest;
  double excess = 0;       // m, thumb travel past the arm, along L_d
  double actee_force = 0;  // N, F_acr
  const double a = std::abs(s.load_distance);
  const bool actee_blocks = s.between_jaws && s.condition != ActeeCondition::broken;
  s.thumb_speed = 0;
  s.blocked = false;

  if (s.grasped) {
    follow_thumb(m, s);
    const double b = std::max(std::abs(s.effort_distance), kMinLeverArm);
    const double cmd = s.theta_command;
    const double stop = actee_blocks ? std::max(s.contact_angle, m.theta_min) : m.theta_min;
    if (cmd >= stop) {
      theta = std::min(cmd, m.theta_max);  // free: the arm follows the thumb
    } else if (actee_blocks && s.contact_angle > m.theta_min) {
      // The thumb pushes on past the actee. Eq. (3), F_ag = F_agr + f_a*v,
      // read with f_a in N/m: the hand's force grows by f_a for every metre
      // the thumb advances past where the arm can follow. In series with the
      // actee's stiffness k this settles where f_a*e*D_ag = k*x*D_ac.
      s.blocked = true;
      const double ka2 = m.actee_stiffness * a * a;
      const double fb2 = m.force_gain * b * b;
      theta = std::max((ka2 * s.contact_angle + fb2 * cmd) / (ka2 + fb2), m.theta_min);
      actee_force = m.actee_stiffness * a * (s.contact_angle - theta);
      excess = b * (theta - cmd);
    } else {
      theta = m.theta_min;  // pressed against the closed stop
      excess = b * (theta - cmd);
    }
    s.theta = theta;
    s.omega = (theta - theta_before) / m.timestep;
    s.alpha = (s.omega - omega_before) / m.timestep;
    const double motion = motion_torques(m, s);
    double effort = motion / b + m.force_gain * excess;
    // The hand cannot push harder than s.max_force (the agent's, capped by
    // the grasp type's; stage 2): past that point more
    // travel of the tracked thumb adds no force, and the squeeze it would
    // have made is dropped. The command stays where the thumb is, so the
    // thumb has to come back that far before the force falls.
    if (excess > 0 && effort > s.max_force) {
      excess = std::max(0.0, (s.max_force - motion / b) / m.force_gain);
      if (s.blocked) {
        actee_force = std::min(actee_force, m.force_gain * excess * b / a);
        theta = s.contact_angle - actee_force / (m.actee_stiffness * a);
        s.theta = theta;
      }
      effort = motion / b + m.force_gain * excess;
    }
    s.torque[kActee] = actee_force * a;
    // Whatever of the agent's torque neither the terms nor the actee take
    // goes into the angle limit.
    s.torque[kStop] = effort * b - motion - s.torque[kActee];
    s.effort_force = effort;
    // The thumb as contacts see it: held on the arm's surface, however far
    // the tracked thumb went past it (a haptic proxy, the "god object").
    // The tracked thumb turned back about the pivot by how far it is ahead
    // of the arm.
    const Eigen::Isometry3d back = moving_arm_pose(std::max(0.0, s.theta - cmd));
    s.thumb_proxy = s.object_pose * (back * s.thumb_in_object);
  } else {
    // Untouched, the spring returns the tool to its rest angle.
    s.theta = theta;
    s.theta_command = theta;
    s.omega = (theta - theta_before) / m.timestep;
    s.alpha = (s.omega - omega_before) / m.timestep;
    // The limit holds whatever the spring pushes with at rest.
    s.torque[kActee] = 0;
    s.torque[kStop] = -motion_torques(m, s);
    s.effort_force = 0;
    s.effort_distance = 0;
  }
  s.effort_excess = excess;
  s.actee_force = actee_force;
  s.actee_compression = s.blocked ? a * (s.contact_angle - s.theta) : 0.0;
  s.at_limit = s.theta <= m.theta_min || s.theta >= m.theta_max;
  s.pattern = (s.grasped && a > 0 && s.effort_distance != 0) ? pattern_at(s.effort_distance, s.load_distance)
                                                             : m.pattern;
}

}  // namespace afford
