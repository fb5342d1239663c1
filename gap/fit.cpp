#include "fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

#include "terms.h"

namespace afford {
namespace {

constexpr double kMinExponent = 0.5, kMaxExponent = 4.0;  // the actee's power laws searched
// m: the references a law is written with, a deflection an actee can have
// (the file takes up to 1 m): beyond them the law is all but linear.
constexpr double kLeastReference = 1e-6, kMostReference = 1.0;
constexpr int kMaxRounds = 5;   // of the alternating search for a delay and an exponent together
constexpr int kShiftSteps = 60;  // the grid of a preload's compression shift searched with a progressive spring
// After its first round, each is searched this far either side of where it was, on a grid of kNearSteps.
constexpr double kDelayReach = 0.01;     // s
constexpr double kExponentReach = 0.25;
constexpr int kNearSteps = 6;
// A round that moves them less than this ends the search: a hundredth of a
// sample at 1 kHz, and far below what the data tells of an exponent.
constexpr double kDelaySettled = 1e-5;   // s
constexpr double kExponentSettled = 1e-3;

bool is_linear(EffectKind k) { return k != EffectKind::sensor_latency && k != EffectKind::actee_compliance; }

// The minimum of f on [lo, hi]: a grid of `steps`, then golden sections
// around the best point. Deterministic. f(x, on_grid): on_grid is true
// for the grid's points, the same in every search over [lo, hi].
template <typename F>
double minimise(F f, double lo, double hi, int steps) {
  double best = lo, best_f = std::numeric_limits<double>::max();
  const double h = (hi - lo) / steps;
  for (int i = 0; i <= steps; ++i) {
    const double x = lo + h * i;
    const double v = f(x, true);
    if (v < best_f) {
      best_f = v;
      best = x;
    }
  }
  double a = std::max(lo, best - h), b = std::min(hi, best + h);
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(c, false), fd = f(d, false);
  for (int i = 0; i < 40 && b - a > 1e-6 * (1 + std::abs(best)); ++i) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = f(c, false);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = f(d, false);
    }
  }
  const double x = 0.5 * (a + b);
  return f(x, false) <= best_f ? x : best;
}

}  // namespace

double nominal_value(const Model& m, EffectKind k, size_t param) {
  switch (k) {
    case EffectKind::pivot_friction: return m.friction_torque;
    case EffectKind::viscous_damping: return m.damping;
    case EffectKind::spring_preload: return m.spring_preload;
    case EffectKind::progressive_spring: return m.spring_cubic;
    case EffectKind::arm_inertia: return m.arm_inertia;
    case EffectKind::gravity: return m.gravity_extra;
    case EffectKind::actee_compliance: return param == 0 ? m.actee_exponent : m.actee_reference;
    case EffectKind::sensor_latency: return m.sensor_latency;
  }
  return 0;
}

bool in_physical_range(const EffectParam& p, double value, double nominal, double margin) {
  const double lower = p.keeps_sign && nominal > 0 ? std::max(p.min, 0.0) : p.min;
  const double upper = p.keeps_sign && nominal < 0 ? std::min(p.max, 0.0) : p.max;
  const bool lower_included = p.min_included || lower > p.min || margin > 0;
  return (lower_included ? value >= lower - margin : value > lower) && value <= upper + margin;
}

double aicc(double rss, size_t n, int k) {
  const double nn = static_cast<double>(n);
  const double kk = k;
  return nn * std::log(std::max(rss, 1e-300) / nn) + 2 * kk + (nn - kk - 1 > 0 ? 2 * kk * (kk + 1) / (nn - kk - 1) : 1e300);
}

