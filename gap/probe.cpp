#include "probe.h"

#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <fstream>
#include <functional>

#include "files.h"
#include "derivatives.h"
#include "replay.h"
#include "units.h"

namespace afford {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180;
constexpr double kProbeWindow = 0.01;      // s either side of a sample: its rate, and whether the arm is still
constexpr double kStillNoise = 8;     // still: the angle's range over the window within this many of its noise
constexpr double kUntouched = 4;      // untouched: the effort within this many of its noise of 0
constexpr double kStopNoise = 5;      // against a stop: the effort this many of its noise past friction's band
constexpr double kEdgeSigmas = 3;     // and past the band's own standard error this many times
constexpr double kBand = 0.02;        // of the visited range: this near either end the arm turns or sits still
constexpr size_t kMinSeen = 10;       // samples to call a stop or the rest seen
constexpr size_t kMinDirection = 50;  // samples moving each way to tell preload from friction

// "30 deg": an SI value in a unit of per_unit SI each. The text and the
// written file both use it, so what is printed is what is written.
std::string in_unit(double si, const char* unit, double per_unit) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g %s", si / per_unit, unit);
  return buf;
}

// A signal's white noise (white_noise), no finer than the column's
// printed resolution.
double noise_of(const std::vector<double>& y, double resolution) { return std::max(white_noise(y), resolution); }

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// One trace as the probe reads it.
struct Look {
  std::vector<double> omega;  // rad/s, the angle's slope across the window
  std::vector<char> still;    // the angle stays within its noise across the window
  double angle_noise = 0;     // rad
  double effort_noise = 0;    // N
  double omega_noise = 0;     // rad/s, the angle's noise in omega
  double fastest = 0;         // rad/s
};

Look look_at(const Trace& tr) {
  Look k;
  const std::vector<double>& t = tr[Signal::t];
  const std::vector<double>& a = tr[Signal::angle];
  const size_t n = tr.size();
  k.angle_noise = noise_of(a, tr.resolution[static_cast<size_t>(Signal::angle)]);
  k.effort_noise = noise_of(tr[Signal::effort_force], tr.resolution[static_cast<size_t>(Signal::effort_force)]);
  k.omega_noise = std::sqrt(2.0) * k.angle_noise / (2 * kProbeWindow);
  k.omega.resize(n);
  k.still.resize(n);
  // The window's largest and smallest angle, kept as it slides (deques of
  // indices, monotone), so a long trace costs one pass.
  std::deque<size_t> hi, lo;
  size_t first = 0, next = 0;
  for (size_t i = 0; i < n; ++i) {
    for (; next < n && t[next] <= t[i] + kProbeWindow; ++next) {
      while (!hi.empty() && a[hi.back()] <= a[next]) hi.pop_back();
      while (!lo.empty() && a[lo.back()] >= a[next]) lo.pop_back();
      hi.push_back(next);
      lo.push_back(next);
    }
    while (t[first] < t[i] - kProbeWindow) ++first;
    while (hi.front() < first) hi.pop_front();
    while (lo.front() < first) lo.pop_front();
    const size_t last = next - 1;
    k.omega[i] = last > first ? (a[last] - a[first]) / (t[last] - t[first]) : 0.0;
    k.still[i] = a[hi.front()] - a[lo.front()] <= kStillNoise * k.angle_noise;
    k.fastest = std::max(k.fastest, std::abs(k.omega[i]));
  }
  return k;
}

// A row of the spring's least squares and its sums: three columns, or two
// when friction is not told apart (held in place, no heap per sample).
using Row = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;

// The file's value of an enabled effect's first parameter, else 0.
double file_effect(const ObjectSpec& o, EffectKind kind) {
  for (const EffectSpec& e : o.effects) {
    if (e.kind == kind && e.enabled) return e.param[0];
  }
  return 0;
}

}  // namespace

