// MuJoCo plays the real tool: a hinge with the tool's limits and torsion
// spring (stiffness and springref, the preload as springref's offset),
// pivot friction (frictionloss), damping, the arm's inertia (armature),
// its weight (a point mass with gravity in the plane of motion), a
// progressive spring (a torque the harness applies), driven by a stiff PD
// servo along the profile; the effort is the servo's torque over the lever
// arm, as a force sensor at the emphasis reads it, delayed by the sensor's
// latency, with noise and quantisation.
#include <mujoco/mujoco.h>

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
constexpr int kSubsteps = 5;            // per 1 kHz sample
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

std::string mjcf(const Tool& tool, const Truth& truth, double turned) {
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
                "           solreffriction='0.0004 1' solimpfriction='0.99 0.999 0.001'/>\n"
                "    <geom type='sphere' size='0.005' pos='%g 0 0' mass='%.9g' contype='0' conaffinity='0'/>\n"
                "  </body></worldbody>\n"
                "  <actuator><general name='servo' joint='hinge' gaintype='fixed' gainprm='20' biastype='affine'\n"
                "                     biasprm='0 -20 -0.1'/></actuator>\n"
                "</mujoco>\n",
                kStep, truth.weight > 0 ? gravity : "0 0 -9.81", tool.theta_min - 0.2, tool.theta_max + 0.2,
                tool.torsion, springref, tool.friction + truth.friction, truth.damping, kMinInertia + truth.inertia,
                kWeightRadius, mass);
  return xml;
}

// The profile's angle at t: between 10 % and 90 % of the tool's range.
double target(const Tool& tool, const Profile& p, double t) {
  const double mid = 0.5 * (tool.theta_min + tool.theta_max);
  const double amp = 0.4 * (tool.theta_max - tool.theta_min);
  const double phase = t / p.period - std::floor(t / p.period);
  const double shape = p.triangle ? (phase < 0.5 ? 4 * phase - 1 : 3 - 4 * phase) : std::sin(2 * kPi * t / p.period);
  return mid + amp * shape;
}

double quantise(double x, double q) { return q * std::round(x / q); }

}  // namespace

std::vector<Sample> simulate(const Tool& tool, const Truth& truth, const Profile& profile, unsigned seed) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("gapcheck-" + std::to_string(seed) + "-" + std::to_string(::getpid()) + ".xml");
  std::ofstream(file) << mjcf(tool, truth, profile.turned);
  char error[1000] = "";
  mjModel* m = mj_loadXML(file.c_str(), nullptr, error, sizeof error);
  std::filesystem::remove(file);
  if (m == nullptr) throw std::runtime_error(std::string("MuJoCo: ") + error);
  mjData* d = mj_makeData(m);
  d->qpos[0] = target(tool, profile, 0);
  d->ctrl[0] = d->qpos[0];
  std::mt19937 random(seed);
  std::normal_distribution<double> effort_noise(0.0, kEffortNoise), angle_noise(0.0, kAngleNoise);
  const double b = tool.effort_at;
  const int samples = static_cast<int>(std::lround(profile.seconds * 1000));
  std::vector<double> effort_history;  // N, at 1 kHz, before the sensor's delay
  std::vector<Sample> out;
  for (int k = 0; k < samples; ++k) {
    for (int s = 0; s < kSubsteps; ++s) {
      const double t = d->time + kStep;
      d->ctrl[0] = target(tool, profile, t);
      // The progressive spring: cubic * d^3 at the spring's lever arm.
      const double compression = tool.spring_position * (tool.rest - d->qpos[0]) +
                                 (tool.preload_torque + truth.preload) / tool.torsion * tool.spring_position;
      d->qfrc_applied[0] = compression > 0 ? truth.cubic * compression * compression * compression * tool.spring_position : 0.0;
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
    out.push_back({t, quantise(d->qpos[0] + angle_noise(random), kAngleQuantum),
                   quantise(effort + effort_noise(random), kEffortQuantum), 0.0});
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return out;
}

}  // namespace gapcheck