Fitter::Fitter(const Model& model, const std::vector<Replay>& replays, std::vector<size_t> train,
               std::vector<size_t> test, SumsCache* cache)
    : model_(model), replays_(replays), cache_(cache), train_(std::move(train)), test_(std::move(test)) {
  if (model.has_actee) actee_ = actee_geometry(model, replays.empty() ? Rig::lever : replays.front().rig);
  const double ds = std::abs(model.spring_position);
  for (const Replay& r : replays_) {
    std::array<std::vector<double>, kEffectKinds> phi;
    std::vector<double> weight;
    if (r.rig == Rig::lever) {
      const size_t n = r.t.size();
      auto col = [&](EffectKind k) -> std::vector<double>& {
        auto& c = phi[static_cast<size_t>(k)];
        c.resize(n);
        return c;
      };
      for (size_t i = 0; i < n; ++i) {
        const double theta = r.x[i], omega = r.rate[i], alpha = r.accel[i];
        const double d = std::max(0.0, spring_compression(model, theta));
        col(EffectKind::pivot_friction)[i] = -smooth_sign(omega);
        col(EffectKind::viscous_damping)[i] = -omega;
        col(EffectKind::spring_preload)[i] = ds;
        col(EffectKind::progressive_spring)[i] = d * d * d * ds;
        col(EffectKind::arm_inertia)[i] = -alpha;
        col(EffectKind::gravity)[i] = -std::cos(theta + r.turned);  // as gravity_coefficients turns the extra
      }
      // Switching gravity on brings the arm's computed weight too.
      if (!model.gravity) {
        Model on = model;
        on.gravity = true;
        on.gravity_extra = 0;
        double c = 0, sn = 0;
        gravity_coefficients(on, model.object_start.linear(), &c, &sn, r.turned);
        weight.resize(n);
        for (size_t i = 0; i < n; ++i) weight[i] = c * std::cos(r.x[i]) + sn * std::sin(r.x[i]);
      }
    }
    phi_.push_back(std::move(phi));
    arm_weight_.push_back(std::move(weight));
    own_actee_.push_back(model.has_actee ? actee_term(model, r, actee_, model.actee_exponent, model.actee_reference)
                                         : std::vector<double>{});
    std::vector<size_t> fitted, in_contact;
    for (size_t s = 0; s < r.fitted.size(); ++s) {
      if (r.fitted[s]) fitted.push_back(s);
      if (r.fitted[s] && r.deflection[s] > 0) in_contact.push_back(s);
    }
    fitted_.push_back(std::move(fitted));
    contact_fitted_.push_back(std::move(in_contact));
  }
}

std::vector<double> Fitter::weighed_column(EffectKind k) const {
  std::vector<double> out;
  if (k == EffectKind::actee_compliance) return out;
  for (size_t i : train_) {
    const Replay& r = replays_[i];
    if (r.rig != Rig::lever) continue;
    for (size_t s : fitted_[i]) {
      double v = 0;
      if (k == EffectKind::sensor_latency) {
        const size_t a = s > 0 ? s - 1 : s, b = s + 1 < r.t.size() ? s + 1 : s;
        v = b > a ? -(r.nominal[b] - r.nominal[a]) / (r.t[b] - r.t[a]) : 0.0;
      } else {
        v = phi_[i][static_cast<size_t>(k)][s];
      }
      out.push_back(v * r.to_newtons * std::sqrt(r.weight[s]));
    }
  }
  return out;
}

std::vector<EffectKind> Fitter::candidates() const {
  std::vector<EffectKind> out;
  const bool lever = !replays_.empty() && replays_.front().rig == Rig::lever;
  bool actee_in_use = false;
  for (const Replay& r : replays_) {
    for (double d : r.deflection) actee_in_use = actee_in_use || d > 0;
  }
  for (const EffectManifest& e : effect_registry()) {
    if (e.kind == EffectKind::actee_compliance && !actee_in_use) continue;
    if (!lever && is_linear(e.kind)) continue;
    out.push_back(e.kind);
  }
  return out;
}

void Fitter::columns(size_t i, const std::vector<EffectKind>& linear, const Nonlinear& nl, std::vector<double>* base,
                     std::vector<std::vector<double>>* cols) const {
  const Replay& r = replays_[i];
  *base = r.nominal;
  cols->clear();
  for (EffectKind k : linear) {
    cols->push_back(phi_[i][static_cast<size_t>(k)]);
    if (k == EffectKind::gravity && !arm_weight_[i].empty()) {
      for (size_t j = 0; j < base->size(); ++j) (*base)[j] += arm_weight_[i][j];
    }
    if (k == EffectKind::progressive_spring && nl.compression_shift != 0) {
      // The cubic at the shifted compression; the file's own cubic moves
      // with it in the base.
      const double ds = std::abs(model_.spring_position);
      for (size_t j = 0; j < base->size(); ++j) {
        const double d = std::max(0.0, spring_compression(model_, r.x[j]));
        const double shifted = std::max(0.0, d + nl.compression_shift);
        cols->back()[j] = shifted * shifted * shifted * ds;
        (*base)[j] += model_.spring_cubic * (shifted * shifted * shifted - d * d * d) * ds;
      }
    }
  }
  // The preload that makes the shift, where it is not a column of its own
  // (Fitter::fit searches it): k times the shift, at the spring's arm.
  const bool preload_fitted = std::find(linear.begin(), linear.end(), EffectKind::spring_preload) != linear.end();
  if (nl.compression_shift != 0 && !preload_fitted) {
    const double torque = model_.spring_constant * nl.compression_shift * std::abs(model_.spring_position);
    for (double& v : *base) v += torque;
  }
  if (nl.exponent > 0) {
    const std::vector<double>& own = own_actee_[i];
    for (size_t j = 0; j < base->size(); ++j) (*base)[j] -= own[j];
    cols->push_back(actee_term(model_, r, actee_, nl.exponent, 1.0));  // k * delta^n: its coefficient is r^(1-n)
  }
  if (nl.delay != 0) {
    *base = delayed_keeping_noise(r.t, *base, nl.delay, r.step);
    for (auto& c : *cols) c = delayed_keeping_noise(r.t, c, nl.delay, r.step);
  }
  for (double& v : *base) v *= r.to_newtons;
  for (auto& c : *cols) {
    for (double& v : c) v *= r.to_newtons;
  }
}