ProbeResult probe_lever(const Measurement& m) {
  if (m.rig != Rig::lever || !m.object) fail(SourceLoc{m.file, 1, 1}, "a lever measurement to probe", "plates");
  const SourceLoc here{m.file, 1, 1};
  const ObjectSpec& o = *m.object;
  ProbeResult p;
  p.object_file = o.file;
  p.file_theta_min = o.lever.theta_min;
  p.file_theta_max = o.lever.theta_max;
  p.file_rest = o.lever.theta_rest;
  p.file_preload = file_effect(o, EffectKind::spring_preload);  // the spring section's preload is this effect
  p.file_friction = file_effect(o, EffectKind::pivot_friction);
  const double b = std::abs(m.effort_at);
  const double sp = std::abs(o.spring.position);
  p.spring_position = sp;

  std::vector<Look> looks;
  double visited_lo = 1e9, visited_hi = -1e9, angle_noise = 0;
  for (const Trace& t : m.traces) {
    looks.push_back(look_at(t));
    angle_noise = std::max(angle_noise, looks.back().angle_noise);
    for (double a : t[Signal::angle]) {
      visited_lo = std::min(visited_lo, a);
      visited_hi = std::max(visited_hi, a);
    }
  }

  // The spring from the samples moving clear of either end (where the arm
  // turns or sits on a stop): torque = K (c - theta) + B - T sign(omega),
  // B the spring's torque at the angle c, T the pivot's friction.
  const double band = kBand * (visited_hi - visited_lo);
  auto each_moving = [&](const std::function<void(double theta, double sign, double torque)>& f) {
    for (size_t j = 0; j < m.traces.size(); ++j) {
      const Trace& t = m.traces[j];
      const Look& k = looks[j];
      const double slow = std::max(0.01 * k.fastest, 5 * k.omega_noise);
      for (size_t i = 0; i < t.size(); ++i) {
        const double theta = t[Signal::angle][i];
        if (k.still[i] || std::abs(k.omega[i]) < slow) continue;
        if (theta < visited_lo + band || theta > visited_hi - band) continue;
        f(theta, smooth_sign(k.omega[i]), t[Signal::effort_force][i] * b);
      }
    }
  };
  double sum_theta = 0;
  each_moving([&](double theta, double sign, double) {
    sum_theta += theta;
    ++(sign < 0 ? p.closing_samples : p.opening_samples);
  });
  p.free_samples = p.closing_samples + p.opening_samples;
  if (p.free_samples < 10) fail(here, "a probe that moves the arm between its limits", "too few samples");
  const double c = sum_theta / static_cast<double>(p.free_samples);
  p.told_apart = p.closing_samples >= kMinDirection && p.opening_samples >= kMinDirection;
  const double one_way = p.closing_samples >= p.opening_samples ? 1.0 : -1.0;  // +1: closing, friction adds
  const int cols = p.told_apart ? 3 : 2;
  Square xtx = Square::Zero(cols, cols);
  Row xty = Row::Zero(cols);
  double yty = 0;
  auto row = [&](double theta, double friction_column) {
    Row x(cols);
    x[0] = c - theta;
    x[1] = 1;
    if (cols == 3) x[2] = friction_column;
    return x;
  };
  each_moving([&](double theta, double sign, double torque) {
    const Row x = row(theta, -sign);
    xtx += x * x.transpose();
    xty += x * torque;
    yty += torque * torque;
  });
  const Eigen::LDLT<Square> ldlt(xtx);
  if (ldlt.info() != Eigen::Success || ldlt.rcond() < 1e-12) {
    fail(here, "a probe that moves the arm over a range of angles", "the same angle throughout");
  }
  const Row beta = ldlt.solve(xty);
  const double rss = std::max(0.0, yty - 2 * beta.dot(xty) + beta.dot(xtx * beta));
  const Square cov =
      rss / static_cast<double>(p.free_samples - static_cast<size_t>(cols)) * ldlt.solve(Square::Identity(cols, cols));
  p.torsion = beta[0];
  p.torsion_sigma = std::sqrt(cov(0, 0));
  if (!(p.torsion > 0)) {
    fail(here, "a probe whose spring pushes back (a torsion above 0)", std::to_string(p.torsion) + " N*m/rad");
  }
  p.spring_constant = p.torsion / (sp * sp);
  if (p.told_apart) {
    p.friction = beta[2];
    p.friction_sigma = std::sqrt(cov(2, 2));
  }
  // The fitted line at theta, and its standard error: the spring's torque
  // (friction 0), or the effort's torque to move the arm closing (+1) or
  // opening (-1). Moving one way only, the line is that way's.
  auto line = [&](double theta, double friction_column, double* sigma) {
    const Row x = row(theta, friction_column);
    *sigma = std::sqrt(std::max(0.0, x.dot(cov * x)));
    return x.dot(beta);
  };

  // Limits: a still arm that the effort presses past the band friction can
  // hold (the other way's edge of the line) is on a stop; within the band
  // friction alone may hold it, and the stop is not seen.
  const bool closing_known = p.told_apart || one_way > 0;
  const bool opening_known = p.told_apart || one_way < 0;
  std::vector<double> lower, upper, untouched;
  for (size_t j = 0; j < m.traces.size(); ++j) {
    const Trace& t = m.traces[j];
    const Look& k = looks[j];
    const double margin = kStopNoise * k.effort_noise * b;
    for (size_t i = 0; i < t.size(); ++i) {
      if (!k.still[i]) continue;
      const double theta = t[Signal::angle][i], force = t[Signal::effort_force][i];
      if (std::abs(force) <= kUntouched * k.effort_noise) untouched.push_back(theta);
      double sigma = 0;
      if (closing_known) {
        const double edge = line(theta, p.told_apart ? 1.0 : 0.0, &sigma);
        if (force * b > edge + margin + kEdgeSigmas * sigma) lower.push_back(theta);
      }
      if (opening_known) {
        const double edge = line(theta, p.told_apart ? -1.0 : 0.0, &sigma);
        if (force * b < edge - margin - kEdgeSigmas * sigma) upper.push_back(theta);
      }
    }
  }
  p.min_found = lower.size() >= kMinSeen;
  p.max_found = upper.size() >= kMinSeen;
  p.min_samples = lower.size();
  p.max_samples = upper.size();
  // The file takes no opening below 0: a stop found at -noise is at 0.
  p.theta_min = p.min_found ? std::max(0.0, median(lower)) : p.file_theta_min;
  p.theta_max = p.max_found ? median(upper) : p.file_theta_max;
  if (!(p.theta_max > p.theta_min)) {
    fail(here, "a probe whose closed stop lies below its open one",
         "theta_min " + in_unit(p.theta_min, "deg", kDeg) + " and theta_max " + in_unit(p.theta_max, "deg", kDeg));
  }

  // The rest: where the untouched arm is seen still, on a stop if within
  // the angle's noise of it; else the file's, on the same stop as in the file.
  p.rest_seen = untouched.size() >= kMinSeen;
  p.rest_samples = untouched.size();
  double rest = std::clamp(p.file_rest, p.theta_min, p.theta_max);
  if (p.file_rest == p.file_theta_max) rest = p.theta_max;
  if (p.file_rest == p.file_theta_min) rest = p.theta_min;
  std::string why = "not observed (the untouched arm not seen still); the file's";
  if (rest == p.theta_max) why += ", on the open stop";
  if (rest == p.theta_min) why += ", on the closed stop";
  char seen[96] = "";
  if (p.rest_seen) {
    p.rest_seen_at = median(untouched);
    std::snprintf(seen, sizeof seen, " (seen still at %.6g deg, %zu samples)", p.rest_seen_at / kDeg, p.rest_samples);
  }
  if (p.rest_seen && p.told_apart) {
    const double tol = kStillNoise * angle_noise;
    if (p.rest_seen_at >= p.theta_max - tol) {
      rest = p.theta_max;
      why = "the untouched arm sits on the open stop";
    } else if (p.rest_seen_at <= p.theta_min + tol) {
      rest = p.theta_min;
      why = "the untouched arm sits on the closed stop";
    } else {
      rest = p.rest_seen_at;
      why = "where the untouched arm sits";
    }
    why += seen;
  }

  double sigma = 0;
  if (p.told_apart) {
    // The preload is the spring's push at the rest angle. The file holds a
    // spring that pushes there only with the rest on the open stop (one
    // that pulls, on the closed stop), else free at rest: an arm that
    // friction holds short of the stop rests, for the file, where the
    // spring is free or on the stop beyond.
    double torque = line(rest, 0, &sigma);
    const bool on_stop = (torque > 0 && rest == p.theta_max) || (torque < 0 && rest == p.theta_min);
    if (!on_stop && std::abs(torque) <= 2 * sigma) {
      torque = 0;  // within its standard error of 0: free at the rest angle
      why += "; the spring free there, within its standard error";
    } else if (!on_stop && torque != 0) {
      char held[192];
      if (p.rest_seen) {
        std::snprintf(held, sizeof held,
                      "the untouched arm seen still at %.6g deg (%zu samples), where the spring still pushes %.4g N "
                      "and friction holds it; written ",
                      rest / kDeg, p.rest_samples, torque / sp);
      } else {
        std::snprintf(held, sizeof held,
                      "not observed (the untouched arm not seen still); at the file's %.6g deg the spring pushes "
                      "%.4g N; written ",
                      rest / kDeg, torque / sp);
      }
      why = held;
      const double free_at = c + beta[1] / p.torsion;  // rad, where K (c - theta) + B = 0
      if (free_at >= p.theta_max || free_at <= p.theta_min) {
        rest = free_at >= p.theta_max ? p.theta_max : p.theta_min;
        torque = line(rest, 0, &sigma);
        why += rest == p.theta_max ? "on the open stop" : "on the closed stop";
      } else {
        rest = free_at;
        torque = 0;
        why += "where the spring is free";
      }
    }
    p.preload_torque = torque;
    p.preload_sigma = sigma;
    p.preload = torque / sp;
    p.friction_fitted = p.friction > 0 && p.friction > 2 * p.friction_sigma;
    p.friction_written = p.friction_fitted ? p.friction : p.file_friction;
  } else {
    // One way only, friction and the preload add up to one torque; the
    // file's preload and friction stay (and its rest, where that preload is).
    why = "the file's kept, where its preload is";
    if (rest == p.theta_max) why += ", on the open stop";
    if (rest == p.theta_min) why += ", on the closed stop";
    why += seen;
    p.combined_torque = line(rest, 0, &p.combined_sigma);
    p.preload = p.file_preload;
    p.preload_torque = p.file_preload * sp;
    p.friction_written = p.file_friction;
  }
  p.theta_rest = rest;
  p.rest_why = why;
  return p;
}

