// Fitting candidate effects to replayed traces (PySINDy's split: a library
// of candidate terms, a fit, a score on data the fit did not see). The
// terms linear in their parameter (friction, damping, preload, progressive
// spring, inertia, gravity) are fitted by linear least squares (Eigen); the
// actee's exponent and the sensor's delay by a 1-D search around that.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "effects.h"
#include "replay.h"

namespace afford {

struct EffectFit {
  EffectKind kind = EffectKind::pivot_friction;
  std::array<double, 2> value{};  // SI, in the manifest's order (the nominal value included)
  std::array<double, 2> sigma{};  // one standard error, same units
  // actee_compliance: the actee's `stiffness` times this (1 but where the
  // law's own reference would lie outside 1 um to 1 m: fit.cpp), and its
  // standard error.
  double stiffness_factor = 1;
  double stiffness_factor_sigma = 0;
};

// Effect k's parameter `param` in the nominal model, SI: what a fitted
// change adds to.
double nominal_value(const Model& m, EffectKind k, size_t param = 0);

// Where a parameter's value may lie, the file's value `nominal` (its sign
// is the part's kind where the parameter keeps it): the range widened by
// `margin` each way (SI).
bool in_physical_range(const EffectParam& p, double value, double nominal, double margin = 0);

struct SetFit {
  std::vector<EffectFit> effects;
  double rss_train = 0;     // (N)^2, over the fitted samples of the training traces
  size_t n_train = 0;
  double w_train = 0;       // the sum of the training samples' weights (Replay::weight)
  int parameters = 0;
  double aicc = 0;          // of the training fit
  double rmse_train = 0;    // N, weighted: sqrt(sum w e^2 / sum w)
  double rmse_test = 0;     // N, weighted, on the judged traces: the score
  size_t n_test = 0;
  double w_test = 0;
  bool valid = true;        // false: a fitted value outside its physical range (a negative friction, ...)
  // What residual() needs to predict again.
  std::vector<EffectKind> linear;  // the linear effects, in coef's order
  std::vector<double> coef;        // their fitted changes, then the power law's coefficient if any
  double delay = 0;                // s
  double exponent = 0;             // 0: the actee's own law
  double compression_shift = 0;    // m, with a preload and a progressive spring fitted together (Fitter::Nonlinear)
};

// Each replay's sums of the normal equations at the delays and exponents
// of a search's grid, kept for the Fitters of one set of replays (the
// folds and the whole): each fold's grid search tries the same delays and
// exponents on the same replays, and a replay's sums do not depend on the
// others fitted with it. Only for Fitters of the same model and replays.
class SumsCache {
 public:
  SumsCache();
  ~SumsCache();
  SumsCache(const SumsCache&) = delete;
  SumsCache& operator=(const SumsCache&) = delete;

 private:
  friend class Fitter;
  struct Entries;
  std::unique_ptr<Entries> entries_;
};

class Fitter {
 public:
  // `train` and `test` index the replays; the model is the nominal one.
  // Fitters given one cache must share the model and the replays.
  Fitter(const Model& model, const std::vector<Replay>& replays, std::vector<size_t> train, std::vector<size_t> test,
         SumsCache* cache = nullptr);

  // The least-squares fit of a set of effects on the training traces, scored
  // on the test traces. The empty set is the nominal model. With `near`,
  // a fit of the same set on other traces of one measurement (a fold's,
  // given the whole's), a delay and an actee's exponent searched together
  // are searched about its values only.
  SetFit fit(const std::vector<EffectKind>& set, const SetFit* near = nullptr) const;

  // The residual (measured - predicted, N) of every sample of replay i
  // under a fit; samples outside the fit (at a limit, after a break) are 0,
  // unless `every_sample` (turn_impulse.h looks across the unfitted).
  std::vector<double> residual(const SetFit& fit, size_t i, bool every_sample = false) const;

  // The candidates that apply to this rig.
  std::vector<EffectKind> candidates() const;

  // Effect k's column over the fitted samples of the training replays, one
  // after another: its torque per unit of its parameter in N at the effort,
  // times the root of each sample's weight, as the fit weighs it. A delay
  // is linearised about the nominal (a sensor tau late reads
  // -tau d(nominal)/dt more). Empty for the actee's law, which acts only
  // in the contact and is judged there.
  std::vector<double> weighed_column(EffectKind k) const;