// What the cache keeps: a replay's sums, or its share of the power law's row.
struct SumsKey {
  size_t replay = 0;
  std::vector<EffectKind> linear;
  double delay = 0, exponent = 0, shift = 0;
  int what = 0;  // 0: the linear columns' sums, 1: with the power law's column, 2: the power law's row
  bool operator<(const SumsKey& o) const {
    return std::tie(replay, linear, delay, exponent, shift, what) <
           std::tie(o.replay, o.linear, o.delay, o.exponent, o.shift, o.what);
  }
};

struct SumsCache::Entries {
  std::map<SumsKey, Fitter::Sums> sums;
};
SumsCache::SumsCache() : entries_(std::make_unique<Entries>()) {}
SumsCache::~SumsCache() = default;

Fitter::Sums Fitter::accumulate(const std::vector<size_t>& on, const std::vector<EffectKind>& linear,
                                const Nonlinear& nl, bool power_law_column, bool on_grid) const {
  const auto k = static_cast<Eigen::Index>(linear.size() + (power_law_column && nl.exponent > 0 ? 1 : 0));
  Sums out;
  out.xtx = Eigen::MatrixXd::Zero(k, k);
  out.xty = Eigen::VectorXd::Zero(k);
  out.inflation = Eigen::VectorXd::Zero(k);
  for (size_t i : on) {
    std::optional<Sums> own;
    const Sums* sums = nullptr;
    if (cache_ && on_grid) {
      const SumsKey key{i, linear, nl.delay, nl.exponent, nl.compression_shift, power_law_column ? 1 : 0};
      auto found = cache_->entries_->sums.find(key);
      if (found == cache_->entries_->sums.end()) {
        found = cache_->entries_->sums.emplace(key, replay_sums(i, linear, nl, power_law_column)).first;
      }
      sums = &found->second;
    } else {
      sums = &own.emplace(replay_sums(i, linear, nl, power_law_column));
    }
    out.xtx += sums->xtx;
    out.xty += sums->xty;
    out.inflation += sums->inflation;
    out.yty += sums->yty;
    out.weights += sums->weights;
    out.count += sums->count;
  }
  return out;
}