std::string probe_text(const ProbeResult& p) {
  std::string out;
  char line[1024];
  std::snprintf(line, sizeof line, "probe of %s: %zu samples moving clear of the ends of the travel (%zu closing, %zu opening)\n",
                p.object_file.c_str(), p.free_samples, p.closing_samples, p.opening_samples);
  out += line;
  auto limit = [&](const char* name, double value, bool found, size_t samples) {
    if (found) {
      std::snprintf(line, sizeof line,
                    "  %s %s: found, the arm still there, pressed against it past what friction holds (%zu samples)\n",
                    name, in_unit(value, "deg", kDeg).c_str(), samples);
    } else {
      std::snprintf(line, sizeof line,
                    "  %s %s: not reached (the arm never stayed still pressed past what friction holds); the file's kept\n",
                    name, in_unit(value, "deg", kDeg).c_str());
    }
    out += line;
  };
  limit("theta_min", p.theta_min, p.min_found, p.min_samples);
  limit("theta_max", p.theta_max, p.max_found, p.max_samples);
  out += "  rest " + in_unit(p.theta_rest, "deg", kDeg) + ": " + p.rest_why + "\n";
  std::snprintf(line, sizeof line,
                "  spring constant %s: torsion S_k*S_p^2 = %.5g +- %.2g N*m/rad at the nominal S_p = %.4g mm\n",
                in_unit(p.spring_constant, "N/m", 1).c_str(), p.torsion, p.torsion_sigma, 1e3 * p.spring_position);
  out += line;
  const std::string friction = in_unit(p.friction_written, "N*m", 1);
  if (p.told_apart) {
    std::snprintf(line, sizeof line, "  preload %s at the rest angle: %.4g +- %.2g N*m\n", in_unit(p.preload, "N", 1).c_str(),
                  p.preload_torque, p.preload_sigma);
    out += line;
    if (p.friction_fitted) {
      std::snprintf(line, sizeof line, "  pivot_friction %s: fitted, +- %.2g N*m\n", friction.c_str(), p.friction_sigma);
    } else {
      std::snprintf(line, sizeof line, "  pivot_friction %s: the file's kept; fitted %.4g +- %.2g N*m, not told from 0\n",
                    friction.c_str(), p.friction, p.friction_sigma);
    }
    out += line;
  } else {
    std::snprintf(line, sizeof line,
                  "  preload %s: the file's kept; the arm moved one way only (%s), where the preload and friction "
                  "add up to one torque (%.4g +- %.2g N*m at the rest angle) and cannot be told apart\n",
                  in_unit(p.preload, "N", 1).c_str(), p.closing_samples >= p.opening_samples ? "closing" : "opening",
                  p.combined_torque, p.combined_sigma);
    out += line;
    out += "  pivot_friction " + friction + ": the file's kept (likewise)\n";
  }
  return out;
}

