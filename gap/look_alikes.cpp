#include "look_alikes.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "report.h"

namespace afford {
namespace {

// Columns this close to parallel leave the data nothing to choose by: the
// other's best fit misses by under 1 - 0.995^2, a hundredth, of the
// chosen effect's own share. Worked out on a 1 Hz sine from 8 to 28 deg,
// the samples below a fifth of its top speed left out: gravity against a
// preload one way up 0.9993; friction against damping 0.947.
constexpr double kLookAlike = 0.995;

// What tells two effects apart, as an experimenter would measure it.
std::string separating(EffectKind a, EffectKind b) {
  auto is = [&](EffectKind x, EffectKind y) { return (a == x && b == y) || (a == y && b == x); };
  if (is(EffectKind::pivot_friction, EffectKind::spring_preload) || is(EffectKind::pivot_friction, EffectKind::gravity)) {
    return "open and close (friction turns with the motion; a preload or a weight does not)";
  }
  if (is(EffectKind::gravity, EffectKind::spring_preload)) {
    return "turn the tool (its weight turns with it; a preload does not)";
  }
  if (is(EffectKind::viscous_damping, EffectKind::sensor_latency)) {
    return "a drive where the effort changes other than with the speed (a second speed with an arm whose inertia "
           "shows, or the slope of an actee's contact): with a linear spring alone a late sensor reads as damping "
           "of the other sign";
  }
  if (is(EffectKind::arm_inertia, EffectKind::sensor_latency)) return "a second speed or a drive with other corners";
  return "a drive that moves them differently (other angles, speeds or orientations)";
}

// `v` with the span of `basis`'s columns taken out (least squares).
Eigen::VectorXd without(const Eigen::VectorXd& v, const Eigen::MatrixXd& basis) {
  if (basis.cols() == 0) return v;
  return v - basis * basis.colPivHouseholderQr().solve(v);
}

}  // namespace

std::vector<LookAlike> look_alikes(const Fitter& fitter, const std::vector<EffectKind>& chosen,
                                   const std::vector<EffectKind>& library) {
  std::vector<LookAlike> out;
  // Each effect's column once: every sample of every training replay.
  std::array<Eigen::VectorXd, kEffectKinds> columns;
  std::array<bool, kEffectKinds> made{};
  auto column = [&](EffectKind k) -> const Eigen::VectorXd& {
    const auto i = static_cast<size_t>(k);
    if (!made[i]) {
      const std::vector<double> c = fitter.weighed_column(k);
      columns[i] = Eigen::Map<const Eigen::VectorXd>(c.data(), static_cast<long>(c.size()));
      made[i] = true;
    }
    return columns[i];
  };
  for (EffectKind k : chosen) {
    const Eigen::VectorXd& own = column(k);
    if (own.size() == 0) continue;
    Eigen::MatrixXd others(own.size(), 0);
    for (EffectKind o : chosen) {
      if (o == k) continue;
      const Eigen::VectorXd& c = column(o);
      if (c.size() != own.size()) continue;
      others.conservativeResize(Eigen::NoChange, others.cols() + 1);
      others.col(others.cols() - 1) = c;
    }
    const Eigen::VectorXd a = without(own, others);
    for (EffectKind j : library) {
      if (std::find(chosen.begin(), chosen.end(), j) != chosen.end()) continue;
      const Eigen::VectorXd& c = column(j);
      if (c.size() != own.size()) continue;
      const Eigen::VectorXd b = without(c, others);
      const double norms = a.norm() * b.norm();
      const double cosine = norms > 0 ? std::abs(a.dot(b)) / norms : 0.0;
      if (cosine >= kLookAlike) out.push_back({k, j, cosine, separating(k, j), "", ""});
    }
  }
  return out;
}

bool adds_nothing_to(const Fitter& fitter, EffectKind k, const std::vector<EffectKind>& others) {
  const std::vector<double> own = fitter.weighed_column(k);
  if (own.empty() || others.empty()) return false;
  const Eigen::Map<const Eigen::VectorXd> a(own.data(), static_cast<long>(own.size()));
  Eigen::MatrixXd basis(a.size(), 0);
  for (EffectKind o : others) {
    const std::vector<double> c = fitter.weighed_column(o);
    if (c.size() != own.size()) continue;
    basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
    basis.col(basis.cols() - 1) = Eigen::Map<const Eigen::VectorXd>(c.data(), static_cast<long>(c.size()));
  }
  const double norm = a.norm();
  if (basis.cols() == 0 || !(norm > 0)) return false;
  // The cosine between the column and its part in the others' span.
  const double off = without(a, basis).norm() / norm;
  return std::sqrt(std::max(0.0, 1 - off * off)) >= kLookAlike;
}

Standing standing_in(LookAlike& l, const SetFit& swapped, const Model& nominal, double sigmas) {
  Standing out;
  bool clear = false;  // the look-alike's change lies clear of zero
  double change = 0, file = 0;  // SI
  for (const EffectFit& e : swapped.effects) {
    const EffectParam& p = manifest_of(e.kind).params[0];
    const ParameterChange c = parameter_change(e, 0, nominal);
    if (e.kind == l.alike) {
      clear = std::abs(c.change) > sigmas * e.sigma[0];
      change = c.change;
      file = c.nominal;
    }
    if (l.out_of_range.empty() && !in_physical_range(p, c.total, c.nominal, sigmas * e.sigma[0])) {
      l.out_of_range = std::string(manifest_of(e.kind).name) + " would need " + p.key + " " + si_quantity(c.total, p) +
                       (c.has_nominal ? " against the file's " + si_quantity(c.nominal, p) : std::string()) +
                       ", outside its physical range" +
                       (p.keeps_sign && c.total * c.nominal < 0 ? " (a measured tool's keeps the file's sign)" : "");
    }
  }
  const EffectParam& p = manifest_of(l.alike).params[0];
  if (l.out_of_range.empty() && !clear) {
    l.out_of_range = std::string(manifest_of(l.alike).name) + " would need " + p.key + " beyond its file's " +
                     si_quantity(file, p) + ", where its physical range ends";
  }
  out.alone = l.out_of_range.empty();
  // Room: a thousandth of its change (any small share) stays in range.
  out.beside = out.alone || (clear && in_physical_range(p, file + 1e-3 * change, file));
  return out;
}

std::string look_alike_text(const LookAlike& l, bool both) {
  char head[160];
  if (!l.told_apart.empty()) {
    std::snprintf(head, sizeof head, "the held-out samples tell %s from %s (cosine %.4f; ", manifest_of(l.chosen).name,
                  manifest_of(l.alike).name, l.cosine);
    return head + l.told_apart + ")" +
           (both ? std::string(", not from both; to tell them apart: ") + l.separate : std::string());
  }
  std::snprintf(head, sizeof head, "the data cannot tell %s from %s%s (cosine %.4f)", manifest_of(l.chosen).name,
                manifest_of(l.alike).name, both ? ", nor from both" : "", l.cosine);
  if (l.out_of_range.empty()) return head + std::string("; to tell them apart: ") + l.separate;
  return head + std::string(", but ") + l.out_of_range +
         (both ? std::string("; a share of it beside ") + manifest_of(l.chosen).name + " may be: " + l.separate
               : std::string());
}

}  // namespace afford
