// MuJoCo 2.2.2 plays the real tool. The arm on a hinge with the tool
// file's torsion spring (stiffness, springref: the preload as its offset),
// pivot friction (frictionloss with MuJoCo's hardest friction constraint),
// damping, inertia (armature) and weight (a point mass under gravity in
// the plane of motion, turned with the tool); a progressive spring, a
// backlash's dead band and a detent applied by the harness. The hand is a
// mass on its own hinge, coaxial with the arm's, driven by a PD servo
// toward the drive's target and pushing the arm through a stiff, damped
// force sensor (a fixed tendon between the two hinges): the effort is the
// force that tendon carries at the emphasis. The actee is a MuJoCo sphere
// where the moving jaw first touches it (a point contact, at
// kContactRadiusPerDepth below), its contact with the jaw MuJoCo's own
// soft contact, its solref and solimp set once in the scene and never
// changed while it plays (the effect-free specimen a flat impedance,
// MuJoCo's linear spring; the library's actee_compliance an impedance that
// rises with depth, design.h), dropped when its force passes the file's
// limit; a load cell reads that contact's force. Between two plates the
// whole actee's geom, the reference specimen of the kind (the effect-free
// contact, of the case's specimen stiffness), gives the curve a testing
// machine reads, which the experimenter fits with the actee file's law
// (plates_fit.h).
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <numbers>

#include "jaw_contact.h"
#include "plates_fit.h"
#include "reality.h"
#include "sensor_readout.h"

namespace gapcheck {
namespace {

constexpr double kG = 9.81;  // m/s^2
// kg*m^2: the arm's inertia when none is hidden: below the noise at any
// drive's acceleration (1e-6 * 400 rad/s^2 is 4e-4 N*m); the design damps
// the sensor for it and the hidden inertia (design.cpp).
constexpr double kMinInertia = 1e-6;
// m: where the hidden weight's mass sits, close to the pivot so that its
// own inertia (weight * r / g) is a hundredth of its torque per 100 rad/s^2.
constexpr double kWeightRadius = 1e-3;
// MuJoCo's soft contact pushes with f = k d^2 p / (dmax^2 (1 - d) A) at a
// penetration p (direct solref, k = -solref[0], impedance d from solimp,
// at rest), A the pressing bodies' mean inverse weight at qpos0
// (body_invweight0). That weight is the arm's about a hinge in the tool
// and the plate's on the plates' rig: the same contact would be stiffer
// on one than on the other, which no real material is. Both rigs give the
// body that presses the actee this one inverse weight, so that one solref
// is one material; large against the true inverse weights (r^2 / I of the
// arm, 1 / m of the plate) the contact then acts as a spring on the true
// masses. The actees are smooth (tools.cpp): each jaw geom's pair makes
// one contact, so no solref is shared among a face's corners.
constexpr double kInvWeight = 1e6;  // 1/kg
// Gives `body` (the arm, or the plate) that inverse weight, translation and rotation.
void press_with_one_weight(mjModel* m, int body) {
  m->body_invweight0[2 * body] = kInvWeight;
  m->body_invweight0[2 * body + 1] = kInvWeight;
}
// The contact's damping: a tenth of critical for the arm at its lightest.
constexpr double kContactDampingRatio = 0.1;
// The actee in the jaws is a sphere placed where the moving jaw first
// touches the actee (jaw_contact), its radius twice the depth at which the
// specimen's linear law reaches the limit: deep enough that the jaw never
// reaches its centre, small enough to roll little. A whole round actee
// rolls under the turning jaw: its point of contact moves out along the
// face by about (a^2 / b) delta for semi-axes a along the jaw and b
// across it, and its depth grows by a^2 delta^2 / (2 b) beyond the
// lever's. Afford's lever does not model that (its moment arm and depth
// are the file's), and it is no effect of the library: the effect-free
// pecans (22.35 by 11.65 mm) of development seeds 3082 and 3094 came out
// 1.1 and 1.55 times the floor off in the contact, and an actee's law was
// named beside the true set in 7 more pecan cases and a hazelnut's. As in
// the ODE reality (ode_scene.cpp) the actee's own contact is kept and the
// rolling left out (afford_gapcheck_tests holds the force to the lever's
// depth). The plates still press the whole actee: a flat plate does not
// roll it, and MuJoCo's force depends on the penetration alone.
constexpr double kContactRadiusPerDepth = 2;
constexpr double kFar = 10;  // m, where a broken actee goes (out of reach of every geom)

const char* geom_type(int type) {
  switch (type) {
    case mjGEOM_SPHERE: return "sphere";
    case mjGEOM_ELLIPSOID: return "ellipsoid";
    case mjGEOM_BOX: return "box";
    case mjGEOM_CAPSULE: return "capsule";
    case mjGEOM_CYLINDER: return "cylinder";
    default: throw std::runtime_error("gapcheck: the MuJoCo reality plays spheres, ellipsoids, boxes, capsules and cylinders");
  }
}

std::string geom_xml(const std::string& name, const SceneGeom& g, bool at_origin) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "<geom name='%s' type='%s' size='%.9g %.9g %.9g' pos='%.9g %.9g %.9g' quat='%.9g %.9g %.9g %.9g' "
                "contype='0' conaffinity='0'/>",
                name.c_str(), geom_type(g.type), g.size[0], g.size[1], g.size[2], at_origin ? 0.0 : g.pos[0],
                at_origin ? 0.0 : g.pos[1], at_origin ? 0.0 : g.pos[2], at_origin ? 1.0 : g.quat[0],
                at_origin ? 0.0 : g.quat[1], at_origin ? 0.0 : g.quat[2], at_origin ? 0.0 : g.quat[3]);
  return buf;
}

