#include "terms.h"

#include <cmath>
#include <limits>

namespace afford {

double grip_margin(double mu_fixed, double mu_moving, double mass_kg, double actee_force_n) {
  return (mu_fixed + mu_moving) * actee_force_n - mass_kg * kStandardGravity;
}

double spring_compression(const Model& m, double theta_rad) {
  return std::abs(m.spring_position) * (m.theta_rest - theta_rad) + m.spring_preload / m.spring_constant;
}

double spring_force(const Model& m, double theta_rad) {
  const double d = spring_compression(m, theta_rad);
  return m.spring_constant * d + (d > 0 ? m.spring_cubic * d * d * d : 0.0);
}

SpringTorques spring_torques(const Model& m, double theta_rad) {
  const double ds = std::abs(m.spring_position);
  SpringTorques t;
  t.linear = m.spring_constant * ds * (m.theta_rest - theta_rad) * ds;
  t.preload = m.spring_preload * ds;
  t.slope = -m.spring_constant * ds * ds;
  if (m.spring_cubic > 0) {
    const double d = spring_compression(m, theta_rad);
    if (d > 0) {
      t.progressive = m.spring_cubic * d * d * d * ds;
      t.slope -= 3 * m.spring_cubic * d * d * ds * ds;
    }
  }
  return t;
}

double actee_force_law(const Model& m, double deflection_m, double thickness_m, double* slope) {
  return actee_law(m.actee_stiffness, m.actee_exponent, m.actee_reference, deflection_m, thickness_m, slope);
}

double actee_law(double stiffness, double exponent, double reference, double deflection_m, double thickness_m,
                 double* slope) {
  if (deflection_m <= 0) {
    *slope = 0;
    return 0;
  }
  if (deflection_m >= thickness_m) {  // never reached by the solver: it brackets below
    *slope = std::numeric_limits<double>::max();
    return std::numeric_limits<double>::max();
  }
  double base = 0, base_slope = 0;
  if (exponent == 1) {
    base = stiffness * deflection_m;
    base_slope = stiffness;
  } else {
    const double ratio = std::pow(deflection_m / reference, exponent);
    base = stiffness * reference * ratio;
    base_slope = stiffness * exponent * ratio * reference / deflection_m;
  }
  const double room = 1.0 / (thickness_m - deflection_m);  // 1/m
  const double factor = thickness_m * room;
  *slope = base_slope * factor + base * factor * room;
  return base * factor;
}

void gravity_coefficients(const Model& m, const Eigen::Matrix3d& object_rotation, double* c, double* s, double turn) {
  *c = *s = 0;
  if (!m.gravity) return;
  // Weight in the object frame; the arm's centre turned by theta about z:
  // torque_z = (R(theta) x) x w, which is linear in cos and sin.
  const Eigen::Matrix3d turned = object_rotation * Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d w = turned.transpose() * Eigen::Vector3d(0, 0, -kStandardGravity * m.arm_mass);
  const double x = m.arm_centre.x(), y = m.arm_centre.y();
  *c = x * w.y() - y * w.x();
  *s = -(x * w.x() + y * w.y());
  // The extra amplitude closes the arm as extra weight would on a tool
  // whose fixed arm lies level with the moving arm above it.
  // Turned by `turn`, it follows -cos(theta + turn).
  *c -= m.gravity_extra * std::cos(turn);
  *s += m.gravity_extra * std::sin(turn);
}

}  // namespace afford
