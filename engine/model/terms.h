// The torque terms about the fulcrum as functions of the lever's angle: the
// physics the solver balances, `describe` and the guides derive from, and
// the tests check against numbers worked out by hand. Torques are N*m,
// opening positive (resisting the agent's squeeze), as in State::torque.
#pragma once

#include <Eigen/Core>

#include "model.h"

namespace afford {

inline constexpr double kStandardGravity = 9.80665;  // m/s^2, along the world's -z

// How much more weight (N) the jaws' friction could carry than the actee's
// own (mass_kg), gripped with actee_force_n: (mu_fixed + mu_moving) * F_acr
// - m * g, 2 * mu * F_acr - m * g when both jaws have the same coefficient.
// Two jaws press on it with F_acr each, and each contact can take up to
// mu * F_acr along its face before it slips (Coulomb); the weight is taken
// whole along the faces, as with the jaws across gravity (the shipped
// functional poses). A jaw beneath the actee would bear part of it, so a
// tilted tool errs on the side of not holding.
double grip_margin(double mu_fixed, double mu_moving, double mass_kg, double actee_force_n);

// Spring compression d (m) of eq. 4 at opening angle theta, along the arc
// the spring's end travels: |S_p| * (rest - theta), plus the preload's
// compression (preload / S_k) when spring_preload is on.
double spring_compression(const Model& m, double theta_rad);

// The spring's force (N) at theta: linear, preload and progressive parts.
double spring_force(const Model& m, double theta_rad);

// The spring's three torque terms at theta and the slope of their sum.
struct SpringTorques {
  double linear = 0;       // S_k * |S_p| * (rest - theta) * |S_p|
  double preload = 0;      // spring_preload: its force * |S_p|, constant
  double progressive = 0;  // progressive_spring: cubic * d^3 * |S_p| (d > 0)
  double slope = 0;        // d(sum)/d theta, N*m/rad
};
SpringTorques spring_torques(const Model& m, double theta_rad);

// The actee's force (N) at a deflection (m) between the jaws, for an actee
// `thickness` m across them, and its slope dF/d deflection (N/m). Linear
// (actee_stiffness), or a power law with actee_compliance; either way
// multiplied by thickness / (thickness - deflection): the solid left when
// an actee is squeezed flat cannot be squeezed, so no force takes it to
// zero thickness (foam densification, Gibson & Ashby, Cellular Solids,
// ch. 5, in its simplest form). The factor changes the law by the fraction
// deflection/thickness (0.6 % for an egg at its limit).
double actee_force_law(const Model& m, double deflection_m, double thickness_m, double* slope);

// The same law for given parameters: stiffness (N/m), exponent (1: linear)
// and reference deflection (m, unused when linear).
double actee_law(double stiffness, double exponent, double reference, double deflection_m, double thickness_m,
                 double* slope);

// Gravity's torque on the moving arm is c * cos(theta) + s * sin(theta)
// for an object turned by `object_rotation` in the world (z up); fills c and
// s (N*m), gravity's extra amplitude included. Zero when gravity is off.
// `turn` (rad) turns the tool further about its hinge (a measurement made
// with the tool upside down, or on its side): the computed weight and the
// extra amplitude turn with it.
void gravity_coefficients(const Model& m, const Eigen::Matrix3d& object_rotation, double* c, double* s,
                          double turn = 0);

}  // namespace afford
