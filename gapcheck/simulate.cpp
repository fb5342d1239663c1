// MuJoCo plays the real tool: a hinge with the tool's limits and torsion
// spring (stiffness and springref, the preload as springref's offset),
// pivot friction (frictionloss), damping, the arm's inertia (armature),
// its weight (a point mass with gravity in the plane of motion), a
// progressive spring (a torque the harness applies), driven by a stiff PD
// servo along the profile; the effort is the servo's torque over the lever
// arm, as a force sensor at the emphasis reads it, delayed by the sensor's
// latency, with noise and quantisation. An actee in the jaws pushes back
// with its law on the arc the jaw travels past the contact (the lever
// model's compression, a (theta_c - theta)), through its lever arm, until
// it breaks; a load cell under it reads its force.
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <unistd.h>

#include "truth.h"

namespace gapcheck {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;             // m/s^2
constexpr double kStep = 2e-4;          // s, MuJoCo's step
// m, where the arm's hidden weight sits: close to the pivot, so that its
// own inertia (weight * r / g) stays below the noise and the label "gravity"
// is the whole truth (at 0.1 m it added a third of the hidden-inertia
// case's torque, a second effect the label did not name).
constexpr double kWeightRadius = 0.02;
// kg*m^2: the arm's inertia when none is hidden, small enough to show no
// transient (1e-6 * 400 rad/s^2 at a triangle's corner is 0.003 N at the
// effort) and large enough for the servo (20 N*m/rad) to stay stable.
constexpr double kMinInertia = 1e-6;
constexpr double kEffortNoise = 0.02;   // N
constexpr double kEffortQuantum = 0.005;  // N
constexpr double kAngleNoise = 1e-4;    // rad
constexpr double kAngleQuantum = 1e-5;  // rad
constexpr double kActeeNoise = 0.1;     // N
constexpr double kActeeQuantum = 0.01;  // N
// The servo of a free drive, N*m/rad and N*m*s/rad.
constexpr double kServoStiffness = 20, kServoDamping = 0.1;

// A squeezing drive pushes against the actee's stiffness K a^2 (900 N*m/rad
// for a walnut at 60 mm): its servo is stiffer, critically damped, and the
// steps shorter so that the stiffest mode (sqrt(k / I) with I = 1e-6)
// stays well inside the explicit spring's stability.
struct Servo {
  double stiffness, damping, step;
};
Servo servo_for(const Tool& tool, const Profile& p) {
  if (p.squeeze == 0 || !tool.actee) return {kServoStiffness, kServoDamping, kStep};
  const double actee = tool.actee->stiffness * tool.actee->lever * tool.actee->lever;  // N*m/rad
  const double stiffness = std::max(kServoStiffness, 4 * actee);
  const double omega = std::sqrt((stiffness + actee) / kMinInertia);  // rad/s
  const double step = kStep / std::ceil(kStep * omega / 0.5);         // omega * step <= 0.5
  return {stiffness, 2 * std::sqrt((stiffness + actee) * kMinInertia), step};
}

// MuJoCo's friction loss is a soft constraint: below a speed it resists as
// a viscous torque, I b d / (1 - d) per rad/s (impedance d, b = 2 / (d
// time constant)). With the arm's 1e-6 kg*m^2, d = 0.99 and 0.4 ms that was
// 0.5 N*m*s/rad, viscous up to 0.054 rad/s: the squeezing drives' whole
// speed, an effect no label named. MuJoCo's hardest impedance (0.9999) and
// its shortest stable time constant (two steps) leave it viscous below
// 5e-4 rad/s on the free drives, 2e-5 rad/s on the squeezing ones.
std::string mjcf(const Tool& tool, const Truth& truth, double turned, const Servo& servo) {
  const double springref = tool.rest + (tool.preload_torque + truth.preload) / tool.torsion;
  const double mass = truth.weight > 0 ? truth.weight / (kG * kWeightRadius) : 1e-6;
  // Gravity in the plane of motion, turned with the tool: the weight's
  // torque is -weight * cos(angle + turned).
  char gravity[64];
  std::snprintf(gravity, sizeof gravity, "%.9g %.9g 0", -kG * std::sin(turned), -kG * std::cos(turned));
  char xml[2048];
  std::snprintf(xml, sizeof xml,
                "<mujoco model='gapcheck'>\n"
                "  <compiler angle='radian'/>\n"
                "  <option timestep='%g' gravity='%s' integrator='implicit'/>\n"
                "  <worldbody><body name='arm'>\n"
                "    <joint name='hinge' type='hinge' axis='0 0 1' limited='true' range='%.9g %.9g'\n"
                "           stiffness='%.9g' springref='%.9g' frictionloss='%.9g' damping='%.9g' armature='%.9g'\n"
                "           solreffriction='%.9g 1' solimpfriction='0.9999 0.9999 0.001'/>\n"
                "    <geom type='sphere' size='0.005' pos='%g 0 0' mass='%.9g' contype='0' conaffinity='0'/>\n"
                "  </body></worldbody>\n"
                "  <actuator><general name='servo' joint='hinge' gaintype='fixed' gainprm='%.9g' biastype='affine'\n"
                "                     biasprm='0 %.9g %.9g'/></actuator>\n"
                "</mujoco>\n",
                servo.step, truth.weight > 0 ? gravity : "0 0 -9.81", tool.theta_min - 0.2, tool.theta_max + 0.2,
                tool.torsion, springref, tool.friction + truth.friction, truth.damping, kMinInertia + truth.inertia,
                2 * servo.step, kWeightRadius, mass, servo.stiffness, -servo.stiffness, -servo.damping);
  return xml;
}

// The profile's angle at t: between 10 % and 90 % of the tool's range;
// with an actee, between 90 % and just clear of it (a free drive), or
// between just clear of it and the squeeze past its contact.
double target(const Tool& tool, const Profile& p, double t) {
  const double span = tool.theta_max - tool.theta_min;
  double mid = 0.5 * (tool.theta_min + tool.theta_max);
  double amp = 0.4 * span;
  if (tool.actee) {
    const ToolActee& a = *tool.actee;
    // Free: from 90 % of the range down to just clear of the actee.
    // Squeezing: from just clear of it to the squeeze past its contact.
    const double clear = a.contact_angle + 0.05 * span;
    const double high = p.squeeze > 0 ? clear : tool.theta_max - 0.1 * span;
    const double low = p.squeeze > 0 ? a.contact_angle - p.squeeze * a.limit / (a.stiffness * a.lever) : clear;
    mid = 0.5 * (high + low);
    amp = 0.5 * (high - low);
  }
  const double phase = t / p.period - std::floor(t / p.period);
  const double shape = p.triangle ? (phase < 0.5 ? 4 * phase - 1 : 3 - 4 * phase) : std::sin(2 * kPi * t / p.period);
  return mid + amp * shape;
}

double quantise(double x, double q) { return q * std::round(x / q); }

// N: the actee's force at the jaw's arc past the contact (truth.h).
double actee_force(const ToolActee& a, const Truth& truth, double deflection) {
  if (deflection <= 0) return 0;
  const double reference = a.limit / a.stiffness;
  const double law = truth.actee_exponent == 0
                         ? a.stiffness * deflection
                         : a.stiffness * reference * std::pow(deflection / reference, truth.actee_exponent);
  return law * a.thickness / (a.thickness - deflection);
}

}  // namespace

