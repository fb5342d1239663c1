// The Open Dynamics Engine plays the real tool (ode_scene.h): ODE's hinge
// with its motor as Coulomb friction that sticks, its angular motor as
// damping, its gravity on the arm's weight, a hand of the case's mass driven by a PD
// servo along the drive and pushing through a stiff stop (the force
// sensor), and the actee as ODE's own penalty contact (dCollide between a
// sphere and the jaw's box, contact joints whose ERP and CFM make a
// spring, ODE's own: linear, or Hunt and Crossley's k d^n for a specimen
// that stiffens; never afford's law, whose h / (h - d) it lacks),
// read by a load cell from the joints' feedback. The harness
// applies the torsion spring (its preload and progressive part), and what
// is outside afford's library: backlash between the arm and the spring, a
// detent, a viscoelastic share of the actee's force; the sensor's gain
// error, offset drift and latency are on its reading. The plates rig
// squeezes the same contact, as an experimenter measures an actee's law.
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "ode_scene.h"
#include "plates_fit.h"
#include "reality.h"
#include "sensor_readout.h"

namespace gapcheck {
namespace {

constexpr double kStep = 1e-4;            // s, the longest step
constexpr double kSettle = 0.3;           // s, held at the drive's start before the trace
constexpr double kPlatesSpeed = 1e-4;     // m/s, the testing machine's crosshead (6 mm/min)
constexpr double kPlatesGap = 2e-5;       // m, the plate's start above the actee
// The plates test a specimen of the kind (truth.h): of the specimen's
// stiffness, but without the stiffening or the relaxation that the one in
// the jaws may have beyond it; true: the one in the jaws itself.
constexpr bool kPlatesTestTheRealSpecimen = false;


// The actee's stiffness about the hinge (N*m/rad) where it is stiffest
// before its limit: the power law's tangent at its reference.
double actee_torsion(const Case& c) {
  if (!c.tool.actee) return 0;
  const ToolActee& a = *c.tool.actee;
  const double n = std::max(1.0, c.truth.actee_exponent);
  return n * ode::contact_law(c).kp * a.lever * a.lever;
}

// s: the step, a whole number of them a millisecond. The hand's servo is
// applied by the harness (explicit): its fastest mode, the hand's inertia
// against the servo and the actee (ODE's stiff stop and contact are
// implicit and need no short step), within omega * step <= 0.3.
double step_for(const Case& c, const Drive& drive) {
  const double inertia = ode::hand_inertia(c);
  const double omega = std::sqrt((drive.servo_stiffness + actee_torsion(c)) / inertia) +
                       drive.servo_damping / inertia;  // rad/s
  return 1e-3 / std::max(1e-3 / kStep, std::ceil(1e-3 * omega / 0.3));
}

// ODE's contact between the actee's sphere and a body's box (the jaw, or
// the testing machine's plate): contact joints whose ERP and CFM make
// the specimen's penalty spring at its depth, and beside it the
// viscoelastic share, a Maxwell element the harness applies along the
// contact's normal. Its force is read from the joints' feedback.
class OdeActeeContact {
 public:
  OdeActeeContact(const Case& c, bool real, double step) : c_(c), real_(real), h_(step), law_(ode::contact_law(c)) {}

  // Before a step: collides the body's box with the actee and adds the
  // contact joints to `group`, and the Maxwell element's force to `body`.
  void add(dWorldID world, dJointGroupID group, dBodyID body, dGeomID box, dGeomID actee) {
    body_ = body;
    n_ = dCollide(box, actee, kMax, geoms_, sizeof(dContactGeom));
    const double share = real_ ? c_.outside.viscoelastic_share : 0.0;
    double depth = 0;
    dVector3 away = {0, 0, 0};  // the normal pushing the body off the actee
    for (int i = 0; i < n_; ++i) {
      depth = std::max(depth, static_cast<double>(geoms_[i].depth));
      dContact contact{};
      contact.geom = geoms_[i];
      contact.surface = ode::surface((1 - share) * stiffness(geoms_[i].depth).secant, law_.kd, h_);
      const dJointID j = dJointCreateContact(world, group, &contact);
      const dBodyID b1 = dGeomGetBody(geoms_[i].g1);
      dJointAttach(j, b1, dGeomGetBody(geoms_[i].g2));
      dJointSetFeedback(j, &feedback_[i]);
      const double sign = b1 == body ? 1 : -1;
      for (int d = 0; d < 3; ++d) away[d] = sign * geoms_[i].normal[d];
    }
    // The viscoelastic share: loaded by the depth's change, relaxing with
    // its time constant; it only pushes.
    if (share > 0 && n_ > 0) {
      maxwell_ = maxwell_ * std::exp(-h_ / c_.outside.viscoelastic_tau) + share * stiffness(depth).tangent * (depth - depth_);
      maxwell_ = std::max(0.0, maxwell_);
      dBodyAddForceAtPos(body, maxwell_ * away[0], maxwell_ * away[1], maxwell_ * away[2], geoms_[0].pos[0],
                         geoms_[0].pos[1], geoms_[0].pos[2]);
    } else {
      maxwell_ = 0;
    }
    depth_ = depth;
  }
  // After the step: the actee's force, N (along the normal).
  double force() const {
    double f = maxwell_;
    for (int i = 0; i < n_; ++i) {
      const dReal* on = dGeomGetBody(geoms_[i].g1) == body_ ? feedback_[i].f1 : feedback_[i].f2;
      f += std::abs(on[0] * geoms_[i].normal[0] + on[1] * geoms_[i].normal[1] + on[2] * geoms_[i].normal[2]);
    }
    return f;
  }
  // Gone (cracked): no more contact.
  void clear() {
    n_ = 0;
    maxwell_ = 0;
    depth_ = 0;
  }