Fitter::Sums Fitter::replay_sums(size_t i, const std::vector<EffectKind>& linear, const Nonlinear& nl,
                                 bool power_law_column) const {
  const size_t k = linear.size() + (power_law_column && nl.exponent > 0 ? 1 : 0);
  Sums out;
  out.xtx = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  out.xty = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(k));
  // The rate and the acceleration are differentiated from a noisy angle:
  // their noise inflates their columns' sums of squares and so shrinks
  // what least squares gives their effects (damping, inertia: errors in
  // the variables). Its known variance is taken off the diagonal
  // (bias-compensated least squares).
  out.inflation = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(k));
  std::vector<double> base;
  std::vector<std::vector<double>> cols;
  std::vector<double> y, wy;  // N, the measured signal less the base at the fitted samples, and times its weight
  columns(i, linear, nl, &base, &cols);
  if (!power_law_column && nl.exponent > 0) cols.pop_back();  // its sums are added by add_power_law
  const Replay& r = replays_[i];
  const std::vector<size_t>& fitted = fitted_[i];
  const std::vector<double>& w = r.weight;
  for (size_t c = 0; c < linear.size(); ++c) {
    double& sum = out.inflation[static_cast<Eigen::Index>(c)];
    for (size_t s : fitted) {
      const double sd = linear[c] == EffectKind::arm_inertia     ? r.accel_noise[s]
                        : linear[c] == EffectKind::viscous_damping ? r.rate_noise[s]
                                                                   : 0.0;
      sum += w[s] * sd * r.to_newtons * sd * r.to_newtons;
    }
  }
  // The normal equations' sums, each added up sample after sample (and
  // then the replays', in the order asked).
  y.resize(fitted.size());
  wy.resize(fitted.size());
  for (size_t j = 0; j < fitted.size(); ++j) {
    y[j] = r.measured[fitted[j]] * r.to_newtons - base[fitted[j]];
    wy[j] = w[fitted[j]] * y[j];
  }
  for (size_t a = 0; a < k; ++a) {
    const std::vector<double>& ca = cols[a];
    for (size_t b = 0; b <= a; ++b) {
      const std::vector<double>& cb = cols[b];
      double& sum = out.xtx(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
      for (size_t s : fitted) sum += w[s] * ca[s] * cb[s];
    }
    double& sum = out.xty[static_cast<Eigen::Index>(a)];
    for (size_t j = 0; j < fitted.size(); ++j) sum += ca[fitted[j]] * wy[j];
  }
  for (size_t j = 0; j < fitted.size(); ++j) {
    out.yty += wy[j] * y[j];
    out.weights += w[fitted[j]];
  }
  out.count += fitted.size();
  return out;
}

Fitter::Sums Fitter::add_power_law(const Sums& linear_sums, const std::vector<size_t>& on,
                                   const std::vector<EffectKind>& linear, double exponent, bool on_grid) const {
  const auto k = static_cast<Eigen::Index>(linear.size());
  Sums out = linear_sums;
  out.xtx.conservativeResize(k + 1, k + 1);
  out.xtx.row(k).setZero();
  out.xtx.col(k).setZero();
  out.xty.conservativeResize(k + 1);
  out.xty[k] = 0;
  out.inflation.conservativeResize(k + 1);
  out.inflation[k] = 0;
  for (size_t i : on) {
    std::optional<Sums> own;
    const Sums* row = nullptr;
    if (cache_ && on_grid) {
      const SumsKey key{i, linear, 0.0, exponent, 0.0, 2};
      auto found = cache_->entries_->sums.find(key);
      if (found == cache_->entries_->sums.end()) {
        found = cache_->entries_->sums.emplace(key, power_law_row(i, linear, exponent)).first;
      }
      row = &found->second;
    } else {
      row = &own.emplace(power_law_row(i, linear, exponent));
    }
    out.xtx.row(k) += row->xtx.row(0);
    out.xty[k] += row->xty[0];
  }
  return out;
}

Fitter::Sums Fitter::power_law_row(size_t i, const std::vector<EffectKind>& linear, double exponent) const {
  // The power law's column is zero off the actee: its sums run over the
  // fitted samples in contact only, which adds up to the same as over all.
  const auto k = static_cast<Eigen::Index>(linear.size());
  Sums out;
  out.xtx = Eigen::MatrixXd::Zero(1, k + 1);
  out.xty = Eigen::VectorXd::Zero(1);
  const bool gravity = std::find(linear.begin(), linear.end(), EffectKind::gravity) != linear.end();
  const Replay& r = replays_[i];
  const std::vector<double> law = actee_term(model_, r, actee_, exponent, 1.0);
  const std::vector<double>& own = own_actee_[i];
  const bool weight = gravity && !arm_weight_[i].empty();
  for (size_t s : contact_fitted_[i]) {
    // As columns() makes them: the base without the actee's own law.
    double base = r.nominal[s];
    if (weight) base += arm_weight_[i][s];
    base -= own[s];
    base *= r.to_newtons;
    const double y = r.measured[s] * r.to_newtons - base, wy = r.weight[s] * y;
    const double ca = law[s] * r.to_newtons;
    for (Eigen::Index b = 0; b < k; ++b) {
      out.xtx(0, b) += r.weight[s] * ca * (phi_[i][static_cast<size_t>(linear[static_cast<size_t>(b)])][s] * r.to_newtons);
    }
    out.xtx(0, k) += r.weight[s] * ca * ca;
    out.xty[0] += ca * wy;
  }
  return out;
}

