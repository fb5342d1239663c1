#include "judge.h"

#include <cmath>
#include <numeric>

namespace afford {
namespace {

// The motion's noise that a fitted set passes into its prediction, at each
// sample of each replay (N times the root of the sample's weight, as the
// residuals are weighed; 0 where either replay is not fitted): the model
// predicts from the measured angle, its rate and its acceleration, and
// differentiating twice makes an arm's inertia pass the angle's noise on
// many times over. The two predictions, from the motion as measured and
// with as much noise again, differ by the noise's share.
std::vector<std::vector<double>> noise_between(const Fitter& measured, const Fitter& noisier,
                                               const std::vector<Replay>& a, const std::vector<Replay>& b,
                                               const SetFit& set) {
  std::vector<std::vector<double>> out;
  for (size_t i = 0; i < a.size(); ++i) {
    const std::vector<double> ea = measured.residual(set, i), eb = noisier.residual(set, i);
    out.emplace_back(ea.size(), 0.0);
    for (size_t s = 0; s < ea.size(); ++s) {
      if (a[i].fitted[s] && b[i].fitted[s]) out.back()[s] = (ea[s] - eb[s]) * std::sqrt(a[i].weight[s]);
    }
  }
  return out;
}

}  // namespace

std::vector<std::vector<double>> Judge::noise_through(const SetFit& f) const {
  return noise_between(data_.every, data_.noisier_every, data_.replays, data_.noisier, f);
}

double Judge::floor_of(const SetFit& f) const {
  // The motion's noise through the prediction: its RMS (N) over the
  // samples both replays fit, weighed as the fits weigh them.
  const std::vector<Replay>& a = data_.replays;
  const std::vector<Replay>& b = data_.noisier;
  const std::vector<std::vector<double>> noise = noise_through(f);
  double sq = 0, weights = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    for (size_t s = 0; s < noise[i].size(); ++s) {
      if (!a[i].fitted[s] || !b[i].fitted[s]) continue;
      sq += noise[i][s] * noise[i][s];
      weights += a[i].weight[s];
    }
  }
  return std::hypot(data_.noise, weights > 0 ? std::sqrt(sq / weights) : 0.0);
}

bool Judge::within(const Scored& f, double factor) const {
  const double floor = factor * floor_of(f.fit);
  return f.fit.rmse_test <= floor && f.rmse_contact <= floor;
}

std::vector<std::vector<double>> Judge::weighed_residual(const SetFit& f) const {
  std::vector<std::vector<double>> out;
  for (size_t i = 0; i < data_.replays.size(); ++i) {
    out.push_back(data_.every.residual(f, i));
    for (size_t s = 0; s < data_.replays[i].t.size(); ++s) out.back()[s] *= std::sqrt(data_.replays[i].weight[s]);
  }
  return out;
}

const ResidualTest& Judge::whiteness_of(const Scored& f) const {
  if (!f.residual_test) {
    const std::vector<std::vector<double>> noise = noise_through(f.fit);
    std::vector<size_t> all(data_.replays.size());
    std::iota(all.begin(), all.end(), size_t{0});
    f.residual_test = whiteness(data_.replays, weighed_residual(f.fit), all, &noise);
  }
  return *f.residual_test;
}

std::vector<double> Judge::beyond_own_noise(const Scored& f) const {
  const std::vector<std::vector<double>> noise = noise_through(f.fit);
  std::vector<double> out = f.sq;
  size_t j = 0;
  for (size_t k = 0; k < data_.folds.size(); ++k) {
    for (size_t i : data_.judged[k]) {
      for (size_t s = 0; s < data_.replays[i].t.size(); ++s) {
        if (data_.replays[i].fitted[s]) out[j++] -= noise[i][s] * noise[i][s];
      }
    }
  }
  return out;
}

std::vector<double> Judge::in_contact_only(const std::vector<double>& sq) const {
  std::vector<double> out;
  for (size_t j = 0; j < sq.size(); ++j) {
    if (data_.judged_in_contact[j]) out.push_back(sq[j]);
  }
  return out;
}

const Scored& Judge::score(const std::vector<EffectKind>& set) {
  auto found = sets_.find(set);
  if (found == sets_.end()) found = sets_.emplace(set, score_anew(set, fitted(set))).first;
  return found->second;
}

const SetFit& Judge::fitted(const std::vector<EffectKind>& set) {
  auto found = fits_.find(set);
  if (found == fits_.end()) found = fits_.emplace(set, data_.every.fit(set)).first;
  return found->second;
}

Scored Judge::score_anew(const std::vector<EffectKind>& set, const SetFit& whole) const {
  Scored out{whole, {}, 0.0, std::nullopt};
  SetFit& f = out.fit;
  double sq = 0, weights = 0;
  size_t n = 0;
  for (size_t k = 0; k < data_.folds.size(); ++k) {
    const SetFit g = data_.folds[k].fit(set, &f);
    f.valid = f.valid && g.valid;
    sq += g.rmse_test * g.rmse_test * g.w_test;
    weights += g.w_test;
    n += g.n_test;
    for (size_t i : data_.judged[k]) {
      const std::vector<double> e = data_.folds[k].residual(g, i);
      for (size_t s = 0; s < e.size(); ++s) {
        if (data_.replays[i].fitted[s]) out.sq.push_back(data_.replays[i].weight[s] * e[s] * e[s]);
      }
    }
  }
  f.rmse_test = weights > 0 ? std::sqrt(sq / weights) : 0.0;
  f.n_test = n;
  f.w_test = weights;
  double sq_contact = 0;
  for (size_t j = 0; j < out.sq.size(); ++j) sq_contact += data_.judged_in_contact[j] ? out.sq[j] : 0.0;
  out.rmse_contact =
      data_.contact_samples > 0 ? std::sqrt(sq_contact / static_cast<double>(data_.contact_samples)) : 0.0;
  return out;
}

}  // namespace afford
