#include "turn_impulse.h"

#include <algorithm>
#include <cmath>

#include "derivatives.h"

namespace afford {
namespace {

constexpr double kLongestTurn = 1.0;  // s: a stretch between resolved speeds longer than this is no turn
constexpr double kShortest = 0.005;   // s: a stretch in motion shorter than this inside a turn is left out

// A sample a turn may cross: free of the actee, short of a limit and the
// break. Unfitted otherwise (a reversal, a rest, motion not resolved).
bool crossable(const Replay& r, size_t s) {
  return !(r.deflection[s] > 0) && r.phase[s] != Phase::at_limit && r.phase[s] != Phase::after_break &&
         s >= r.history;
}

// Least-squares sums of the torque left over (N*m) on the mean
// acceleration (rad/s^2) over stretches.
struct Sums {
  double sxx = 0, sxy = 0, syy = 0;
  size_t n = 0;
  void add(double change, double mean) {
    sxx += change * change;
    sxy += change * mean;
    syy += mean * mean;
    ++n;
  }
  InertiaEstimate estimate() const {
    InertiaEstimate e;
    e.stretches = n;
    if (n < kLeastStretches || !(sxx > 0)) return e;
    // The model's torque lacks -inertia * acceleration (fit.cpp's column).
    e.inertia = -sxy / sxx;
    const double scatter = std::max(0.0, syy - sxy * sxy / sxx) / static_cast<double>(n - 1);  // (N*m)^2
    e.sigma = std::sqrt(scatter / sxx);
    return e;
  }
};

}  // namespace

bool halves_agree(const TurnImpulse& t) {
  const InertiaEstimate &a = t.slowing, &b = t.speeding;
  const double apart = std::abs(a.inertia - b.inertia);
  return a.stretches >= kLeastStretches && b.stretches >= kLeastStretches &&
         (apart <= kHalvesAgree * std::hypot(a.sigma, b.sigma) ||
          apart <= kHalvesNear * std::abs(a.inertia + b.inertia) / 2);
}

TurnImpulse turn_impulse(const std::vector<Replay>& replays, const std::vector<std::vector<double>>& left_over) {
  Sums all, slowing, speeding;
  double force_sq = 0;  // (N per kg*m^2)^2: each stretch's mean acceleration at the effort, squared, summed
  for (size_t i = 0; i < replays.size(); ++i) {
    const Replay& r = replays[i];
    if (r.rig != Rig::lever) continue;
    const size_t n = r.t.size();
    const double gap = kRecordedApart * r.step;
    // Below three times its own noise a rate's sign is the noise's: the
    // arm is still, and friction holds it at any value up to its limit.
    auto moving = [&](size_t k) { return std::abs(r.rate[k]) > 3 * r.rate_noise[k]; };
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
      // Each stretch of the turn in motion on its own: where the arm
      // stands still inside a turn (a stroke that stops, holds and goes
      // back), the model's friction follows the rate's noisy sign while
      // the real one holds whatever the hand asks: an effect-free snips'
      // strokes at 2 rad/s with holds of 0.12 s asked for 0.00066 kg*m^2
      // (development seed 7446, ODE). In motion friction slides, on the
      // side the rate says, and each stretch keeps its own momentum.
      size_t k = a;
      while (k <= b) {
        if (!moving(k)) {
          ++k;
          continue;
        }
        const size_t from = k;
        while (k + 1 <= b && moving(k + 1)) ++k;
        const size_t to = k++;
        if (r.t[to] - r.t[from] < kShortest) continue;
        double mean = 0;  // N*m
        for (size_t j = from; j <= to; ++j) mean += left_over[i][j];
        mean /= static_cast<double>(to - from + 1);
        const double change = (r.rate[to] - r.rate[from]) / (r.t[to] - r.t[from]);  // rad/s^2, the mean acceleration
        all.add(change, mean);
        force_sq += change * r.to_newtons * change * r.to_newtons;
        (std::abs(r.rate[to]) < std::abs(r.rate[from]) ? slowing : speeding).add(change, mean);
      }
    }
  }
  TurnImpulse out;
  static_cast<InertiaEstimate&>(out) = all.estimate();
  out.slowing = slowing.estimate();
  out.speeding = speeding.estimate();
  if (out.stretches >= kLeastStretches) {
    out.force = std::abs(out.inertia) * std::sqrt(force_sq / static_cast<double>(out.stretches));
  }
  return out;
}

}  // namespace afford