namespace {

// Column c's sum of squares less its part in the other columns' span
// (the Schur complement of the others in the normal equations' matrix).
double own_part(const Eigen::MatrixXd& xtx, Eigen::Index c) {
  const Eigen::Index k = xtx.rows();
  if (k == 1) return xtx(c, c);
  std::vector<Eigen::Index> others;
  for (Eigen::Index o = 0; o < k; ++o) {
    if (o != c) others.push_back(o);
  }
  const auto m = static_cast<Eigen::Index>(others.size());
  Eigen::MatrixXd oo(m, m);
  Eigen::VectorXd oc(m);
  // Scaled to unit diagonal, as the solve is.
  auto unit = [&](Eigen::Index a, Eigen::Index b) {
    const double norms = std::sqrt(xtx(a, a) * xtx(b, b));
    return norms > 0 ? xtx(a, b) / norms : 0.0;
  };
  for (Eigen::Index a = 0; a < m; ++a) {
    oc[a] = unit(others[static_cast<size_t>(a)], c);
    for (Eigen::Index b = 0; b < m; ++b) oo(a, b) = unit(others[static_cast<size_t>(a)], others[static_cast<size_t>(b)]);
  }
  const double spanned = oc.dot(oo.ldlt().solve(oc));
  return std::max(0.0, 1 - spanned) * xtx(c, c);
}

}  // namespace

double Fitter::solve(const Sums& sums, std::vector<double>* coef, std::vector<double>* sigma, size_t* n,
                     double* wsum) const {
  const auto k = static_cast<size_t>(sums.xty.size());
  Eigen::MatrixXd xtx = sums.xtx;
  for (Eigen::Index a = 0; a < xtx.rows(); ++a) {
    for (Eigen::Index b = 0; b < a; ++b) xtx(b, a) = xtx(a, b);
  }
  const Eigen::VectorXd& xty = sums.xty;
  const Eigen::VectorXd& inflation = sums.inflation;
  const double yty = sums.yty;
  const size_t count = sums.count;
  *n = count;
  *wsum = sums.weights;
  coef->assign(k, 0.0);
  sigma->assign(k, 0.0);
  if (k == 0) return yty;
  // Normal equations, scaled to unit diagonal so that columns of very
  // different sizes (a cubic spring, a friction sign) stay well conditioned.
  Eigen::MatrixXd compensated = xtx;
  for (Eigen::Index c = 0; c < compensated.rows(); ++c) {
    if (!(inflation[c] > 0)) continue;
    // Never more than half of the column's own part, the part the other
    // columns do not span: a column that is mostly noise stays as it is,
    // and so does one all but parallel to another, whose own part the
    // noise may exceed. Taken off the whole column, the compensation left
    // the normal equations indefinite: a damping beside a friction on
    // strokes of all but one speed was fitted as -1.5 N*m of friction and
    // 18.8 N*m*s/rad of damping (development seed 5082, a tongs in ODE).
    compensated(c, c) -= std::min(inflation[c], 0.5 * own_part(xtx, c));
  }
  Eigen::VectorXd scale = compensated.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd a = scale.asDiagonal() * compensated * scale.asDiagonal();
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(a);
  const Eigen::VectorXd z = ldlt.solve(scale.asDiagonal() * xty);
  const Eigen::VectorXd beta = scale.asDiagonal() * z;
  const double rss = std::max(0.0, yty - 2 * beta.dot(xty) + beta.dot(xtx * beta));
  const double dof = static_cast<double>(count) - static_cast<double>(k);
  const double s2 = dof > 0 ? rss / dof : 0.0;
  const Eigen::MatrixXd inv = scale.asDiagonal() * ldlt.solve(Eigen::MatrixXd::Identity(a.rows(), a.cols())) *
                              scale.asDiagonal();
  for (size_t c = 0; c < k; ++c) {
    (*coef)[c] = beta[static_cast<Eigen::Index>(c)];
    (*sigma)[c] = std::sqrt(std::max(0.0, s2 * inv(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(c))));
  }
  return rss;
}

double Fitter::rss(const std::vector<size_t>& on, const std::vector<EffectKind>& linear, const Nonlinear& nl,
                   const std::vector<double>& coef, size_t* n, double* wsum) const {
  double sum = 0, weights = 0;
  size_t count = 0;
  std::vector<double> base;
  std::vector<std::vector<double>> cols;
  for (size_t i : on) {
    columns(i, linear, nl, &base, &cols);
    const Replay& r = replays_[i];
    for (size_t s = 0; s < base.size(); ++s) {
      if (!r.fitted[s]) continue;
      double p = base[s];
      for (size_t c = 0; c < cols.size(); ++c) p += coef[c] * cols[c][s];
      const double e = r.measured[s] * r.to_newtons - p;
      sum += r.weight[s] * e * e;
      weights += r.weight[s];
      ++count;
    }
  }
  *n = count;
  *wsum = weights;
  return sum;
}

