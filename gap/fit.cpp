#include "fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "terms.h"

namespace afford {
namespace {

constexpr double kMaxDelay = 0.1;                // s, the longest sensor delay searched
constexpr double kMinExponent = 0.5, kMaxExponent = 4.0;  // the actee's power laws searched

bool is_linear(EffectKind k) { return k != EffectKind::sensor_latency && k != EffectKind::actee_compliance; }

std::vector<double> delayed(const std::vector<double>& t, const std::vector<double>& y, double delay) {
  if (delay == 0) return y;
  std::vector<double> out(y.size());
  for (size_t i = 0; i < y.size(); ++i) out[i] = value_at(t, y, t[i] - delay);
  return out;
}

// The minimum of f on [lo, hi]: a grid of `steps`, then golden sections
// around the best point. Deterministic.
template <typename F>
double minimise(F f, double lo, double hi, int steps) {
  double best = lo, best_f = std::numeric_limits<double>::max();
  const double h = (hi - lo) / steps;
  for (int i = 0; i <= steps; ++i) {
    const double x = lo + h * i;
    const double v = f(x);
    if (v < best_f) {
      best_f = v;
      best = x;
    }
  }
  double a = std::max(lo, best - h), b = std::min(hi, best + h);
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < 40 && b - a > 1e-9 * (1 + std::abs(best)); ++i) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = f(d);
    }
  }
  const double x = 0.5 * (a + b);
  return f(x) <= best_f ? x : best;
}

// The effect's current value in the nominal model (what a fitted change adds to).
double nominal_value(const Model& m, EffectKind k) {
  switch (k) {
    case EffectKind::pivot_friction: return m.friction_torque;
    case EffectKind::viscous_damping: return m.damping;
    case EffectKind::spring_preload: return m.spring_preload;
    case EffectKind::progressive_spring: return m.spring_cubic;
    case EffectKind::arm_inertia: return m.arm_inertia;
    case EffectKind::gravity: return m.gravity_extra;
    default: return 0;
  }
}

}  // namespace

double aicc(double rss, size_t n, int k) {
  const double nn = static_cast<double>(n);
  const double kk = k;
  return nn * std::log(std::max(rss, 1e-300) / nn) + 2 * kk + (nn - kk - 1 > 0 ? 2 * kk * (kk + 1) / (nn - kk - 1) : 1e300);
}

Fitter::Fitter(const Model& model, const std::vector<Replay>& replays, std::vector<size_t> train,
               std::vector<size_t> test)
    : model_(model), replays_(replays), train_(std::move(train)), test_(std::move(test)) {
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
    weight_.push_back(std::move(weight));
  }
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
    if (k == EffectKind::gravity && !weight_[i].empty()) {
      for (size_t j = 0; j < base->size(); ++j) (*base)[j] += weight_[i][j];
    }
  }
  if (nl.exponent > 0) {
    const std::vector<double> own = actee_term(model_, r, actee_, model_.actee_exponent, model_.actee_reference);
    for (size_t j = 0; j < base->size(); ++j) (*base)[j] -= own[j];
    cols->push_back(actee_term(model_, r, actee_, nl.exponent, 1.0));  // k * delta^n: its coefficient is r^(1-n)
  }
  *base = delayed(r.t, *base, nl.delay);
  for (auto& c : *cols) c = delayed(r.t, c, nl.delay);
  for (double& v : *base) v *= r.to_newtons;
  for (auto& c : *cols) {
    for (double& v : c) v *= r.to_newtons;
  }
}

double Fitter::solve(const std::vector<size_t>& on, const std::vector<EffectKind>& linear, const Nonlinear& nl,
                     std::vector<double>* coef, std::vector<double>* sigma, size_t* n) const {
  const size_t k = linear.size() + (nl.exponent > 0 ? 1 : 0);
  Eigen::MatrixXd xtx = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  Eigen::VectorXd xty = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(k));
  double yty = 0;
  size_t count = 0;
  std::vector<double> base;
  std::vector<std::vector<double>> cols;
  Eigen::VectorXd row(static_cast<Eigen::Index>(k));
  // The rate and the acceleration are differentiated from a noisy angle:
  // their noise inflates their columns' sums of squares and so shrinks
  // what least squares gives their effects (damping, inertia: errors in
  // the variables). Its known variance is taken off the diagonal
  // (bias-compensated least squares).
  Eigen::VectorXd inflation = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(k));
  for (size_t i : on) {
    columns(i, linear, nl, &base, &cols);
    const Replay& r = replays_[i];
    Eigen::VectorXd per_sample = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(k));
    for (size_t c = 0; c < linear.size(); ++c) {
      const double sd = linear[c] == EffectKind::arm_inertia     ? r.accel_noise
                        : linear[c] == EffectKind::viscous_damping ? r.rate_noise
                                                                   : 0.0;
      per_sample[static_cast<Eigen::Index>(c)] = sd * r.to_newtons * sd * r.to_newtons;
    }
    for (size_t s = 0; s < base.size(); ++s) {
      if (!r.fitted[s]) continue;
      inflation += per_sample;
      const double y = r.measured[s] * r.to_newtons - base[s];
      for (size_t c = 0; c < k; ++c) row[static_cast<Eigen::Index>(c)] = cols[c][s];
      xtx.noalias() += row * row.transpose();
      xty += row * y;
      yty += y * y;
      ++count;
    }
  }
  *n = count;
  coef->assign(k, 0.0);
  sigma->assign(k, 0.0);
  if (k == 0) return yty;
  // Normal equations, scaled to unit diagonal so that columns of very
  // different sizes (a cubic spring, a friction sign) stay well conditioned.
  Eigen::MatrixXd compensated = xtx;
  for (Eigen::Index c = 0; c < compensated.rows(); ++c) {
    // Never more than half: a column that is mostly noise stays as it is.
    compensated(c, c) -= std::min(inflation[c], 0.5 * compensated(c, c));
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
                   const std::vector<double>& coef, size_t* n) const {
  double sum = 0;
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
      sum += e * e;
      ++count;
    }
  }
  *n = count;
  return sum;
}