// A model from XML text, through MuJoCo's virtual file system.
struct Sim {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  explicit Sim(const std::string& xml) {
    auto vfs = std::make_unique<mjVFS>();
    mj_defaultVFS(vfs.get());
    const int size = static_cast<int>(xml.size());
    if (mj_makeEmptyFileVFS(vfs.get(), "gapcheck.xml", size) != 0) throw std::runtime_error("MuJoCo: no room for the scene");
    std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), "gapcheck.xml")], xml.data(), xml.size());
    char error[1000] = "";
    m = mj_loadXML("gapcheck.xml", vfs.get(), error, sizeof error);
    mj_deleteVFS(vfs.get());
    if (m == nullptr) throw std::runtime_error(std::string("MuJoCo: ") + error + "\n" + xml);
    d = mj_makeData(m);
    // MPR (the ellipsoids' collider) to far below a micrometre: at
    // 270 N/mm a micrometre of penetration is 0.27 N.
    m->opt.mpr_tolerance = 1e-12;
    m->opt.mpr_iterations = 200;
  }
  ~Sim() {
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  Sim(const Sim&) = delete;
  Sim& operator=(const Sim&) = delete;
};

// The actee's contact, fixed for a case: MuJoCo's solref (direct) and
// solimp, and the static force they give (for the harness's relaxing share).
struct ActeeContact {
  double stiffness = 0;  // N/m, the specimen's where the impedance is at dmax
  double elastic = 1;    // the share that does not relax (viscoelastic_actee): the solref's
  double damping = 0;    // N*s/m, where the impedance is at dmax
  ActeeImpedance impedance;  // design.h: flat for the effect-free specimen

  // -k and -b such that the impedance at dmax gives the stiffness and damping.
  std::string solref() const {
    char buf[64];
    const double scale = (1 - impedance.dmax) * kInvWeight;
    std::snprintf(buf, sizeof buf, "%.12g %.12g", -elastic * stiffness * scale, -damping * scale);
    return buf;
  }
  std::string solimp() const {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.12g %.12g %.12g %.12g %.12g", impedance.d0, impedance.dmax, impedance.width,
                  impedance.midpoint, impedance.power);
    return buf;
  }
  // N: MuJoCo's static force at penetration p (m), elastic and relaxing together.
  double force(double p) const { return p > 0 ? stiffness * p * impedance.law(p) : 0.0; }
};