 private:
  // The specimen's secant stiffness at `depth` (ODE's penalty spring, its
  // stiffness rising with depth when the specimen's law is a power) and
  // its tangent stiffness, N/m. The engine's own law, not the actee
  // file's: a plain penalty spring K d lacks the file's h / (h - d), so
  // that against the file's law K d h / (h - d) fitted by the plates an
  // effect-free hazelnut or walnut differs by 0.6 to 2 N RMS at the effort
  // over the squeeze (up to 4 N near the crack; the egg 0.04 N), as a real
  // actee differs from any law written for it (seeds 501-560).
  struct Stiffness {
    double secant, tangent;
  };
  Stiffness stiffness(double depth) const {
    const double exponent = real_ ? c_.truth.actee_exponent : 0.0;
    if (exponent == 0 || exponent == 1) return {law_.kp, law_.kp};
    const double reference = c_.tool.actee->limit / law_.kp;  // m, where the power law meets the linear one
    const double x = std::max(depth, 1e-6 * reference) / reference;
    const double secant = law_.kp * std::pow(x, exponent - 1);
    return {secant, exponent * secant};
  }

  static constexpr int kMax = 4;
  const Case& c_;
  bool real_;
  double h_;
  ode::ContactLaw law_;
  dBodyID body_ = nullptr;
  int n_ = 0;
  dContactGeom geoms_[kMax];
  dJointFeedback feedback_[kMax];
  double maxwell_ = 0;  // N
  double depth_ = 0;    // m, at the last step
};

class OdeReality final : public Reality {
 public:
  const char* name() const override { return "ode"; }
  std::vector<Measured> play(const Case& c, const Drive& drive, unsigned noise_seed) const override;
  PlatesLaw plates(const Case& c) const override;
};

std::vector<Measured> OdeReality::play(const Case& c, const Drive& drive, unsigned noise_seed) const {
  const Tool& tool = c.tool;
  const Truth& truth = c.truth;
  const Outside& out = c.outside;
  if (!(tool.torsion > 0) || !(tool.effort_at > 0)) throw std::runtime_error("ode reality: " + tool.name + ": no spring or emphasis");
  const double h = step_for(c, drive);
  const int substeps = static_cast<int>(std::lround(1e-3 / h));
  ode::ToolScene scene(c, drive, h);
  const double preload = tool.preload_torque + truth.preload;  // N*m
  const double b = tool.effort_at;
  OdeActeeContact contact(c, true, h);

  double spring_angle = 0;  // rad, the spring's end behind the backlash
  bool broken = false;
  double load = 0;          // N, the actee's force on the load cell

  // One step of ODE with the servo's target at the step's end.
  auto step = [&](double target) {
    const double theta = scene.angle();
    // Backlash: the spring's end follows the arm only when the arm reaches
    // an end of the free play.
    if (out.backlash > 0) {
      spring_angle = std::clamp(spring_angle, theta - 0.5 * out.backlash, theta + 0.5 * out.backlash);
    } else {
      spring_angle = theta;
    }
    double torque = tool.torsion * (tool.rest - spring_angle) + preload;
    // The progressive spring: cubic * d^3 at the spring's lever arm.
    const double compression =
        tool.spring_position * (tool.rest - spring_angle) + preload / tool.torsion * tool.spring_position;
    if (compression > 0) torque += truth.cubic * compression * compression * compression * tool.spring_position;
    // The detent: a click, a Gaussian bump in the potential whose slope
    // peaks at the detent's torque (as the MuJoCo reality plays it).
    if (out.detent_torque > 0 && out.detent_width > 0) {
      const double u = (theta - out.detent_angle) / out.detent_width;
      torque += out.detent_torque * std::sqrt(std::exp(1.0)) * u * std::exp(-0.5 * u * u);
    }
    dJointAddHingeTorque(scene.hinge, torque);
    // The hand's servo, on the hand.
    const double servo = drive.servo_stiffness * (target - scene.hand_angle()) - drive.servo_damping * scene.hand_rate();
    dBodyAddTorque(scene.hand, 0, 0, servo);
    // The actee is in the jaws on the drives that squeeze it (the others
    // are played without it, as the MuJoCo reality does).
    const bool touching = scene.actee && drive.squeezes && !broken;
    if (touching) contact.add(scene.world, scene.contacts, scene.arm, scene.jaw, scene.actee);
    dWorldStep(scene.world, h);
    if (touching) {
      load = contact.force();
      if (tool.actee->breaks && load > tool.actee->limit) {  // the shell gives way: it resists no more
        broken = true;
        load = 0;
        contact.clear();
      }
    }
    dJointGroupEmpty(scene.contacts);
  };

  // Held at the start until it settles, as the experimenter starts.
  const double start = drive.target(0);
  scene.place(start);
  spring_angle = start;
  for (int i = 0, settle = static_cast<int>(std::lround(kSettle / h)); i < settle; ++i) step(start);

  SensorReadout sensors(c, noise_seed);
  const int samples = static_cast<int>(std::lround(drive.seconds * 1000));
  std::vector<Measured> trace;
  trace.reserve(static_cast<size_t>(samples));
  for (int k = 0; k < samples; ++k) {
    const double t = k * 1e-3;
    // The sensor's torque on the arm (its spring and damper) opens
    // positive; the effort closes positive.
    trace.push_back(sensors.read(k, scene.angle(), -scene.sensor_torque() / b, load, broken));
    for (int s = 1; s <= substeps; ++s) step(drive.target(t + s * h));
  }
  return trace;
}

PlatesLaw OdeReality::plates(const Case& c) const {
  if (!c.tool.actee) return {};
  const ToolActee& a = *c.tool.actee;
  const double radius = 0.5 * a.thickness;
  ode::PlatesScene scene(radius, kPlatesGap);
  const double h = kStep;
  OdeActeeContact contact(c, kPlatesTestTheRealSpecimen, h);
  dJointSetSliderParam(scene.slider, dParamVel, -kPlatesSpeed);
  dJointSetSliderParam(scene.slider, dParamFMax, 1e7);
  const double touch = radius;  // y of the actee's top: the plate's face there is zero deflection
  // The curve, read as a testing machine reads it; the experimenter fits
  // the actee file's law to it (plates_fit.h). ODE's contact itself is its
  // own penalty spring.
  PlatesLaw law;
  const int substeps = static_cast<int>(std::lround(1e-3 / h));
  // Long enough for the softest law to reach the limit: the viscoelastic
  // share relaxed, a power law's straight line.
  const double seconds = (kPlatesGap + 4 * a.limit / ode::contact_law(c).kp) / kPlatesSpeed;
  bool reached = false;
  for (int k = 0; k * 1e-3 < seconds && !reached; ++k) {
    double force = 0;
    for (int s = 0; s < substeps; ++s) {
      contact.add(scene.world, scene.contacts, scene.plate, scene.plate_geom, scene.actee);
      dWorldStep(scene.world, h);
      force = contact.force();
      dJointGroupEmpty(scene.contacts);
    }
    const double deflection = touch - scene.plate_face();
    reached = force >= a.limit;
    if (deflection > 0 && force <= a.limit) {
      law.deflection.push_back(deflection);
      law.force.push_back(force);
    }
  }
  if (!reached) throw std::runtime_error("ode reality: the plates did not squeeze " + a.file + " to its limit");
  const PlatesFit fit = fit_plates(law.deflection, law.force, a.thickness, a.limit);
  law.stiffness = fit.stiffness;
  law.rms_misfit = fit.rms_misfit;
  return law;
}

}  // namespace

std::unique_ptr<Reality> make_ode_reality() { return std::make_unique<OdeReality>(); }

}  // namespace gapcheck
