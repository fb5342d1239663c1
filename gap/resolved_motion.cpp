#include "resolved_motion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace afford {
namespace {

constexpr double kUnresolved = 2;      // a window's misfit this many times its noise's: the motion is not resolved
constexpr double kShortWindow = 0.01;  // s each side: where the narrow window cannot follow the motion
constexpr int kShortDegree = 2;

// The samples whose window the polynomial cannot follow: it leaves more
// than kUnresolved times what the noise alone would, in the angle (`d`:
// a ringing, a snap) or in the measured effort (`e`: a ringing below the
// angle's noise still moves the effort through the arm's inertia, A w^2
// times it). A noise's RMS over the narrow window's 51 samples (44
// degrees of freedom) is known to a tenth, over the plain window's 21
// (18) to a sixth. The effort is looked at less what the nominal model
// predicts from the angle alone (`effort_left`, N): a stiff actee's law
// turns the jaws' touch into a kink of the effort that the angle
// explains, which is not motion the samples miss. Its noise
// (`effort_variance`, N^2, sample by sample) is the sensor's and the
// angle's through that prediction.
// A misfit marks its window's middle; what it cannot follow lies
// somewhere in the window, and a ringing's tail decays past it: the
// whole window is left out.
std::vector<bool> misfitting(const Derivatives& d, const Derivatives& e, double x_noise,
                             const std::vector<double>& effort_variance) {
  const double allowed = kUnresolved * x_noise * d.misfit_noise_gain;
  const size_t n = d.misfit.size(), m = d.half_width;
  // The noise's variance summed up to each sample: its mean over a window.
  std::vector<double> summed(n + 1, 0.0);
  for (size_t i = 0; i < n; ++i) summed[i + 1] = summed[i] + effort_variance[i];
  std::vector<bool> out(n, false);
  for (size_t i = 0; i < n; ++i) {
    const size_t from = i >= m ? i - m : 0, to = std::min(n - 1, i + m);
    const double variance = (summed[to + 1] - summed[from]) / static_cast<double>(to + 1 - from);
    const double allowed_effort = kUnresolved * std::sqrt(variance) * e.misfit_noise_gain;
    if (d.misfit[i] <= allowed && e.misfit[i] <= allowed_effort) continue;
    for (size_t j = from; j <= to; ++j) out[j] = true;
  }
  return out;
}

// The samples whose window (`m` samples each side) reaches across the
// break (a kink no polynomial follows), and the free samples whose window
// reaches into the actee's contact. Those are left out alone: as the jaws
// touch or leave it the force on the arm changes at once, a hand that
// drives the arm answers with a jolt, and the window smears that jolt's
// acceleration over the free samples beside it. Its misfit is diluted
// among the window's and hidden in the contact's noise (the actee's
// stiffness passes the angle's noise on). A press leaving its actee left
// 10 times the noise in the free samples within 25 ms of it, 0.03 N
// elsewhere (development seeds 6159 and 6471, ODE).
std::vector<bool> beside_contact_or_break(const Replay& r, size_t m, size_t break_at) {
  const size_t n = r.t.size();
  // Contact samples counted up to each sample: whether a window holds any.
  std::vector<size_t> touching(n + 1, 0);
  for (size_t i = 0; i < n; ++i) touching[i + 1] = touching[i] + (r.deflection[i] > 0 ? 1 : 0);
  std::vector<bool> out(n, false);
  for (size_t i = 0; i < n; ++i) {
    const size_t from = i >= m ? i - m : 0, to = std::min(n - 1, i + m);
    if (r.deflection[i] <= 0 && touching[to + 1] > touching[from]) out[i] = true;
    const bool across_break = break_at != SIZE_MAX && i + m >= break_at && i <= break_at + m;
    if (across_break) {
      for (size_t j = from; j <= to; ++j) out[j] = true;
    }
  }
  return out;
}

}  // namespace

std::vector<bool> unresolved(const Derivatives& d, Replay& r, const std::vector<double>& effort_left,
                             const std::vector<double>& effort_variance) {
  const size_t n = r.t.size();
  std::vector<bool> out = misfitting(d, local_derivatives(r.t, effort_left), r.x_noise, effort_variance);
  const std::vector<bool> beside = beside_contact_or_break(r, d.half_width, r.break_at);
  if (std::find(out.begin(), out.end(), true) != out.end()) {
    const Derivatives plain = local_derivatives(r.t, r.x, kShortWindow, kShortDegree);
    const std::vector<bool> plain_out =
        misfitting(plain, local_derivatives(r.t, effort_left, kShortWindow, kShortDegree), r.x_noise, effort_variance);
    for (size_t i = 0; i < n; ++i) {
      if (!out[i] || plain_out[i] || beside[i] || plain.rate_noise_gain * r.x_noise > r.rate_noise[i]) continue;
      out[i] = false;
      r.rate[i] = plain.rate[i];
      r.accel[i] = plain.accel[i];
      r.rate_noise[i] = plain.rate_noise_gain * r.x_noise;
      r.accel_noise[i] = plain.accel_noise_gain * r.x_noise;
    }
  }
  for (size_t i = 0; i < n; ++i) out[i] = out[i] || beside[i];
  return out;
}

}  // namespace afford
