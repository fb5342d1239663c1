#include "residual_tests.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace afford {
namespace {

constexpr int kLags = 20;        // Ljung-Box
constexpr int kMemory = 80;      // lags over which a coloured noise's autocovariance is summed (Bartlett)
constexpr size_t kBatches = 40;  // batch means for the paired test's standard error

// 99 % point of chi-square with k degrees of freedom (Wilson-Hilferty).
double chi2_99(int k) {
  const double a = 2.0 / (9.0 * k);
  return k * std::pow(1 - a + 2.3263 * std::sqrt(a), 3);
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ma += a[i];
    mb += b[i];
  }
  ma /= static_cast<double>(a.size());
  mb /= static_cast<double>(b.size());
  double sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

bool taken(const Replay& r, size_t s, Samples samples) {
  return r.fitted[s] && (samples == Samples::every || !(r.deflection[s] > 0));
}

// Autocovariances at lags 0 to `lags` within each trace's stretches of
// `samples`, pooled, each trace's mean removed; `n` the samples.
std::vector<double> autocovariance(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& series,
                                   const std::vector<size_t>& which, Samples samples, size_t* n, int lags) {
  std::vector<double> ck(static_cast<size_t>(lags) + 1, 0.0);
  *n = 0;
  for (size_t i : which) {
    const Replay& r = replays[i];
    const std::vector<double>& e = series[i];
    double mean = 0;
    size_t m = 0;
    for (size_t s = 0; s < e.size(); ++s) {
      if (taken(r, s, samples)) {
        mean += e[s];
        ++m;
      }
    }
    if (m == 0) continue;
    mean /= static_cast<double>(m);
    *n += m;
    for (size_t s = 0; s < e.size(); ++s) {
      if (!taken(r, s, samples)) continue;
      for (int k = 0; k <= lags && s + static_cast<size_t>(k) < e.size(); ++k) {
        if (taken(r, s + static_cast<size_t>(k), samples)) ck[static_cast<size_t>(k)] += (e[s] - mean) * (e[s + static_cast<size_t>(k)] - mean);
      }
    }
  }
  return ck;
}

}  // namespace

void what_it_follows(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& residual,
                     std::string* name, double* corr) {
  std::vector<double> e, dir, speed, accel, x;
  for (size_t i = 0; i < replays.size(); ++i) {
    const Replay& r = replays[i];
    for (size_t s = 0; s < r.t.size(); ++s) {
      if (!r.fitted[s]) continue;
      e.push_back(residual[i][s]);
      dir.push_back(r.rate[s] > 0 ? 1.0 : (r.rate[s] < 0 ? -1.0 : 0.0));
      speed.push_back(r.rate[s]);
      accel.push_back(r.accel[s]);
      x.push_back(r.x[s]);
    }
  }
  const bool lever = replays.front().rig == Rig::lever;
  const std::pair<const char*, const std::vector<double>*> signals[] = {
      {"the direction of motion", &dir}, {"the speed", &speed}, {"the acceleration", &accel},
      {lever ? "the angle" : "the displacement", &x}};
  *corr = 0;
  *name = "nothing measured";
  if (e.size() < 3) return;
  for (const auto& [n, v] : signals) {
    const double c = correlation(e, *v);
    if (std::abs(c) > std::abs(*corr)) {
      *corr = c;
      *name = n;
    }
  }
}