SetFit Fitter::fit(const std::vector<EffectKind>& set, const SetFit* near) const {
  std::vector<EffectKind> linear;
  bool latency = false, compliance = false;
  for (EffectKind k : set) {
    if (k == EffectKind::sensor_latency) latency = true;
    else if (k == EffectKind::actee_compliance) compliance = true;
    else linear.push_back(k);
  }
  std::vector<double> coef, sigma;
  size_t n = 0;
  double w = 0;
  // The training error for given nonlinear parameters, linear ones solved.
  // The linear columns' sums while the power law's exponent is searched
  // without a delay: they do not change with it.
  std::optional<Sums> linear_sums;
  std::vector<EffectKind> fitted_linear = linear;  // those solved for: all but a preload searched as a shift
  auto train_rss = [&](const Nonlinear& nl, bool on_grid = false) {
    if (nl.exponent > 0 && nl.delay == 0 && nl.compression_shift == 0) {
      if (!linear_sums) linear_sums = accumulate(train_, fitted_linear, nl, false);
      return solve(add_power_law(*linear_sums, train_, fitted_linear, nl.exponent, on_grid), &coef, &sigma, &n, &w);
    }
    return solve(accumulate(train_, fitted_linear, nl, true, on_grid), &coef, &sigma, &n, &w);
  };
  Nonlinear best;
  // A search's grid is the same in every fit: its points' sums are kept.
  auto best_exponent = [&](double delay) {
    return minimise([&](double e, bool grid) { return train_rss(Nonlinear{delay, e}, grid && delay == 0); },
                    kMinExponent, kMaxExponent, 35);
  };
  auto best_delay = [&](double exponent) {
    return minimise([&](double d, bool grid) { return train_rss(Nonlinear{d, exponent}, grid && exponent == 0); },
                    0.0, kLongestDelay, 50);
  };
  // Both at once: one, then the other, until neither moves (they trade
  // off: a later effort reads like a stiffer actee while it is loaded).
  // After a first search over each whole range, each is searched again
  // about where it was (a window it may move across from round to round);
  // started from `near`'s values, only about them.
  auto about = [&](double x, double lo, double hi, double reach, auto f) {
    return minimise([&](double v, bool) { return f(v); }, std::max(lo, x - reach), std::min(hi, x + reach), kNearSteps);
  };
  const bool both = latency && compliance;
  const bool started = both && near != nullptr;
  if (started) {
    best = Nonlinear{near->delay, near->exponent};
  } else if (compliance) {
    best.exponent = best_exponent(0.0);
  }
  for (int round = 0; round < (both ? kMaxRounds : 1); ++round) {
    const Nonlinear was = best;
    if (round == 0 && !started) {
      if (latency) best.delay = best_delay(best.exponent);
      if (both) best.exponent = best_exponent(best.delay);
    } else {
      best.delay = about(best.delay, 0.0, kLongestDelay, kDelayReach,
                         [&](double d) { return train_rss(Nonlinear{d, best.exponent}); });
      best.exponent = about(best.exponent, kMinExponent, kMaxExponent, kExponentReach,
                            [&](double e) { return train_rss(Nonlinear{best.delay, e}); });
    }
    if (std::abs(best.delay - was.delay) < kDelaySettled && std::abs(best.exponent - was.exponent) < kExponentSettled) break;
  }
  // A preload and a progressive spring together: the cubic acts on the
  // whole compression (terms.cpp), so a change of preload dp shifts the
  // cubic's column by dp / k. Fitted as a search over that shift, the
  // preload's change k times it (in the base, columns()), about where the
  // fit taken at the nominal compression puts it; its standard error
  // from the curvature, as a delay's.
  const auto preload_at = std::find(linear.begin(), linear.end(), EffectKind::spring_preload);
  const bool shifts = preload_at != linear.end() && model_.spring_constant > 0 &&
                      std::find(linear.begin(), linear.end(), EffectKind::progressive_spring) != linear.end();
  const auto at = static_cast<size_t>(preload_at - linear.begin());
  if (shifts) {
    train_rss(best);
    const double unshifted = coef[at] / model_.spring_constant;  // m
    double deepest = 0;  // m, the most the spring is compressed in the fitted samples
    for (size_t i : train_) {
      for (size_t s : fitted_[i]) deepest = std::max(deepest, spring_compression(model_, replays_[i].x[s]));
    }
    const double reach = 2 * (std::abs(unshifted) + deepest);
    fitted_linear.erase(fitted_linear.begin() + static_cast<std::ptrdiff_t>(at));
    linear_sums.reset();  // they held the preload's column
    best.compression_shift = minimise(
        [&](double x, bool) { return train_rss(Nonlinear{best.delay, best.exponent, x}); }, unshifted - reach,
        unshifted + reach, kShiftSteps);
  }
  const double rss_train = train_rss(best);
  std::vector<double> best_coef = coef, best_sigma = sigma;
  if (shifts) {
    // The shift's standard error from the curvature about it (as
    // curvature_sigma below, on either side: a shift may be negative).
    const double h = 1e-6;  // m
    const size_t dof = n > best_coef.size() + 1 ? n - best_coef.size() - 1 : 0;
    const double s2 = dof > 0 ? rss_train / static_cast<double>(dof) : 0.0;
    auto at_shift = [&](double v) { return train_rss(Nonlinear{best.delay, best.exponent, v}); };
    const double x = best.compression_shift;
    const double second = (at_shift(x + h) - 2 * rss_train + at_shift(x - h)) / (h * h);
    const double shift_sigma = second > 0 ? std::sqrt(2 * s2 / second) : std::numeric_limits<double>::infinity();
    const auto where = static_cast<std::ptrdiff_t>(at);
    best_coef.insert(best_coef.begin() + where, model_.spring_constant * x);
    best_sigma.insert(best_sigma.begin() + where, model_.spring_constant * shift_sigma);
  }

  SetFit out;
  out.linear = linear;
  out.coef = best_coef;
  out.delay = best.delay;
  out.exponent = best.exponent;
  out.compression_shift = best.compression_shift;
  out.rss_train = rss_train;
  out.n_train = n;
  out.parameters = static_cast<int>(best_coef.size()) + (latency ? 1 : 0) + (compliance ? 1 : 0);
  out.aicc = aicc(rss_train, n, out.parameters);
  out.w_train = w;
  out.rmse_train = w > 0 ? std::sqrt(rss_train / w) : 0.0;
  size_t n_test = 0;
  double w_test = 0;
  const double rss_test = rss(test_, linear, best, best_coef, &n_test, &w_test);
  out.rmse_test = w_test > 0 ? std::sqrt(rss_test / w_test) : 0.0;
  out.n_test = n_test;
  out.w_test = w_test;

  const double s2 = n > static_cast<size_t>(out.parameters) ? rss_train / static_cast<double>(n - out.parameters) : 0;
  // A nonlinear parameter's standard error from the curvature of the
  // training error about its optimum: var = 2 s^2 / (d^2 rss / dp^2).
  auto curvature_sigma = [&](auto with, double x, double h) {
    const double f0 = train_rss(with(x)), fp = train_rss(with(x + h)), fm = train_rss(with(std::max(0.0, x - h)));
    const double second = (fp - 2 * f0 + fm) / (h * h);
    return second > 0 ? std::sqrt(2 * s2 / second) : std::numeric_limits<double>::infinity();
  };
  for (size_t c = 0; c < linear.size(); ++c) {
    EffectFit e;
    e.kind = linear[c];
    const double nominal = nominal_value(model_, linear[c]);
    e.value[0] = nominal + best_coef[c];
    e.sigma[0] = best_sigma[c];
    out.effects.push_back(e);
    if (!in_physical_range(manifest_of(e.kind).params[0], e.value[0], nominal)) out.valid = false;
  }
  if (compliance) {
    EffectFit e;
    e.kind = EffectKind::actee_compliance;
    const double c = best_coef.back();  // = reference^(1 - n)
    e.value[0] = best.exponent;
    e.sigma[0] = curvature_sigma([&](double x) { return Nonlinear{best.delay, x, best.compression_shift}; },
                                 best.exponent, 0.01);
    if (!(c > 0)) out.valid = false;
    // The law is c * stiffness * deflection^n. Its reference holds c only
    // where n is off 1: a law all but linear that is softer or stiffer than
    // the file's would need one far beyond the actee (5 m for 7 % softer
    // at n = 1.045; MuJoCo's jaws on a nut, development seeds 3067, 3202,
    // 3281) or far below any deflection (1e-241 m for 20 % softer at
    // n = 0.9996), and a linear one none at all. Then the law is written
    // at the nominal's reference (1 mm for a linear nominal), the actee's
    // stiffness scaled to keep c.
    const bool linear_law = std::abs(best.exponent - 1) < 1e-6;
    const double own_reference = linear_law || !(c > 0) ? 0.0 : std::pow(c, 1 / (1 - best.exponent));  // m
    if (own_reference >= kLeastReference && own_reference <= kMostReference) {
      e.value[1] = own_reference;
      e.sigma[1] = own_reference * std::abs(best_sigma.back() / c / (1 - best.exponent));
    } else {
      const double written_at = model_.actee_reference > 0 ? model_.actee_reference : 1e-3;  // m
      e.value[1] = written_at;
      e.sigma[1] = 0;
      if (c > 0) {
        e.stiffness_factor = c * std::pow(written_at, best.exponent - 1);
        e.stiffness_factor_sigma = best_sigma.back() * std::pow(written_at, best.exponent - 1);
      }
    }
    out.effects.push_back(e);
  }
  if (latency) {
    EffectFit e;
    e.kind = EffectKind::sensor_latency;
    e.value[0] = best.delay;
    e.sigma[0] = curvature_sigma([&](double x) { return Nonlinear{x, best.exponent, best.compression_shift}; },
                                 best.delay, 5e-4);
    out.effects.push_back(e);
  }
  return out;
}