SetFit Fitter::fit(const std::vector<EffectKind>& set) const {
  std::vector<EffectKind> linear;
  bool latency = false, compliance = false;
  for (EffectKind k : set) {
    if (k == EffectKind::sensor_latency) latency = true;
    else if (k == EffectKind::actee_compliance) compliance = true;
    else linear.push_back(k);
  }
  std::vector<double> coef, sigma;
  size_t n = 0;
  // The training error for given nonlinear parameters, linear ones solved.
  auto train_rss = [&](const Nonlinear& nl) { return solve(train_, linear, nl, &coef, &sigma, &n); };
  Nonlinear best;
  auto best_exponent = [&](double delay) {
    return minimise([&](double e) { return train_rss(Nonlinear{delay, e}); }, kMinExponent, kMaxExponent, 35);
  };
  auto best_delay = [&](double exponent) {
    return minimise([&](double d) { return train_rss(Nonlinear{d, exponent}); }, 0.0, kMaxDelay, 50);
  };
  if (compliance) best.exponent = best_exponent(0.0);
  // Both at once: a few rounds of one, then the other.
  for (int round = 0; round < (latency && compliance ? 3 : 1); ++round) {
    if (latency) best.delay = best_delay(best.exponent);
    if (compliance && latency) best.exponent = best_exponent(best.delay);
  }
  const double rss_train = train_rss(best);
  const std::vector<double> best_coef = coef, best_sigma = sigma;

  SetFit out;
  out.linear = linear;
  out.coef = best_coef;
  out.delay = best.delay;
  out.exponent = best.exponent;
  out.rss_train = rss_train;
  out.n_train = n;
  out.parameters = static_cast<int>(best_coef.size()) + (latency ? 1 : 0) + (compliance ? 1 : 0);
  out.aicc = aicc(rss_train, n, out.parameters);
  out.rmse_train = n > 0 ? std::sqrt(rss_train / static_cast<double>(n)) : 0.0;
  size_t n_test = 0;
  const double rss_test = rss(test_, linear, best, best_coef, &n_test);
  out.rmse_test = n_test > 0 ? std::sqrt(rss_test / static_cast<double>(n_test)) : 0.0;
  out.n_test = n_test;

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
    e.value[0] = nominal_value(model_, linear[c]) + best_coef[c];
    e.sigma[0] = best_sigma[c];
    out.effects.push_back(e);
    const EffectParam& p = manifest_of(e.kind).params[0];
    if (e.value[0] < p.min || (!p.min_included && e.value[0] <= p.min) || e.value[0] > p.max) out.valid = false;
  }
  if (compliance) {
    EffectFit e;
    e.kind = EffectKind::actee_compliance;
    const double c = best_coef.back();  // = reference^(1 - n)
    e.value[0] = best.exponent;
    e.sigma[0] = curvature_sigma([&](double x) { return Nonlinear{best.delay, x}; }, best.exponent, 0.01);
    if (!(c > 0)) out.valid = false;
    // A law that is linear has no reference; 1 mm stands for any.
    e.value[1] = std::abs(best.exponent - 1) < 1e-6 || !(c > 0) ? 1e-3 : std::pow(c, 1 / (1 - best.exponent));
    e.sigma[1] = std::abs(best.exponent - 1) < 1e-6 || !(c > 0)
                     ? 0.0
                     : e.value[1] * std::abs(best_sigma.back() / c / (1 - best.exponent));
    if (!(e.value[1] > 0 && e.value[1] <= 1)) out.valid = false;
    out.effects.push_back(e);
  }
  if (latency) {
    EffectFit e;
    e.kind = EffectKind::sensor_latency;
    e.value[0] = best.delay;
    e.sigma[0] = curvature_sigma([&](double x) { return Nonlinear{x, best.exponent}; }, best.delay, 5e-4);
    out.effects.push_back(e);
  }
  return out;
}

std::vector<double> Fitter::residual(const SetFit& fit, size_t i) const {
  std::vector<double> base;
  std::vector<std::vector<double>> cols;
  columns(i, fit.linear, Nonlinear{fit.delay, fit.exponent}, &base, &cols);
  const Replay& r = replays_[i];
  std::vector<double> out(base.size(), 0.0);
  for (size_t s = 0; s < base.size(); ++s) {
    if (!r.fitted[s]) continue;
    double p = base[s];
    for (size_t c = 0; c < cols.size(); ++c) p += fit.coef[c] * cols[c][s];
    out[s] = r.measured[s] * r.to_newtons - p;
  }
  return out;
}

}  // namespace afford