double arm_inertia(const Case& c) {
  const double mass = c.truth.weight > 0 ? c.truth.weight / (kG * kWeightRadius) : 0.0;
  return kMinInertia + c.truth.inertia + mass * kWeightRadius * kWeightRadius;
}

// The specimen in the jaws (`real`: its stiffening and viscoelastic share)
// or the reference specimen of its kind that the plates measure
// (effect-free: a flat impedance, nothing relaxing), both of the case's
// specimen stiffness.
ActeeContact actee_contact(const Case& c, bool real) {
  const ToolActee& a = *c.tool.actee;
  ActeeContact contact;
  contact.stiffness = a.stiffness * c.actee_specimen;
  if (real) {
    contact.impedance = c.actee_impedance;
    contact.elastic = 1 - c.outside.viscoelastic_share;
  }
  const double mass = arm_inertia(c) / (a.lever * a.lever);  // kg, the arm's at the jaw
  contact.damping = 2 * kContactDampingRatio * std::sqrt(contact.stiffness * mass);
  return contact;
}

// The actee's contacts: the normal force they carry (N) and the deepest
// penetration (m).
struct ContactRead {
  double force = 0, penetration = 0;
};
ContactRead read_contacts(const mjModel* m, mjData* d, int actee_geom) {
  ContactRead r;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& con = d->contact[i];
    if (con.geom1 != actee_geom && con.geom2 != actee_geom) continue;
    mjtNum f[6];
    mj_contactForce(m, d, i, f);
    r.force += f[0];
    r.penetration = std::max(r.penetration, -con.dist);
  }
  return r;
}

// The relaxing share of a viscoelastic actee: a Maxwell element (a spring
// with the law's share, in series with a dashpot of time constant tau),
// applied by the harness along with MuJoCo's contact.
struct Maxwell {
  double share = 0, tau = 0;  // s
  double force = 0;           // N
  double last_law = 0;        // N, the law's force at the step before
  void step(double law_force, double h, bool touching) {
    if (share == 0) return;
    force = touching ? std::max(0.0, force * std::exp(-h / tau) + share * (law_force - last_law)) : 0.0;
    last_law = touching ? law_force : 0.0;
  }
};

// Explicit steps stay stable while the stiffest mode turns at most 0.8 rad
// a step (rad/s).
double step_for(double omega) { return std::min(2e-4, 0.8 / omega); }

class MujocoReality final : public Reality {
 public:
  const char* name() const override { return "mujoco"; }
  std::vector<Measured> play(const Case& c, const Drive& drive, unsigned noise_seed) const override;
  PlatesLaw plates(const Case& c) const override;
};

