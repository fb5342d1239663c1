#include "turn_impulse.h"

#include <algorithm>
#include <cmath>

#include "derivatives.h"

namespace afford {
namespace {

constexpr size_t kLeastTurns = 3;
constexpr double kLongestTurn = 1.0;  // s: a stretch between resolved speeds longer than this is no turn

// A sample a turn may cross: free of the actee, short of a limit and the
// break. Unfitted otherwise (a reversal, a rest, motion not resolved).
bool crossable(const Replay& r, size_t s) {
  return !(r.deflection[s] > 0) && r.phase[s] != Phase::at_limit && r.phase[s] != Phase::after_break &&
         s >= r.history;
}

}  // namespace

TurnImpulse turn_impulse(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& left_over) {
  TurnImpulse out;
  double sxx = 0, sxy = 0, syy = 0;  // (rad/s^2)^2, rad/s^2 * N*m, (N*m)^2
  for (size_t i = 0; i < replays.size(); ++i) {
    const Replay& r = replays[i];
    if (r.rig != Rig::lever) continue;
    const size_t n = r.t.size();
    const double gap = kRecordedApart * r.step;
    size_t s = 0;
    while (s < n) {
      if (r.phase[s] != Phase::reversal) {
        ++s;
        continue;
      }
      // The turn runs from the last fitted sample before the reversal to
      // the first after it, over samples it may cross, with no time gap.
      size_t a = s, b = s;
      bool whole = crossable(r, s);
      while (whole && a > 0 && !r.fitted[a]) {
        whole = crossable(r, a - 1) && r.t[a] - r.t[a - 1] <= gap;
        --a;
      }
      while (whole && b + 1 < n && !r.fitted[b]) {
        whole = crossable(r, b + 1) && r.t[b + 1] - r.t[b] <= gap;
        ++b;
      }
      s = b + 1;
      if (!whole || !r.fitted[a] || !r.fitted[b] || r.t[b] - r.t[a] > kLongestTurn) continue;
      double mean = 0;  // N*m
      for (size_t k = a; k <= b; ++k) mean += left_over[i][k];
      mean /= static_cast<double>(b - a + 1);
      const double change = (r.rate[b] - r.rate[a]) / (r.t[b] - r.t[a]);  // rad/s^2, the mean acceleration
      sxx += change * change;
      sxy += change * mean;
      syy += mean * mean;
      ++out.turns;
    }
  }
  if (out.turns < kLeastTurns || !(sxx > 0)) return out;
  // The model's torque lacks -inertia * acceleration (fit.cpp's column).
  out.inertia = -sxy / sxx;
  const double scatter = std::max(0.0, syy - sxy * sxy / sxx) / static_cast<double>(out.turns - 1);  // (N*m)^2
  out.sigma = std::sqrt(scatter / sxx);
  return out;
}

}  // namespace afford