double Fitter::scaled_actee_rss(size_t i, double exponent, double* factor, double* wsum,
                                std::vector<double>* residual, double zero_m) const {
  const Replay& r = replays_[i];
  const std::vector<double>& own = own_actee_[i];
  const std::vector<double> law =
      exponent > 0   ? actee_term(model_, r, actee_, exponent, 1.0, zero_m)
      : zero_m > 0 ? actee_term(model_, r, actee_, model_.actee_exponent, model_.actee_reference, zero_m)
                   : own;
  // y = the measurement less everything but the actee's law; one column.
  auto y_at = [&](size_t s) { return (r.measured[s] - (r.nominal[s] - own[s])) * r.to_newtons; };
  double cc = 0, cy = 0, yy = 0, w = 0;
  for (size_t s : fitted_[i]) {
    const double c = law[s] * r.to_newtons, y = y_at(s);
    cc += r.weight[s] * c * c;
    cy += r.weight[s] * c * y;
    yy += r.weight[s] * y * y;
    w += r.weight[s];
  }
  const double f = cc > 0 ? cy / cc : 0.0;
  *factor = f;
  *wsum = w;
  if (residual) {
    residual->assign(r.t.size(), 0.0);
    for (size_t s : fitted_[i]) (*residual)[s] = y_at(s) - f * law[s] * r.to_newtons;
  }
  return std::max(0.0, yy - f * cy);
}

