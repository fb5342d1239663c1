// The Open Dynamics Engine's scenes for the ODE reality (ode_reality.cpp):
// the tool with a hand pushing through a force sensor, and the plates rig
// an experimenter squeezes an actee in. Every force a body feels is ODE's
// own (joints, motors, stops, contacts) or a torque the harness applies
// for the spring, the weight's turning and the effects outside afford's
// library; nothing here calls afford.
#pragma once

#include <ode/ode.h>

#include "design.h"

namespace gapcheck::ode {

// The actee's contact as ODE's penalty spring-damper (N/m, N*s/m): the
// contact joint's ERP and CFM at a step h are kp h / (kp h + kd) and
// 1 / (kp h + kd), ODE's implicit spring and damper.
struct ContactLaw {
  double kp = 0, kd = 0;
};
// The engine's own contact for a case's actee: a penalty spring of the
// specimen's stiffness (the file's times c.actee_specimen; the ODE reality
// makes it the real actee's law of truth.h, power and h / (h - d), by its
// secant at the depth), no damping
// (the implicit step damps it enough), frictionless (the jaws slide on
// the actee freely).
ContactLaw contact_law(const Case& c);
// ODE's soft contact for kp, kd at step h, frictionless.
dSurfaceParameters surface(double kp, double kd, double h);

// kg*m^2: the hand's inertia about the hinge.
double hand_inertia(const Case& c);

// ODE's global state: initialised once, and per thread.
void init_thread();

// The real tool for one drive. The moving arm is a body on a hinge (axis z)
// to the world at the fulcrum, its weight a mass at kWeightRadius under
// ODE's gravity in the plane of motion (turned with the tool); its pivot
// friction the hinge's motor held at zero speed with the friction as its
// most torque (ODE's Coulomb friction: it sticks and slips); its damping
// a motor (ODE's angular motor) with the damping's inverse as its CFM, an
// implicit viscous torque. The hand is a body of c.hand.mass at the
// emphasis on a hinge to the arm about the same axis, held at zero
// relative angle by a stop (lo = hi) whose ERP and CFM make it a stiff
// torsional spring-damper: the force sensor, read from its deflection.
// An actee in the jaws is a small sphere (a point contact, so that the
// moving jaw's push keeps its lever arm as the jaw turns into it), fixed to
// the world where the moving jaw's face (a box on the arm, its face a line
// through the hinge) first touches it at tool.actee's contact angle and
// lever arm, as jaw_contact found them (ODE has no ellipsoid, so the
// exported jaw scene, c.jaws, is not rebuilt geom by geom).
class ToolScene {
 public:
  ToolScene(const Case& c, const Drive& drive, double step);
  ~ToolScene();
  ToolScene(const ToolScene&) = delete;
  ToolScene& operator=(const ToolScene&) = delete;

  // Sets the arm and the hand at `angle` (rad), at rest, the sensor slack.
  void place(double angle);
  double angle() const;          // rad, the arm's hinge
  double rate() const;           // rad/s
  double hand_angle() const;     // rad
  double hand_rate() const;      // rad/s
  double sensor_torque() const;  // N*m, the sensor's spring and damper on the arm, opening positive

  dWorldID world = nullptr;
  dBodyID arm = nullptr, hand = nullptr;
  dJointID hinge = nullptr, sensor = nullptr, damper = nullptr;
  dGeomID actee = nullptr, jaw = nullptr;  // only with an actee
  dJointGroupID contacts = nullptr;
  double sensor_stiffness = 0;  // N*m/rad
  double sensor_damping = 0;    // N*m*s/rad
  double arm_inertia = 0;       // kg*m^2, about the hinge

 private:
  double arm_mass_radius_ = 0;  // m, where the arm's mass sits along it
  double hand_radius_ = 0;      // m, the hand along the arm (negative: behind the fulcrum)
};

// The plates rig: the actee's sphere resting on a fixed plate, glued to
// it, and a plate above on a slider (axis y) driven down at a constant
// speed by the slider's motor; the contact is the same law as the tool's.
class PlatesScene {
 public:
  PlatesScene(double radius, double gap);
  ~PlatesScene();
  PlatesScene(const PlatesScene&) = delete;
  PlatesScene& operator=(const PlatesScene&) = delete;

  double plate_face() const;  // m, the moving plate's face (its lower side), y

  dWorldID world = nullptr;
  dBodyID plate = nullptr;
  dJointID slider = nullptr;
  dGeomID actee = nullptr, plate_geom = nullptr, base = nullptr;
  dJointGroupID contacts = nullptr;
  double plate_half = 0;  // m, the moving plate's half thickness
};

}  // namespace gapcheck::ode