std::vector<Measured> MujocoReality::play(const Case& c, const Drive& drive, unsigned noise_seed) const {
  const Tool& tool = c.tool;
  const Truth& truth = c.truth;
  const bool with_actee = tool.actee.has_value() && drive.squeezes;
  const double b = tool.effort_at;
  const double inertia = arm_inertia(c);
  const double hand_inertia = c.hand.mass * b * b;
  const ActeeContact contact = with_actee ? actee_contact(c, true) : ActeeContact{};
  // The stiffest mode: the arm between the sensor, the spring and the
  // actee (its impedance may stiffen it, so thrice its stiffness), or the hand.
  const double actee_rotational = with_actee ? 3 * contact.stiffness * tool.actee->lever * tool.actee->lever : 0.0;
  const double omega = std::max(std::sqrt((c.hand.sensor_stiffness + tool.torsion + actee_rotational) / inertia),
                                std::sqrt((drive.servo_stiffness + c.hand.sensor_stiffness) / hand_inertia));
  const int substeps = static_cast<int>(std::ceil(1e-3 / step_for(omega)));
  const double h = 1e-3 / substeps;

  const double springref = tool.rest + (tool.preload_torque + truth.preload) / tool.torsion;
  const double mass = truth.weight > 0 ? truth.weight / (kG * kWeightRadius) : 1e-6;
  std::string xml;
  char buf[2048];
  std::snprintf(buf, sizeof buf,
                "<mujoco model='gapcheck'>\n"
                "  <compiler angle='radian'/>\n"
                "  <option timestep='%.9g' gravity='%.9g %.9g 0' integrator='implicit'/>\n"
                "  <worldbody>\n"
                "    <body name='arm'>\n"
                "      <inertial pos='%.9g 0 0' mass='%.9g' diaginertia='1e-12 1e-12 1e-12'/>\n"
                "      <joint name='hinge' type='hinge' axis='0 0 1' limited='true' range='%.9g %.9g'\n"
                "             stiffness='%.9g' springref='%.9g' frictionloss='%.9g' damping='%.9g' armature='%.9g'\n"
                "             solreffriction='%.9g 1' solimpfriction='0.9999 0.9999 0.001'/>\n",
                h, -kG * std::sin(drive.turned), -kG * std::cos(drive.turned), kWeightRadius, mass,
                tool.theta_min - 0.3, tool.theta_max + 0.3, tool.torsion, springref, tool.friction + truth.friction,
                truth.damping, kMinInertia + truth.inertia, 2 * h);
  xml += buf;
  const JawScene& scene = c.jaws;
  if (with_actee) {
    for (size_t i = 0; i < scene.moving.size(); ++i) xml += "      " + geom_xml("jaw" + std::to_string(i), scene.moving[i], false) + "\n";
  }
  std::snprintf(buf, sizeof buf,
                "    </body>\n"
                "    <body name='hand'>\n"
                "      <inertial pos='0 0 0' mass='1e-6' diaginertia='1e-12 1e-12 1e-12'/>\n"
                "      <joint name='hand' type='hinge' axis='0 0 1' armature='%.9g'/>\n"
                "    </body>\n",
                hand_inertia);
  xml += buf;
  if (with_actee) {
    const ToolActee& a = *tool.actee;
    const double radius = kContactRadiusPerDepth * a.limit / contact.stiffness;  // m
    double centre[3];
    for (int i = 0; i < 3; ++i) centre[i] = a.touch[i] + radius * a.into[i];
    std::snprintf(buf, sizeof buf,
                  "    <body name='actee' mocap='true' pos='%.9g %.9g %.9g'>\n"
                  "      <geom name='actee' type='sphere' size='%.9g' contype='0' conaffinity='0'/>\n"
                  "    </body>\n",
                  centre[0], centre[1], centre[2], radius);
    xml += buf;
  }
  xml += "  </worldbody>\n";
  if (with_actee) {
    xml += "  <contact>\n";
    for (size_t i = 0; i < scene.moving.size(); ++i) {
      xml += "    <pair geom1='jaw" + std::to_string(i) + "' geom2='actee' condim='1' solref='" + contact.solref() +
             "' solimp='" + contact.solimp() + "'/>\n";
    }
    xml += "  </contact>\n";
  }
  std::snprintf(buf, sizeof buf,
                "  <tendon><fixed name='sensor' stiffness='%.9g' damping='%.9g' springlength='0'>\n"
                "    <joint joint='hand' coef='1'/><joint joint='hinge' coef='-1'/></fixed></tendon>\n"
                "  <actuator><general name='servo' joint='hand' gaintype='fixed' gainprm='%.9g' biastype='affine'\n"
                "                     biasprm='0 %.9g %.9g'/></actuator>\n"
                "</mujoco>\n",
                c.hand.sensor_stiffness, c.hand.sensor_damping, drive.servo_stiffness, -drive.servo_stiffness,
                -drive.servo_damping);
  xml += buf;

  Sim sim(xml);
  mjModel* m = sim.m;
  mjData* d = sim.d;
  const int arm_body = mj_name2id(m, mjOBJ_BODY, "arm");
  press_with_one_weight(m, arm_body);
  const int actee_geom = with_actee ? mj_name2id(m, mjOBJ_GEOM, "actee") : -1;
  const int hinge = m->jnt_qposadr[mj_name2id(m, mjOBJ_JOINT, "hinge")];
  const int hand = m->jnt_qposadr[mj_name2id(m, mjOBJ_JOINT, "hand")];
  const int arm_dof = m->jnt_dofadr[mj_name2id(m, mjOBJ_JOINT, "hinge")];
  const int hand_dof = m->jnt_dofadr[mj_name2id(m, mjOBJ_JOINT, "hand")];

  Maxwell maxwell{c.outside.viscoelastic_share, c.outside.viscoelastic_tau};
  double backlash_end = 0;  // rad, where the spring's end is (backlash)
  double load = 0;          // N, the actee's force
  bool broken = false;
  // The harness's torques on the hinge, then one MuJoCo step.
  auto step = [&](double t) {
    d->ctrl[0] = drive.target(t);
    const double theta = d->qpos[hinge];
    double torque = 0;  // N*m, opening positive
    // The progressive spring: cubic * x^3 at the spring's arm, x its compression.
    const double compression = tool.spring_position * (springref - theta);
    if (compression > 0) torque += truth.cubic * compression * compression * compression * tool.spring_position;
    if (c.outside.backlash > 0) {
      // The spring's end follows the arm only across the play: MuJoCo's
      // joint spring pulls toward springref from theta, the spring from its end.
      const double half = 0.5 * c.outside.backlash;
      backlash_end = std::clamp(backlash_end, theta - half, theta + half);
      torque += tool.torsion * (theta - backlash_end);
    }
    if (c.outside.detent_torque > 0) {
      // A click: a bump in the potential, its slope peaking at the torque.
      const double u = (theta - c.outside.detent_angle) / c.outside.detent_width;
      torque += c.outside.detent_torque * std::sqrt(std::exp(1.0)) * u * std::exp(-0.5 * u * u);
    }
    if (with_actee && !broken) {
      torque += maxwell.force * tool.actee->lever;
    }
    d->qfrc_applied[arm_dof] = torque;
    mj_step(m, d);
    if (with_actee && !broken) {
      const ContactRead r = read_contacts(m, d, actee_geom);
      maxwell.step(contact.force(r.penetration), h, r.penetration > 0);
      load = r.force + maxwell.force;
      if (tool.actee->breaks && load > tool.actee->limit) {  // the shell gives way: it resists no more
        broken = true;
        load = 0;
        maxwell.force = 0;
        d->mocap_pos[2] += kFar;
      }
    }
  };

  // Settle at the drive's start, holding its first target, before the
  // record begins.
  d->qpos[hinge] = d->qpos[hand] = drive.target(0);
  backlash_end = drive.target(0);
  mj_forward(m, d);
  for (int k = 0; k < 300 * substeps; ++k) step(0);

  SensorReadout sensors(c, noise_seed);
  const int samples = static_cast<int>(std::lround(drive.seconds * 1000));
  std::vector<Measured> out;
  out.reserve(static_cast<size_t>(samples));
  for (int k = 0; k < samples; ++k) {
    const double t = k * 1e-3;
    // The sensor's stretch is hand minus arm (the tendon's length; from
    // the state now, as mj_step leaves ten_length one step behind); its
    // force closes the arm.
    const double stretch = d->qpos[hand] - d->qpos[hinge];
    const double rate = d->qvel[hand_dof] - d->qvel[arm_dof];
    const double felt = -(c.hand.sensor_stiffness * stretch + c.hand.sensor_damping * rate) / b;
    out.push_back(sensors.read(k, d->qpos[hinge], felt, load, broken));
    for (int i = 0; i < substeps; ++i) step(t + (i + 1) * h);
  }
  return out;
}