void write_probed_object(const ProbeResult& p, const std::string& path) {
  YAML::Node root = YAML::LoadFile(p.object_file);
  YAML::Node lever = root["lever"];
  // What the probe did not see keeps the file's own text.
  if (p.min_found) lever["theta_min"] = in_unit(p.theta_min, "deg", kDeg);
  if (p.max_found) lever["theta_max"] = in_unit(p.theta_max, "deg", kDeg);
  // A rest on a stop is that stop's very text: the file takes a pushing
  // spring's rest only at theta_max exactly (a pulling one's at theta_min).
  if (p.theta_rest == p.theta_max) {
    lever["rest"] = YAML::Clone(lever["theta_max"]);
  } else if (p.theta_rest == p.theta_min) {
    lever["rest"] = YAML::Clone(lever["theta_min"]);
  } else {
    lever["rest"] = in_unit(p.theta_rest, "deg", kDeg);
  }
  YAML::Node spring = root["spring"];
  spring["constant"] = in_unit(p.spring_constant, "N/m", 1);
  // The preload at the rest angle, given as such (a rest length would move
  // it with the new constant); a pull is a rest length shorter than the gap.
  if (p.preload >= 0) {
    if (spring["rest_length"]) spring.remove("rest_length");
    spring["preload"] = in_unit(p.preload, "N", 1);
  } else {
    const double rest_length = p.spring_position * p.theta_rest + p.preload / p.spring_constant;  // m
    if (!(rest_length > 0)) throw std::runtime_error("the probed spring pulls harder than a spring of any length can");
    if (spring["preload"]) spring.remove("preload");
    spring["rest_length"] = in_unit(rest_length, "m", 1);
  }
  if (root["effects"] && root["effects"]["spring_preload"]) root["effects"].remove("spring_preload");
  if (p.friction_fitted) {
    YAML::Node friction = root["effects"]["pivot_friction"];
    friction["torque"] = in_unit(p.friction_written, "N*m", 1);
    if (friction["enabled"]) friction.remove("enabled");
  }
  YAML::Emitter out;
  out << root;
  // Through engine/base/output_file.h: never over an input or a file afford did not write.
  write_file_checked(path, "# Written by afford gap --probe from " + p.object_file +
                               ": lever limits, rest, spring and friction as probed where seen, the file's "
                               "elsewhere.\n" + out.c_str() + "\n");
}

}  // namespace afford