std::vector<Sample> simulate(const Tool& tool, const Truth& truth, const Profile& profile, unsigned seed) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("gapcheck-" + std::to_string(seed) + "-" + std::to_string(::getpid()) + ".xml");
  const Servo servo = servo_for(tool, profile);
  const int substeps = static_cast<int>(std::lround(1e-3 / servo.step));
  std::ofstream(file) << mjcf(tool, truth, profile.turned, servo);
  char error[1000] = "";
  mjModel* m = mj_loadXML(file.c_str(), nullptr, error, sizeof error);
  std::filesystem::remove(file);
  if (m == nullptr) throw std::runtime_error(std::string("MuJoCo: ") + error);
  mjData* d = mj_makeData(m);
  d->qpos[0] = target(tool, profile, 0);
  d->ctrl[0] = d->qpos[0];
  std::mt19937 random(seed);
  std::normal_distribution<double> effort_noise(0.0, kEffortNoise), angle_noise(0.0, kAngleNoise),
      load_noise(0.0, kActeeNoise);
  bool broken = false;
  double load = 0;  // N, the actee's force
  const double b = tool.effort_at;
  const int samples = static_cast<int>(std::lround(profile.seconds * 1000));
  std::vector<double> effort_history;  // N, at 1 kHz, before the sensor's delay
  std::vector<Sample> out;
  for (int k = 0; k < samples; ++k) {
    for (int s = 0; s < substeps; ++s) {
      const double t = d->time + servo.step;
      d->ctrl[0] = target(tool, profile, t);
      // The progressive spring: cubic * d^3 at the spring's lever arm.
      const double compression = tool.spring_position * (tool.rest - d->qpos[0]) +
                                 (tool.preload_torque + truth.preload) / tool.torsion * tool.spring_position;
      d->qfrc_applied[0] = compression > 0 ? truth.cubic * compression * compression * compression * tool.spring_position : 0.0;
      if (tool.actee && !broken) {
        const ToolActee& a = *tool.actee;
        load = actee_force(a, truth, a.lever * (a.contact_angle - d->qpos[0]));
        if (a.breaks && load > a.limit) {  // the shell gives way: it resists no more
          broken = true;
          load = 0;
        }
        d->qfrc_applied[0] += load * a.lever;  // it pushes the jaws open where the jaw touches it
      }
      mj_step(m, d);
    }
    // The servo's torque opens positive; the effort closes positive.
    effort_history.push_back(-d->actuator_force[0] / b);
    const double t = k * 1e-3;
    const double delayed_index = k - truth.latency * 1000;
    double effort = effort_history.front();
    if (delayed_index > 0) {
      const auto i = static_cast<size_t>(delayed_index);
      const double w = delayed_index - static_cast<double>(i);
      effort = i + 1 < effort_history.size() ? (1 - w) * effort_history[i] + w * effort_history[i + 1] : effort_history[i];
    }
    const double angle = quantise(d->qpos[0] + angle_noise(random), kAngleQuantum);
    effort = quantise(effort + effort_noise(random), kEffortQuantum);
    const double actee = tool.actee ? quantise(load + load_noise(random), kActeeQuantum) : 0.0;
    out.push_back({t, angle, effort, actee, broken});
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return out;
}

}  // namespace gapcheck
