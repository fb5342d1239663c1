#include "probe.h"

#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "replay.h"
#include "units.h"

namespace afford {
namespace {

constexpr double kRestForce = 0.02;   // of the largest effort: below this the hand does not touch
constexpr double kBand = 0.02;        // of the range: this near a limit counts as on it

// "30 deg": an SI value in a unit of per_unit SI each.
std::string in_unit(double si, const char* unit, double per_unit) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g %s", si / per_unit, unit);
  return buf;
}

}  // namespace

ProbeResult probe_lever(const Measurement& m) {
  if (m.rig != Rig::lever || !m.object) fail(SourceLoc{m.file, 1, 1}, "a lever measurement to probe", "plates");
  ProbeResult p;
  p.object_file = m.object->file;
  const double b = std::abs(m.effort_at);
  // Limits: the angles the arm reaches; rest: where it sits untouched.
  double peak_force = 0;
  p.theta_min = 1e9;
  p.theta_max = -1e9;
  for (const Trace& t : m.traces) {
    for (size_t i = 0; i < t.size(); ++i) {
      peak_force = std::max(peak_force, t[Signal::effort_force][i]);
      p.theta_min = std::min(p.theta_min, t[Signal::angle][i]);
      p.theta_max = std::max(p.theta_max, t[Signal::angle][i]);
    }
  }
  std::vector<double> rest;
  for (const Trace& t : m.traces) {
    for (size_t i = 0; i < t.size(); ++i) {
      if (t[Signal::effort_force][i] < kRestForce * peak_force) rest.push_back(t[Signal::angle][i]);
    }
  }
  if (rest.empty()) fail(SourceLoc{m.file, 1, 1}, "a probe that lets go of the tool at least once (to see its rest angle)", "none");
  std::nth_element(rest.begin(), rest.begin() + static_cast<long>(rest.size() / 2), rest.end());
  p.theta_rest = rest[rest.size() / 2];

  // Between the limits, moving: torque = K (rest - theta) + P - T sign(omega).
  const double band = kBand * (p.theta_max - p.theta_min);
  Eigen::Matrix3d xtx = Eigen::Matrix3d::Zero();
  Eigen::Vector3d xty = Eigen::Vector3d::Zero();
  double yty = 0;
  for (const Trace& t : m.traces) {
    std::vector<double> omega(t.size());
    for (size_t i = 0; i < t.size(); ++i) {
      const size_t lo = i > 2 ? i - 2 : 0, hi = std::min(t.size() - 1, i + 2);
      omega[i] = (t[Signal::angle][hi] - t[Signal::angle][lo]) / (t[Signal::t][hi] - t[Signal::t][lo]);
    }
    double fastest = 0;
    for (double w : omega) fastest = std::max(fastest, std::abs(w));
    for (size_t i = 0; i < t.size(); ++i) {
      const double theta = t[Signal::angle][i];
      if (theta < p.theta_min + band || theta > p.theta_max - band || std::abs(omega[i]) < 0.01 * fastest) continue;
      const Eigen::Vector3d x(p.theta_rest - theta, 1.0, -smooth_sign(omega[i]));
      const double y = t[Signal::effort_force][i] * b;
      xtx += x * x.transpose();
      xty += x * y;
      yty += y * y;
      ++p.free_samples;
    }
  }
  if (p.free_samples < 10) fail(SourceLoc{m.file, 1, 1}, "a probe that moves the arm between its limits", "too few samples");
  const Eigen::Vector3d beta = xtx.ldlt().solve(xty);
  const double rss = std::max(0.0, yty - 2 * beta.dot(xty) + beta.dot(xtx * beta));
  const Eigen::Matrix3d cov = rss / static_cast<double>(p.free_samples - 3) * xtx.inverse();
  p.torsion = beta[0];
  p.preload_torque = beta[1];
  p.friction = beta[2];
  p.torsion_sigma = std::sqrt(cov(0, 0));
  p.preload_sigma = std::sqrt(cov(1, 1));
  p.friction_sigma = std::sqrt(cov(2, 2));
  const double sp = std::abs(m.object->spring.position);
  p.spring_constant = p.torsion / (sp * sp);
  p.preload = p.preload_torque / sp;
  return p;
}

std::string probe_text(const ProbeResult& p) {
  const double deg = 3.14159265358979323846 / 180;
  char buf[768];
  std::snprintf(buf, sizeof buf,
                "probe of %s (%zu samples moving between the limits):\n"
                "  theta_min %.3f deg, theta_max %.3f deg, rest %.3f deg\n"
                "  torsion spring S_k*S_p^2 = %.5g +- %.2g N*m/rad (S_k = %.5g N/m at the nominal S_p)\n"
                "  preload torque %.4g +- %.2g N*m (%.4g N at S_p)\n"
                "  pivot friction %.4g +- %.2g N*m\n",
                p.object_file.c_str(), p.free_samples, p.theta_min / deg, p.theta_max / deg, p.theta_rest / deg, p.torsion,
                p.torsion_sigma, p.spring_constant, p.preload_torque, p.preload_sigma, p.preload, p.friction,
                p.friction_sigma);
  return buf;
}

void write_probed_object(const ProbeResult& p, const std::string& path) {
  const double deg = 3.14159265358979323846 / 180;
  YAML::Node root = YAML::LoadFile(p.object_file);
  root["lever"]["theta_min"] = in_unit(p.theta_min, "deg", deg);
  root["lever"]["theta_max"] = in_unit(p.theta_max, "deg", deg);
  // A spring that pushes at rest holds the tool on its open stop.
  const double rest = p.preload > 0 ? p.theta_max : std::clamp(p.theta_rest, p.theta_min, p.theta_max);
  root["lever"]["rest"] = in_unit(rest, "deg", deg);
  root["spring"]["constant"] = in_unit(p.spring_constant, "N/m", 1);
  if (root["spring"]["rest_length"]) root["spring"].remove("rest_length");
  root["spring"]["preload"] = in_unit(std::max(0.0, p.preload), "N", 1);
  if (root["effects"] && root["effects"]["spring_preload"]) root["effects"].remove("spring_preload");
  if (p.friction > 2 * p.friction_sigma && p.friction > 0) {
    root["effects"]["pivot_friction"]["torque"] = in_unit(p.friction, "N*m", 1);
  }
  YAML::Emitter out;
  out << root;
  std::ofstream file(path);
  file << "# Written by afford gap --probe from " << p.object_file << ": lever limits, rest and spring as probed.\n"
       << out.c_str() << "\n";
  file.close();
  if (!file) throw std::runtime_error("cannot write " + path);
}

}  // namespace afford