PlatesLaw MujocoReality::plates(const Case& c) const {
  const ToolActee& a = *c.tool.actee;
  const ActeeContact contact = actee_contact(c, false);
  const SceneGeom& actee = c.jaws.actee;
  // The plate: a crosshead on a slide across the jaws' direction (y),
  // driven ten times as stiff as the actee, starting just touching it.
  constexpr double kPlateMass = 0.05;  // kg
  constexpr double kPlateHalf = 0.005; // m
  const double kp = 10 * contact.stiffness;
  const double kv = 2 * std::sqrt(kp * kPlateMass);
  const double h = 1e-3 / std::ceil(1e-3 / step_for(std::sqrt(3 * (kp + contact.stiffness) / kPlateMass)));
  char buf[2048];
  std::snprintf(buf, sizeof buf,
                "<mujoco model='gapcheck-plates'>\n"
                "  <option timestep='%.9g' gravity='0 0 0' integrator='implicit'/>\n"
                "  <worldbody>\n"
                "    <geom name='anvil' type='box' size='0.05 %.9g 0.05' pos='0 %.9g 0' contype='0' conaffinity='0'/>\n"
                "    <body name='actee' mocap='true' pos='0 0 0' quat='%.9g %.9g %.9g %.9g'>\n"
                "      %s\n"
                "    </body>\n"
                "    <body name='plate' pos='0 %.9g 0'>\n"
                "      <inertial pos='0 0 0' mass='%.9g' diaginertia='1e-6 1e-6 1e-6'/>\n"
                "      <joint name='press' type='slide' axis='0 -1 0'/>\n"
                "      <geom name='plate' type='box' size='0.05 %.9g 0.05' contype='0' conaffinity='0'/>\n"
                "    </body>\n"
                "  </worldbody>\n"
                "  <contact><pair geom1='plate' geom2='actee' condim='1' solref='%s' solimp='%s'/></contact>\n"
                "  <actuator><general name='crosshead' joint='press' gaintype='fixed' gainprm='%.9g' biastype='affine'\n"
                "                     biasprm='0 %.9g %.9g'/></actuator>\n"
                "</mujoco>\n",
                h, kPlateHalf, -(0.5 * a.thickness + kPlateHalf), actee.quat[0], actee.quat[1], actee.quat[2],
                actee.quat[3], geom_xml("actee", actee, true).c_str(), 0.5 * a.thickness + kPlateHalf, kPlateMass,
                kPlateHalf, contact.solref().c_str(), contact.solimp().c_str(), kp, -kp, -kv);
  Sim sim(buf);
  mjModel* m = sim.m;
  mjData* d = sim.d;
  const int plate = mj_name2id(m, mjOBJ_BODY, "plate");
  press_with_one_weight(m, plate);
  const int actee_geom = mj_name2id(m, mjOBJ_GEOM, "actee");
  // Slowly: to the limit's deflection in 2 s, read at 1 kHz up to the
  // limit, the crosshead's travel since it touched and the load cell.
  const double speed = a.limit / contact.stiffness / 2;  // m/s
  const int substeps = static_cast<int>(std::lround(1e-3 / h));
  PlatesLaw out;
  for (int k = 1; k <= 4000; ++k) {
    for (int i = 0; i < substeps; ++i) {
      d->ctrl[0] = speed * d->time;
      mj_step(m, d);
    }
    const double x = d->qpos[0];  // m
    const double force = read_contacts(m, d, actee_geom).force;
    if (force > a.limit) break;
    if (x <= 0) continue;
    out.deflection.push_back(x);
    out.force.push_back(force);
  }
  const PlatesFit fit = fit_plates(out.deflection, out.force, a.thickness, a.limit);
  out.stiffness = fit.stiffness;
  out.rms_misfit = fit.rms_misfit;
  return out;
}

}  // namespace

std::unique_ptr<Reality> make_mujoco_reality() { return std::make_unique<MujocoReality>(); }

}  // namespace gapcheck
