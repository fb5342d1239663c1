#include "sensor_gain.h"

#include <algorithm>
#include <cmath>

#include "residual_tests.h"

namespace afford {
namespace {

// A force sensor's gain error a look-alike may have, at most: a load
// cell's calibration is off by percents; one that reads half again or
// half as much is a wrong unit or channel, which the user sees at once.
constexpr double kMostGainError = 0.5;

// The weighted least-squares gain over replays `on`: the nominal effort
// (N) is the column, the nominal residual the target.
double gain_on(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& residual,
               const std::vector<size_t>& on) {
  double xy = 0, xx = 0;
  for (size_t i : on) {
    const Replay& r = replays[i];
    for (size_t s = 0; s < r.t.size(); ++s) {
      if (!r.fitted[s]) continue;
      const double column = r.nominal[s] * r.to_newtons;
      xy += r.weight[s] * column * residual[i][s];
      xx += r.weight[s] * column * column;
    }
  }
  return xx > 0 ? xy / xx : 0.0;
}

}  // namespace

GainFit held_out_gain(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& residual,
                      const std::vector<std::vector<size_t>>& judged) {
  GainFit out;
  std::vector<size_t> every(replays.size());
  for (size_t i = 0; i < every.size(); ++i) every[i] = i;
  out.gain = gain_on(replays, residual, every);
  for (const std::vector<size_t>& fold : judged) {
    std::vector<size_t> train;
    for (size_t i : every) {
      if (std::find(fold.begin(), fold.end(), i) == fold.end()) train.push_back(i);
    }
    const double gain = gain_on(replays, residual, train);
    for (size_t i : fold) {
      const Replay& r = replays[i];
      for (size_t s = 0; s < r.t.size(); ++s) {
        if (!r.fitted[s]) continue;
        const double e = residual[i][s] - gain * r.nominal[s] * r.to_newtons;
        out.sq.push_back(r.weight[s] * e * e);
        out.weights += r.weight[s];
      }
    }
  }
  return out;
}

GainAlike gain_alike_of(const Judge& judge, const Scored& nominal, const Scored& set, bool contact) {
  const JudgedData& data = judge.data();
  std::vector<std::vector<double>> nominal_residual;
  for (size_t i = 0; i < data.replays.size(); ++i) nominal_residual.push_back(data.every.residual(nominal.fit, i));
  const GainFit gain = held_out_gain(data.replays, nominal_residual, data.judged);
  auto alike_in = [&](bool only_contact) {
    std::vector<double> gain_sq = gain.sq, set_sq = set.sq;
    if (only_contact) {
      gain_sq = judge.in_contact_only(gain.sq);
      set_sq = judge.in_contact_only(set.sq);
    }
    double gain_sum = 0;
    for (double v : gain_sq) gain_sum += v;
    const double gain_mean = only_contact ? gain_sum / static_cast<double>(data.contact_samples)
                                          : (gain.weights > 0 ? gain_sum / gain.weights : 0.0);
    auto mean_sq = [&](const Scored& f) {
      return only_contact ? f.rmse_contact * f.rmse_contact : f.fit.rmse_test * f.fit.rmse_test;
    };
    const double was = mean_sq(nominal);
    const double cut = was - mean_sq(set);
    // A gain that leaves more than the noise's tolerance where the set
    // is within it has not explained the gap as well, however its
    // misfit gathers in a few stretches that the paired test's batches
    // cannot weigh (a preload to the noise against a gain leaving 1.55
    // times it, development seed 6172, both engines).
    if (judge.matched(set) && std::sqrt(gain_mean) > kMatched * judge.floor_of(nominal.fit)) return false;
    return cut > 0 && was - gain_mean >= kNearlyAsFar * cut && paired_t(set_sq, gain_sq) < kSeparated;
  };
  return {gain.gain, std::abs(gain.gain) <= kMostGainError && alike_in(false) && (!contact || alike_in(true))};
}

}  // namespace afford