double Fitter::own_zero(size_t i, double exponent) const {
  double most = 0;  // m, the largest deflection fitted
  for (size_t s : fitted_[i]) most = std::max(most, replays_[i].deflection[s]);
  double f = 0, w = 0;
  return minimise([&](double z, bool) { return scaled_actee_rss(i, exponent, &f, &w, nullptr, z); }, 0.0, most / 2, 30);
}

double Fitter::shared_exponent(const std::vector<size_t>& on, bool own_zeros) const {
  return minimise(
      [&](double e, bool) {
        double sum = 0, f = 0, w = 0;
        for (size_t i : on) sum += scaled_actee_rss(i, e, &f, &w, nullptr, own_zeros ? own_zero(i, e) : 0.0);
        return sum;
      },
      kMinExponent, kMaxExponent, 35);
}

std::vector<double> Fitter::residual(const SetFit& fit, size_t i, bool every_sample) const {
  std::vector<double> base;
  std::vector<std::vector<double>> cols;
  columns(i, fit.linear, Nonlinear{fit.delay, fit.exponent, fit.compression_shift}, &base, &cols);
  const Replay& r = replays_[i];
  std::vector<double> out(base.size(), 0.0);
  for (size_t s = 0; s < base.size(); ++s) {
    if (!r.fitted[s] && !every_sample) continue;
    double p = base[s];
    for (size_t c = 0; c < cols.size(); ++c) p += fit.coef[c] * cols[c][s];
    out[s] = r.measured[s] * r.to_newtons - p;
  }
  return out;
}

}  // namespace afford
