#include "sensor_gain.h"

#include <algorithm>

namespace afford {
namespace {

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

}  // namespace afford