ResidualTest whiteness(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& residual,
                       const std::vector<size_t>& which, const std::vector<std::vector<double>>* noise,
                       Samples samples) {
  size_t n = 0, n_noise = 0;  // the noise's count is the residual's: the same samples
  const std::vector<double> ck = autocovariance(replays, residual, which, samples, &n, kMemory);
  // The angle's noise through the model is not white (the rates are
  // polynomial fits over a window): its own autocovariance, from the same
  // noise replayed again, is what noise alone would show.
  const std::vector<double> expected = noise != nullptr ? autocovariance(replays, *noise, which, samples, &n_noise, kMemory)
                                                        : std::vector<double>(kMemory + 1, 0.0);
  ResidualTest t;
  t.threshold = chi2_99(kLags);
  t.samples = n;
  const double c0 = ck[0];
  if (n <= static_cast<size_t>(kMemory) || c0 <= 0) {
    t.white = true;
    return t;
  }
  // Per sample: the residual's autocovariance, and under the hypothesis
  // that it is noise, the noise's (the sensor's white share at lag 0,
  // the motion's coloured share through the model at every lag).
  const double nn = static_cast<double>(n);
  std::vector<double> gamma(kMemory + 1), null(kMemory + 1), colour(kMemory + 1);
  for (size_t k = 0; k <= kMemory; ++k) {
    gamma[k] = ck[k] / nn;
    colour[k] = expected[k] / nn;
  }
  // The colour's shape is the model's (a polynomial's window through its
  // inertia), its size the noise's through the inertia the data has,
  // which a fit may have changed: it is scaled to the residual's own,
  // least squares over the lags. How large the residual may be is the
  // noise floor's question, not this test's.
  double cross = 0, own = 0;
  for (size_t k = 1; k <= kMemory; ++k) {
    cross += gamma[k] * colour[k];
    own += colour[k] * colour[k];
  }
  const double scale = own > 0 ? std::max(0.0, cross / own) : 0.0;
  for (size_t k = 0; k <= kMemory; ++k) {
    colour[k] *= scale;
    null[k] = k == 0 ? gamma[0] : colour[k];
  }
  // Bartlett's variance of a sample autocovariance at lag k, of a series
  // of autocovariance g: (1/N) sum over j of g(j)^2 + g(j+k) g(j-k). A
  // coloured noise's lags scatter far more than a white one's 1/N: a
  // Ljung-Box statistic of the plain autocorrelations would call it
  // structure. The estimate of the colour taken off scatters as much again.
  auto at = [](const std::vector<double>& g, long j) {
    const auto a = static_cast<size_t>(std::abs(j));
    return a < g.size() ? g[a] : 0.0;
  };
  auto bartlett = [&](const std::vector<double>& g, long k) {
    double v = 0;
    for (long j = -kMemory; j <= kMemory; ++j) v += at(g, j) * at(g, j) + at(g, j + k) * at(g, j - k);
    return v / nn;
  };
  double excess = 0;
  for (long k = 1; k <= kLags; ++k) {
    const double variance = bartlett(null, k) + (noise != nullptr ? bartlett(colour, k) : 0.0);
    const double d = gamma[static_cast<size_t>(k)] - colour[static_cast<size_t>(k)];
    if (variance > 0) t.q += d * d / variance;
    excess += d * d;
  }
  t.share = gamma[0] > 0 ? std::sqrt(excess / kLags) / gamma[0] : 0.0;  // a residual of zeros has no shape
  t.white = t.q <= t.threshold;
  return t;
}

// How many standard errors worse `b` predicts the held-out samples than
// `a` (squared errors, sample by sample, the same samples in the same
// order). Neighbouring samples' errors are correlated, so the standard
// error comes from the means of kBatches consecutive batches.
double paired_t(const std::vector<double>& a, const std::vector<double>& b) {
  const size_t n = std::min(a.size(), b.size());
  const size_t len = n / kBatches;
  if (len == 0) return 0.0;
  std::vector<double> means(kBatches, 0.0);
  for (size_t k = 0; k < kBatches; ++k) {
    for (size_t i = k * len; i < (k + 1) * len; ++i) means[k] += b[i] - a[i];
    means[k] /= static_cast<double>(len);
  }
  double mean = 0;
  for (double m : means) mean += m;
  mean /= kBatches;
  double var = 0;
  for (double m : means) var += (m - mean) * (m - mean);
  var /= kBatches - 1;
  const double se = std::sqrt(var / kBatches);
  return se > 0 ? mean / se : (mean > 0 ? std::numeric_limits<double>::infinity() : 0.0);
}

}  // namespace afford
