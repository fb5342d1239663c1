#include "ode_scene.h"

#include <algorithm>
#include <cmath>
#include <mutex>

namespace gapcheck::ode {
namespace {

constexpr double kG = 9.81;  // m/s^2
// m, where the arm's weight sits: close to the pivot, so that its own
// inertia (weight * r / g) stays below the noise (as in the MuJoCo reality).
constexpr double kWeightRadius = 1e-3;
// kg*m^2: the arm's inertia about its mass centre when none is hidden.
constexpr double kMinInertia = 1e-6;
// kg: the arm's mass when it has no weight (gravity then leaves it alone).
constexpr double kMasslessArm = 1e-5;
// m: the hand's own size (a sphere's radius), for its inertia about itself.
constexpr double kHandRadius = 0.01;
// m: the radius of the actee's sphere in the jaws (ToolScene): a point
// contact against the jaw's face.
constexpr double kContactRadius = 2e-4;
// rad: the hinge's stops, outside the tool's range (the drives stay inside).
constexpr double kStopMargin = 0.2;

// Turns a body about z through the fulcrum (the world's origin) to
// `angle`, from its place at angle 0, and stops it.
void turn(dBodyID body, double x0, double y0, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  dBodySetPosition(body, c * x0 - s * y0, s * x0 + c * y0, 0);
  dMatrix3 r;
  dRFromAxisAndAngle(r, 0, 0, 1, angle);
  dBodySetRotation(body, r);
  dBodySetLinearVel(body, 0, 0, 0);
  dBodySetAngularVel(body, 0, 0, 0);
}

}  // namespace

ContactLaw contact_law(const Case& c) {
  return {c.tool.actee ? c.actee_specimen * c.tool.actee->stiffness : 0.0, 0.0};
}

dSurfaceParameters surface(double kp, double kd, double h) {
  dSurfaceParameters s{};
  s.mode = dContactSoftERP | dContactSoftCFM;
  s.mu = 0;  // frictionless: one row, along the normal
  s.soft_erp = kp * h / (kp * h + kd);
  s.soft_cfm = 1 / (kp * h + kd);
  return s;
}

double hand_inertia(const Case& c) {
  return c.hand.mass * (c.tool.effort_at * c.tool.effort_at + 0.4 * kHandRadius * kHandRadius);
}

void init_thread() {
  static std::once_flag once;
  std::call_once(once, [] { dInitODE2(0); });
  dAllocateODEDataForThread(dAllocateMaskAll);
}

ToolScene::ToolScene(const Case& c, const Drive& drive, double step) {
  init_thread();
  const Tool& tool = c.tool;
  const Truth& truth = c.truth;
  world = dWorldCreate();
  // Gravity in the plane of motion, turned with the tool: the weight's
  // torque is -weight * cos(angle + turned).
  dWorldSetGravity(world, -kG * std::sin(drive.turned), -kG * std::cos(drive.turned), 0);
  dWorldSetERP(world, 0.2);
  dWorldSetCFM(world, 1e-10);
  dWorldSetContactSurfaceLayer(world, 0);
  dWorldSetContactMaxCorrectingVel(world, dInfinity);

  // The moving arm, at angle 0 along x.
  arm = dBodyCreate(world);
  const bool weighs = truth.weight > 0;
  const double arm_mass = weighs ? truth.weight / (kG * kWeightRadius) : kMasslessArm;
  const double inertia = kMinInertia + truth.inertia;
  dMass m;
  dMassSetParameters(&m, arm_mass, 0, 0, 0, inertia, inertia, inertia, 0, 0, 0);
  dBodySetMass(arm, &m);
  dBodySetPosition(arm, kWeightRadius, 0, 0);
  dBodySetGravityMode(arm, weighs ? 1 : 0);
  arm_mass_radius_ = kWeightRadius;
  arm_inertia = inertia + arm_mass * kWeightRadius * kWeightRadius;

  hinge = dJointCreateHinge(world, nullptr);
  dJointAttach(hinge, arm, nullptr);
  dJointSetHingeAnchor(hinge, 0, 0, 0);
  dJointSetHingeAxis(hinge, 0, 0, 1);
  dJointSetHingeParam(hinge, dParamLoStop, tool.theta_min - kStopMargin);
  dJointSetHingeParam(hinge, dParamHiStop, tool.theta_max + kStopMargin);
  // Pivot friction: the motor held at zero speed, at most the friction.
  const double friction = tool.friction + truth.friction;
  dJointSetHingeParam(hinge, dParamVel, 0);
  dJointSetHingeParam(hinge, dParamFMax, std::max(0.0, friction));

  // Damping: an angular motor at zero speed with unbounded torque whose
  // CFM (rad/s per N*m) is the damping's inverse: ODE solves it with the
  // step, an implicit viscous torque.
  if (truth.damping > 0) {
    damper = dJointCreateAMotor(world, nullptr);
    dJointAttach(damper, arm, nullptr);
    dJointSetAMotorMode(damper, dAMotorUser);
    dJointSetAMotorNumAxes(damper, 1);
    dJointSetAMotorAxis(damper, 0, 1, 0, 0, 1);
    dJointSetAMotorParam(damper, dParamVel, 0);
    dJointSetAMotorParam(damper, dParamFMax, 1e9);
    dJointSetAMotorParam(damper, dParamCFM, 1 / truth.damping);
  }

  // The hand, at the emphasis, hinged to the arm about the same axis; the
  // sensor a stop at zero relative angle (lo = hi: both ways), ERP k h /
  // (k h + c) and CFM 1 / (k h + c): ODE's implicit spring of stiffness k
  // and damper c.
  const double b = tool.effort_at;
  hand = dBodyCreate(world);
  dMass mh;
  dMassSetSphereTotal(&mh, c.hand.mass, kHandRadius);
  dBodySetMass(hand, &mh);
  hand_radius_ = tool.effort_sign * b;
  dBodySetPosition(hand, hand_radius_, 0, 0);
  dBodySetGravityMode(hand, 0);  // its weight is the experimenter's concern
  sensor_stiffness = c.hand.sensor_stiffness;
  sensor_damping = c.hand.sensor_damping;
  const double k = sensor_stiffness, kd = sensor_damping;
  sensor = dJointCreateHinge(world, nullptr);
  dJointAttach(sensor, hand, arm);
  dJointSetHingeAnchor(sensor, 0, 0, 0);
  dJointSetHingeAxis(sensor, 0, 0, 1);
  dJointSetHingeParam(sensor, dParamLoStop, 0);
  dJointSetHingeParam(sensor, dParamHiStop, 0);
  dJointSetHingeParam(sensor, dParamStopERP, k * step / (k * step + kd));
  dJointSetHingeParam(sensor, dParamStopCFM, 1 / (k * step + kd));
  dJointSetHingeParam(sensor, dParamBounce, 0);

  // The actee: a sphere fixed where the moving jaw's face (a line through
  // the hinge) first touches it at the contact angle, at the lever arm
  // from the hinge; the jaw a box on the arm whose lower face is that
  // line. The sphere is small (kContactRadius), not the actee's size: a
  // flat face turning about the hinge onto a sphere of radius r rolls its
  // contact point out along the face by r sin(delta) and deepens it by
  // r (1 - cos(delta)) at a squeeze of delta rad, a moment arm growing
  // with the squeeze (0.2 to 0.3 % of the actee's torque at a hazelnut's
  // limit, up to 0.6 N at the effort) that afford's law and the labels do
  // not have: with a point-like contact the moment arm stays the lever
  // jaw_contact found and the depth is lever sin(delta) (within 1e-4 of
  // both at a crack). ODE's sphere-box contact stays the face's normal
  // when the sphere's centre is inside the box, so the box is deep
  // enough for any squeeze (ten times the linear law's deflection at the
  // limit), and as long and wide as the actee.
  if (tool.actee) {
    const ToolActee& a = *tool.actee;
    const double r = kContactRadius, size = 0.5 * a.thickness, lever = a.lever, tc = a.contact_angle;
    actee = dCreateSphere(nullptr, r);
    dGeomSetPosition(actee, lever * std::cos(tc) + r * std::sin(tc), lever * std::sin(tc) - r * std::cos(tc), 0);
    const double squeeze = 10 * a.limit / (c.actee_specimen * a.stiffness);  // m
    const double length = 4 * size, depth = std::max({size, 0.005, 2 * squeeze}), width = 4 * size;
    jaw = dCreateBox(nullptr, length, depth, width);
    dGeomSetBody(jaw, arm);
    dGeomSetOffsetPosition(jaw, lever - kWeightRadius, 0.5 * depth, 0);
  }
  contacts = dJointGroupCreate(0);
}

ToolScene::~ToolScene() {
  if (jaw) dGeomDestroy(jaw);
  if (actee) dGeomDestroy(actee);
  dJointGroupDestroy(contacts);
  dWorldDestroy(world);  // its bodies and joints with it
}

void ToolScene::place(double angle) {
  turn(arm, arm_mass_radius_, 0, angle);
  turn(hand, hand_radius_, 0, angle);
}

double ToolScene::angle() const { return dJointGetHingeAngle(hinge); }
double ToolScene::rate() const { return dJointGetHingeAngleRate(hinge); }
double ToolScene::hand_angle() const { return angle() + dJointGetHingeAngle(sensor); }
double ToolScene::hand_rate() const { return rate() + dJointGetHingeAngleRate(sensor); }
// The hand ahead of the arm (opening) pulls it open: the stop's spring and
// damper, as ODE's implicit step makes them act (at the step's end).
double ToolScene::sensor_torque() const {
  return sensor_stiffness * dJointGetHingeAngle(sensor) + sensor_damping * dJointGetHingeAngleRate(sensor);
}

PlatesScene::PlatesScene(double radius, double gap) {
  init_thread();
  world = dWorldCreate();
  dWorldSetGravity(world, 0, 0, 0);
  dWorldSetERP(world, 0.2);
  dWorldSetCFM(world, 1e-10);
  dWorldSetContactSurfaceLayer(world, 0);
  dWorldSetContactMaxCorrectingVel(world, dInfinity);
  actee = dCreateSphere(nullptr, radius);
  dGeomSetPosition(actee, 0, 0, 0);
  const double side = 8 * radius;
  plate_half = 0.005;
  base = dCreateBox(nullptr, side, 2 * plate_half, side);  // the fixed plate it rests on
  dGeomSetPosition(base, 0, -radius - plate_half, 0);
  plate = dBodyCreate(world);
  dMass m;
  dMassSetBoxTotal(&m, 1.0, side, 2 * plate_half, side);
  dBodySetMass(plate, &m);
  dBodySetPosition(plate, 0, radius + gap + plate_half, 0);
  plate_geom = dCreateBox(nullptr, side, 2 * plate_half, side);
  dGeomSetBody(plate_geom, plate);
  slider = dJointCreateSlider(world, nullptr);
  dJointAttach(slider, plate, nullptr);
  dJointSetSliderAxis(slider, 0, 1, 0);
  contacts = dJointGroupCreate(0);
}

PlatesScene::~PlatesScene() {
  dGeomDestroy(plate_geom);
  dGeomDestroy(base);
  dGeomDestroy(actee);
  dJointGroupDestroy(contacts);
  dWorldDestroy(world);
}

double PlatesScene::plate_face() const { return dBodyGetPosition(plate)[1] - plate_half; }

}  // namespace gapcheck::ode