  // Specimens that differ in stiffness (several nuts of one kind): replay i
  // alone, its actee's law times the factor that fits that trace best. The
  // law is the actee's own when `exponent` is 0, else the power law of that
  // exponent; it starts at deflection `zero_m` (0: the trace's zero).
  // Returns the weighted RSS (N^2); the factor (of the own law, or the
  // power law's coefficient), the weights' sum and, if asked, each sample's
  // residual (N, 0 where not fitted) through the pointers.
  double scaled_actee_rss(size_t i, double exponent, double* factor, double* wsum,
                          std::vector<double>* residual = nullptr, double zero_m = 0) const;
  // Where replay i's specimen seats (m): the start of its law, between 0
  // and half its largest deflection, that fits it best with its own factor.
  double own_zero(size_t i, double exponent) const;
  // The power law's exponent that fits the replays `on` best, each with a
  // factor of its own, and with a zero of its own where `own_zeros`.
  double shared_exponent(const std::vector<size_t>& on, bool own_zeros = false) const;

 private:
  friend class SumsCache;
  struct Nonlinear {
    double delay = 0;      // s
    double exponent = 0;   // 0: the model's own actee law
    // m: how much further the spring is compressed than the nominal's, a
    // fitted preload's (its change over the spring constant): a
    // progressive spring's cubic acts on the whole compression
    // (terms.cpp), so a preload moves its column.
    double compression_shift = 0;
  };
  // Prediction columns of replay i: the nominal, and one per linear effect
  // (and the actee's power law when exponent > 0), delayed by `delay`.
  void columns(size_t i, const std::vector<EffectKind>& linear, const Nonlinear& nl, std::vector<double>* base,
               std::vector<std::vector<double>>* cols) const;
  // The weighted normal equations (each sample by Replay::weight) of a set
  // of replays, lower triangle, added up sample after sample.
  struct Sums {
    Eigen::MatrixXd xtx;
    Eigen::VectorXd xty, inflation;  // inflation: the differentiated columns' noise variance
    double yty = 0, weights = 0;
    size_t count = 0;
  };
  // For fixed nonlinear parameters; the power law's column last when
  // `power_law_column` and an exponent is given (else only the base
  // without the actee's own law). `on_grid`: the parameters are a grid
  // point of a search, whose sums the cache keeps.
  Sums accumulate(const std::vector<size_t>& on, const std::vector<EffectKind>& linear, const Nonlinear& nl,
                  bool power_law_column, bool on_grid = false) const;
  // Replay i's share of them.
  Sums replay_sums(size_t i, const std::vector<EffectKind>& linear, const Nonlinear& nl, bool power_law_column) const;
  // The same with the power law's column added to sums made without it
  // (no delay): only the samples in contact count.
  Sums add_power_law(const Sums& linear_sums, const std::vector<size_t>& on, const std::vector<EffectKind>& linear,
                     double exponent, bool on_grid = false) const;
  // Replay i's share of the power law's row (xtx's last row, xty's last
  // entry; the rest zero).
  Sums power_law_row(size_t i, const std::vector<EffectKind>& linear, double exponent) const;
  // Weighted linear least squares from the sums: the weighted RSS, with
  // the coefficients and their standard errors.
  double solve(const Sums& sums, std::vector<double>* coef, std::vector<double>* sigma, size_t* n,
               double* wsum) const;
  // The weighted sum of squared errors (N^2) of a fitted set; n samples of
  // total weight wsum.
  double rss(const std::vector<size_t>& on, const std::vector<EffectKind>& linear, const Nonlinear& nl,
             const std::vector<double>& coef, size_t* n, double* wsum) const;

  const Model& model_;
  const std::vector<Replay>& replays_;
  SumsCache* cache_ = nullptr;
  std::vector<size_t> train_, test_;
  std::vector<std::array<std::vector<double>, kEffectKinds>> phi_;  // per replay: linear regressors
  std::vector<std::vector<double>> arm_weight_;  // per replay: the arm's weight torque, if gravity is off
  std::vector<std::vector<double>> own_actee_;  // per replay: the actee's own law's torque (with an actee)
  std::vector<std::vector<size_t>> fitted_;     // per replay: the samples fitted and scored
  std::vector<std::vector<size_t>> contact_fitted_;  // per replay: those with the actee deflected
  ActeeGeometry actee_;
};

// AICc of a least-squares fit: n ln(rss/n) + 2k + 2k(k+1)/(n-k-1).
double aicc(double rss, size_t n, int k);

// An effect earns its place in a set where, among other tests, it cuts the
// training AICc by at least this much.
inline constexpr double kAiccMargin = 10;

// A held-out RMSE within this factor of the noise is the noise.
inline constexpr double kMatched = 1.15;

}  // namespace afford
