#include "plates_fit.h"

#include <cmath>
#include <stdexcept>

namespace gapcheck {
namespace {

// Power laws an actee file takes whose exponent is searched (plain numbers).
constexpr double kLowest = 0.5, kHighest = 4.0;

struct Points {
  std::vector<double> x, f;  // m, N
  double h = 0;              // m
};

// F = C x^n h / (h - x): C by least squares through 0 (it is linear in C),
// and the RMS misfit (N).
void fit_power(const Points& p, double n, double* c, double* rms) {
  double fg = 0, gg = 0;
  for (size_t i = 0; i < p.x.size(); ++i) {
    const double g = std::pow(p.x[i], n) * p.h / (p.h - p.x[i]);
    fg += p.f[i] * g;
    gg += g * g;
  }
  *c = fg / gg;
  double sq = 0;
  for (size_t i = 0; i < p.x.size(); ++i) {
    sq += std::pow(p.f[i] - *c * std::pow(p.x[i], n) * p.h / (p.h - p.x[i]), 2);
  }
  *rms = std::sqrt(sq / static_cast<double>(p.x.size()));
}

}  // namespace

PlatesFit fit_plates(const std::vector<double>& deflection, const std::vector<double>& force, double thickness,
                     double limit) {
  if (deflection.size() != force.size()) throw std::runtime_error("gapcheck: a plates curve of unequal columns");
  Points p;
  p.h = thickness;
  for (size_t i = 0; i < deflection.size(); ++i) {
    // Before the plates touch there is no law to read; past 0.9 h the
    // densification's pole is too near for a testing machine anyway.
    if (deflection[i] > 0 && deflection[i] < 0.9 * thickness) {
      p.x.push_back(deflection[i]);
      p.f.push_back(force[i]);
    }
  }
  if (p.x.size() < 10) throw std::runtime_error("gapcheck: the plates read fewer than 10 points");
  PlatesFit out;
  double c = 0;
  fit_power(p, 1.0, &out.stiffness, &out.rms_linear);
  // The exponent: a grid over what the file takes and a golden section
  // about its best node (the misfit after C is solved is smooth in n).
  constexpr double kNode = 0.05;
  double best_n = 1, best = out.rms_linear;
  for (double n = kLowest; n <= kHighest + 1e-9; n += kNode) {
    double rms = 0;
    fit_power(p, n, &c, &rms);
    if (rms < best) {
      best = rms;
      best_n = n;
    }
  }
  double lo = std::max(kLowest, best_n - kNode), hi = std::min(kHighest, best_n + kNode);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1);
  for (int i = 0; i < 60; ++i) {
    const double a = hi - ratio * (hi - lo), b = lo + ratio * (hi - lo);
    double ra = 0, rb = 0;
    fit_power(p, a, &c, &ra);
    fit_power(p, b, &c, &rb);
    if (ra < rb) {
      hi = b;
    } else {
      lo = a;
    }
  }
  const double n = 0.5 * (lo + hi);
  fit_power(p, n, &c, &out.rms_power);
  out.rms_misfit = out.rms_linear;
  // C = K r^(1 - n) with r = limit / K, so C = limit^(1 - n) K^n.
  const double k = std::pow(c / std::pow(limit, 1 - n), 1 / n);
  const double r = limit / k;
  // An experimenter writes the power law only where it clearly fits the
  // curve better, and only one the file takes (reference up to 1 m).
  if (out.rms_power < 0.5 * out.rms_linear && std::isfinite(k) && k > 0 && r > 0 && r <= 1) {
    out.stiffness = k;
    out.exponent = n;
    out.reference = r;
    out.rms_misfit = out.rms_power;
  }
  return out;
}

}  // namespace gapcheck
