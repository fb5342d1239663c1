#include "replay.h"

#include <algorithm>
#include <cmath>

#include "derivatives.h"
#include "resolved_motion.h"
#include "smooth_derivative.h"
#include "state.h"
#include "terms.h"

namespace afford {
namespace {

constexpr double kReversalWindow = 0.02; // s: samples this near a change of direction are a reversal
constexpr double kReversalSpeed = 0.2;  // of the peak speed: a reversal lasts until the speed is back above this
constexpr double kLimitBand = 1e-3;      // rad: this near an angle limit counts as at it
constexpr double kSignWidth = 1e-3;      // rad/s: friction's sign turns over this speed
constexpr double kHeldBand = 0.1;        // friction's band below this share of a sample's noise does not matter
constexpr double kDropTime = 0.02;       // s: a crack drops the actee's force within this

// x, its rate and acceleration, and their noise (white_noise), no finer
// than the printed `resolution` (rad or m), which a noise-free trace
// still has.
Derivatives differentiate(Replay& r, double resolution) {
  Derivatives d = local_derivatives(r.t, r.x);
  r.step = sample_step(r.t);
  r.x_noise = std::max(white_noise(r.x), resolution);
  SmoothDerivative v = smooth_derivative(r.t, r.x, r.x_noise, d, 1);
  SmoothDerivative a = smooth_derivative(r.t, r.x, r.x_noise, d, 2);
  r.rate_noise = std::move(v.noise_gain);
  for (double& g : r.rate_noise) g *= r.x_noise;
  r.accel_noise = std::move(a.noise_gain);
  for (double& g : r.accel_noise) g *= r.x_noise;
  r.rate = std::move(v.value);
  r.accel = std::move(a.value);
  return d;
}

// Where the actee gave way in a trace without a `broken` column: its
// measured force falls to a tenth of what it carried within kDropTime
// while the model still squeezes it at more than half that deflection (a
// release unloads it only as the jaws open). SIZE_MAX: nowhere.
size_t measured_break(const Replay& r, const std::vector<double>& actee, double noise) {
  double peak = 0, peak_deflection = 0;
  size_t from = 0;  // the first sample within kDropTime of the one looked at
  for (size_t i = 0; i < actee.size(); ++i) {
    if (actee[i] > peak) {
      peak = actee[i];
      peak_deflection = r.deflection[i];
    }
    while (r.t[i] - r.t[from] > kDropTime) ++from;
    if (peak < 10 * noise || actee[i] > 0.1 * peak + 3 * noise) continue;
    if (r.deflection[i] <= 0.5 * peak_deflection) continue;
    for (size_t j = from; j < i; ++j) {
      if (actee[j] > 0.5 * peak) return i;
    }
  }
  return SIZE_MAX;
}


// Phases from direction, contact and the limits; `limit` and `broken` say
// which samples are at a limit and after the break.
// `edge` samples at either end are not fitted: there the rates are
// extrapolated from one side, which misses a start's transient.
// `friction`: the model's friction, in the main signal's unit (N*m about
// the fulcrum; 0 for plates).
void assign_phases(Replay& r, const std::vector<bool>& at_limit, const std::vector<bool>& broken,
                   const std::vector<bool>& blurred, size_t edge, double friction) {
  // A lever closes as its angle falls; plates load as their displacement grows.
  const double closing = r.rig == Rig::lever ? -1.0 : 1.0;
  const size_t n = r.t.size();
  // The drive's top speed, as its 95th percentile: a transient's spike
  // (a start, a ringing) is not the speed the drive runs at.
  std::vector<double> speeds(n);
  for (size_t i = 0; i < n; ++i) speeds[i] = std::abs(r.rate[i]);
  const auto top = speeds.begin() + static_cast<long>(0.95 * static_cast<double>(n - 1));
  std::nth_element(speeds.begin(), top, speeds.end());
  const double peak = *top;
  // Below this speed the arm is at rest: there Coulomb friction takes any
  // value up to its limit, which the motion alone cannot tell.
  // ... and below three times the noise of the rate itself, where its sign
  // is the noise's: each sample's own, from the window it took.
  const double least = std::max(1e-9, 0.01 * peak);
  auto still = [&](size_t i) { return std::max(least, 3 * r.rate_noise[i]); };
  r.phase.assign(n, Phase::at_rest);
  r.fitted.assign(n, true);
  r.held.assign(n, false);
  // Within `edge` samples of a time gap (closing-only strokes whose return
  // was not recorded) the rates are one-sided, as at the trace's ends.
  std::vector<bool> near_gap(n, false);
  const double gap = kRecordedApart * r.step;
  for (size_t i = 1; i < n; ++i) {
    if (r.t[i] - r.t[i - 1] <= gap) continue;
    for (size_t j = i >= edge ? i - edge : 0; j < std::min(n, i + edge); ++j) near_gap[j] = true;
  }
  int last_sign = 0;
  std::vector<size_t> turns;
  for (size_t i = 0; i < n; ++i) {
    const double rate = closing * r.rate[i];
    const int sign = rate > still(i) ? -1 : (rate < -still(i) ? 1 : 0);  // -1: closing or loading
    if (sign != 0 && last_sign != 0 && sign != last_sign) turns.push_back(i);
    if (sign != 0) last_sign = sign;
    const bool contact = r.deflection[i] > 0;
    if (sign < 0) r.phase[i] = contact ? Phase::loading : Phase::free_closing;
    if (sign > 0) r.phase[i] = contact ? Phase::unloading : Phase::free_opening;
  }
  // A reversal runs from kReversalWindow before a change of direction to
  // as long after it, and on while the speed stays below a fraction of
  // its peak: there friction turns over (sticks, creeps, breaks away) at a
  // pace set by what drives the tool, which no term of the library models.
  const double slow = kReversalSpeed * peak;
  for (size_t turn : turns) {
    auto from = static_cast<size_t>(std::lower_bound(r.t.begin(), r.t.end(), r.t[turn] - kReversalWindow) - r.t.begin());
    auto to = static_cast<size_t>(std::upper_bound(r.t.begin(), r.t.end(), r.t[turn] + kReversalWindow) - r.t.begin());
    while (from > 0 && std::abs(r.rate[from - 1]) < slow) --from;
    while (to < n && std::abs(r.rate[to]) < slow) ++to;
    for (size_t i = from; i < to; ++i) r.phase[i] = Phase::reversal;
  }
  for (size_t i = 0; i < n; ++i) {
    // Squeezed and all but still: the effort loads a stiff actee while the
    // angle hardly moves, so the rate is the noise's and friction may take
    // any value up to its limit. Where that band is a small share of what
    // the angle's own noise passes into the prediction through the actee's
    // stiffness, the sample still tells the actee's law by its deflection.
    const bool held = r.deflection[i] > 0 && friction < kHeldBand * std::abs(r.slope[i]) * r.x_noise;
    const bool moving = std::abs(r.rate[i]) > still(i) && r.phase[i] != Phase::reversal;
    if (held && !moving) r.phase[i] = closing * r.rate[i] > 0 ? Phase::loading : Phase::unloading;
    const bool in_motion = r.phase[i] != Phase::reversal && r.phase[i] != Phase::at_rest;
    if (blurred[i] && in_motion) r.phase[i] = Phase::unresolved;
    if (at_limit[i]) r.phase[i] = Phase::at_limit;
    if (broken[i]) r.phase[i] = Phase::after_break;
    // A limit's reaction, the snap as the actee breaks, motion the samples
    // do not resolve, and friction at rest and while it turns over at a
    // reversal are outside what the model predicts from the motion:
    // reported, not fitted or scored.
    r.fitted[i] = !at_limit[i] && !broken[i] && !blurred[i] && (moving || held) && i >= edge && i + edge < n &&
                  !near_gap[i];
    r.held[i] = r.fitted[i] && !moving;
  }
}

}  // namespace

double value_at(const std::vector<double>& t, const std::vector<double>& y, double at) {
  if (at <= t.front()) return y.front();
  if (at >= t.back()) return y.back();
  const size_t j = static_cast<size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin());
  const double w = (at - t[j - 1]) / (t[j] - t[j - 1]);
  return (1 - w) * y[j - 1] + w * y[j];
}

std::vector<double> delayed(const std::vector<double>& t, const std::vector<double>& y, double delay, double step) {
  if (delay == 0) return y;
  // value_at at every t[i] - delay, in one walk: those times increase with
  // i. A sensor's memory starts again after a time gap (a stretch not
  // recorded): there, as at the trace's start, the first value is held.
  std::vector<double> out(y.size());
  const double gap = kRecordedApart * step;
  size_t j = 1;      // the first sample later than the time asked for, once inside
  size_t start = 0;  // the first sample of the stretch sample i is in
  for (size_t i = 0; i < y.size(); ++i) {
    if (i > 0 && t[i] - t[i - 1] > gap) start = i;
    const double at = t[i] - delay;
    if (at <= t[start] || at >= t.back()) {
      out[i] = at <= t[start] ? y[start] : y.back();
      continue;
    }
    j = std::max(j, start + 1);
    while (t[j] <= at) ++j;
    const double w = (at - t[j - 1]) / (t[j] - t[j - 1]);
    out[i] = (1 - w) * y[j - 1] + w * y[j];
  }
  return out;
}

std::vector<double> delayed_keeping_noise(const std::vector<double>& t, const std::vector<double>& y, double delay,
                                          double step) {
  if (delay == 0) return y;
  // One walk: where the stencil does not apply, delayed()'s value, as it
  // would give it (held before a stretch's start and after the end, else
  // linear between the samples either side).
  const size_t n = t.size();
  std::vector<double> out(n);
  const double gap = kRecordedApart * step;
  // even[a]: the step from sample a to a + 1 is the sampling step (within 1 %).
  std::vector<unsigned char> even(n, 0);
  for (size_t a = 0; a + 1 < n; ++a) even[a] = std::abs(t[a + 1] - t[a] - step) <= 0.01 * step;
  size_t j = 1;             // the first sample later than the time asked for
  size_t start_held = 0;    // delayed()'s stretch: it holds the first value before it
  size_t start_even = 0;    // the stencil's: evenly spaced from here on (never before start_held)
  for (size_t i = 0; i < n; ++i) {
    if (i > 0 && t[i] - t[i - 1] > gap) start_held = i;
    if (i > 0 && !even[i - 1] && t[i] - t[i - 1] > step) start_even = i;
    const double at = t[i] - delay;
    if (at <= t[start_held] || at >= t.back()) {
      out[i] = at <= t[start_held] ? y[start_held] : y.back();
      continue;
    }
    j = std::max(j, start_held + 1);
    while (t[j] <= at) ++j;
    const double f = (at - t[j - 1]) / (t[j] - t[j - 1]);
    // Samples j-2 .. j+1 around the interval, in the stretch and evenly
    // spaced, else the linear value.
    if (at <= t[start_even] || j < start_even + 2 || j + 1 >= n || !even[j - 2] || !even[j - 1] || !even[j]) {
      out[i] = (1 - f) * y[j - 1] + f * y[j];
      continue;
    }
    // Weights (-s, 1 - f + s, f + s, -s): they sum to 1, reproduce a
    // line, and their squares sum to 1 with this s.
    const double s = 0.25 * (std::sqrt(1 + 8 * f * (1 - f)) - 1);
    out[i] = -s * y[j - 2] + (1 - f + s) * y[j - 1] + (f + s) * y[j] - s * y[j + 1];
  }
  return out;
}

void leave_out_late_readings(std::vector<Replay>& replays, double delay) {
  if (delay <= 0) return;
  for (Replay& r : replays) {
    const size_t n = r.t.size();
    const double gap = kRecordedApart * r.step;
    const std::vector<bool> source = r.fitted;  // where the model predicts the effort
    size_t start = 0;                             // the first sample of the stretch sample i is in
    for (size_t i = 0; i < n; ++i) {
      if (i > 0 && r.t[i] - r.t[i - 1] > gap) start = i;
      if (!r.fitted[i]) continue;
      const double at = r.t[i] - delay;
      // The samples either side of the earlier time must both be predicted.
      const size_t later = static_cast<size_t>(std::upper_bound(r.t.begin(), r.t.end(), at) - r.t.begin());
      if (at <= r.t[start] || later == 0 || later >= n || !source[later] || !source[later - 1]) r.fitted[i] = false;
    }
  }
}

void release_held(std::vector<Replay>& replays, double friction) {
  for (Replay& r : replays) {
    for (size_t i = 0; i < r.t.size(); ++i) {
      if (!r.held[i] || friction < kHeldBand * std::abs(r.slope[i]) * r.x_noise) continue;
      r.held[i] = false;
      r.fitted[i] = false;
      r.phase[i] = Phase::at_rest;
    }
  }
}

void weigh(std::vector<Replay>& replays, double noise, double delay) {
  // Only the weights' ratios matter to fits and weighted RMSEs; a
  // noise-free effort (traces written by formulas) still ranks them.
  const double sensor = std::max(noise * noise, 1e-24);  // N^2
  for (Replay& r : replays) {
    // The angle's noise reaches the prediction through the slope and,
    // differentiated twice, through the arm's inertia: where the
    // acceleration keeps a narrow window (a trace's ends, a fast motion)
    // a heavy arm passes far more of it.
    std::vector<double> through(r.t.size());  // N^2
    for (size_t i = 0; i < r.t.size(); ++i) {
      const double slope = r.slope[i] * r.x_noise * r.to_newtons;                  // N
      const double inertia = r.inertia * r.accel_noise[i] * r.to_newtons;  // N
      through[i] = slope * slope + inertia * inertia;
    }
    // A set with the latency predicts the reading at t from the motion at
    // t - delay, and takes on the angle's noise there: the first readings
    // after the jaws leave a stiff actee are predicted by its contact,
    // where the angle's noise passes on many times over. Each weight must
    // hold for every set compared, late or not: the noisier prediction
    // sets it.
    if (delay > 0) {
      const std::vector<double> late = delayed(r.t, through, delay, r.step);
      for (size_t i = 0; i < through.size(); ++i) through[i] = std::max(through[i], late[i]);
    }
    r.weight.resize(r.t.size());
    for (size_t i = 0; i < r.t.size(); ++i) r.weight[i] = sensor / (sensor + through[i]);
  }
}

double smooth_sign(double rate) { return std::tanh(rate / kSignWidth); }

const char* phase_name(Phase p) {
  static const char* const kNames[] = {"free closing", "free opening", "reversals",     "loading in contact",
                                       "unloading in contact", "at rest", "at a limit", "the break's snap",
                                       "unresolved motion"};
  return kNames[static_cast<int>(p)];
}

std::vector<Replay> replay_lever(const Model& model, const Measurement& m) {
  const auto state = make_state(model);
  const bool actee = model.has_actee && state->between_jaws;
  const double a = actee ? std::abs(state->load_distance) : 0.0;
  const double b = std::abs(m.effort_at);
  std::vector<Replay> out;
  for (const Trace& trace : m.traces) {
    double g_cos = 0, g_sin = 0;
    gravity_coefficients(model, model.object_start.linear(), &g_cos, &g_sin, trace.turned);
    Replay r;
    r.file = trace.file;
    r.turned = trace.turned;
    r.t = trace[Signal::t];
    r.x = trace[Signal::angle];
    const Derivatives d = differentiate(r, trace.resolution[static_cast<size_t>(Signal::angle)]);
    r.to_newtons = 1 / b;
    r.inertia = model.arm_inertia;
    r.resolution = trace.resolution[static_cast<size_t>(Signal::effort_force)];
    const size_t n = r.t.size();
    r.measured.resize(n);
    r.nominal.resize(n);
    r.deflection.resize(n);
    r.slope.resize(n);
    r.weight.assign(n, 1.0);  // until weigh() knows the effort's noise
    const bool measured_actee = trace.has(Signal::actee_force) && actee;
    // The jaws' squeeze of the actee by the model, then where it gave way:
    // the `broken` column, else its measured force dropping while the model
    // still squeezes it, else where the model's force passes its limit.
    for (size_t i = 0; i < n; ++i) r.deflection[i] = actee ? std::max(0.0, a * (state->contact_angle - r.x[i])) : 0.0;
    if (trace.has(Signal::broken)) {
      const std::vector<double>& broken = trace[Signal::broken];
      r.break_at = static_cast<size_t>(std::find_if(broken.begin(), broken.end(), [](double v) { return v > 0.5; }) -
                                       broken.begin());
    } else if (measured_actee) {
      const std::vector<double>& force = trace[Signal::actee_force];
      r.break_at = measured_break(r, force, white_noise(force));
    } else if (actee && model.actee_breaks) {
      double slope = 0;
      for (size_t i = 0; i < n && r.break_at == SIZE_MAX; ++i) {
        if (actee_force_law(model, r.deflection[i], state->actee_thickness, &slope) > model.actee_limit) r.break_at = i;
      }
    }
    if (r.break_at >= n) r.break_at = SIZE_MAX;
    std::vector<bool> at_limit(n);
    std::vector<double> from_angle(n);  // N*m: the nominal's prediction from the angle alone, no rates
    for (size_t i = 0; i < n; ++i) {
      const double theta = r.x[i];
      r.measured[i] = trace[Signal::effort_force][i] * b;
      const SpringTorques spring = spring_torques(model, theta);
      // After the break the tool is a tool without an actee.
      const bool whole = actee && i < r.break_at;
      if (!whole) r.deflection[i] = 0;
      const double deflection = r.deflection[i];
      double slope = 0;
      const double actee_force = actee_force_law(model, deflection, state->actee_thickness, &slope);
      // Within three of the angle's noise of the actee, that noise may put
      // the jaws on it: the prediction then follows the actee's stiffness,
      // as far as the noise could press it.
      if (whole && deflection == 0) {
        const double reach = a * (state->contact_angle - theta + 3 * r.x_noise);
        if (reach > 0) actee_force_law(model, reach, state->actee_thickness, &slope);
      }
      from_angle[i] = spring.linear + spring.preload + spring.progressive + actee_force * a +
                      g_cos * std::cos(theta) + g_sin * std::sin(theta);
      // The actee's torque F(a (theta_c - theta)) a turns by -F' a^2 per radian.
      r.slope[i] = spring.slope - slope * a * a - g_cos * std::sin(theta) + g_sin * std::cos(theta);
      at_limit[i] = theta <= model.theta_min + kLimitBand || theta >= model.theta_max - kLimitBand;
      if (measured_actee) {
        r.actee_measured.push_back(trace[Signal::actee_force][i]);
        r.actee_nominal.push_back(actee_force);
      }
    }
    // A late sensor reports the effort of `delay` ago.
    const bool late = model.sensor_latency > 0;
    const std::vector<double> from_angle_read =
        late ? delayed(r.t, from_angle, model.sensor_latency, r.step) : from_angle;
    const std::vector<double>& effort = trace[Signal::effort_force];
    const double effort_noise = std::max(white_noise(effort), r.resolution);
    std::vector<double> effort_left(n), effort_variance(n);
    for (size_t i = 0; i < n; ++i) {
      effort_left[i] = effort[i] - from_angle_read[i] / b;
      const double through = r.slope[i] * r.x_noise / b;  // N: the angle's noise in that prediction
      effort_variance[i] = effort_noise * effort_noise + through * through;
    }
    const std::vector<bool> blurred = unresolved(d, r, effort_left, effort_variance);
    // The prediction, from the rates unresolved() leaves. Coulomb friction
    // against the motion; a smooth sign near rest, where the motion alone
    // cannot say which way friction holds.
    for (size_t i = 0; i < n; ++i) {
      const double friction = -model.friction_torque * smooth_sign(r.rate[i]);
      r.nominal[i] = from_angle[i] + friction - model.damping * r.rate[i] - model.arm_inertia * r.accel[i];
    }
    if (late) r.nominal = delayed(r.t, r.nominal, model.sensor_latency, r.step);
    // The snap as the actee gives way lasts until the polynomial follows
    // the motion again over a whole window, and then as long again as a
    // late sensor may read it: the measurement's own delay and the longest
    // a fit searches. One resolved sample is enough: `blurred` already
    // spreads every window the polynomial misses over the samples it holds,
    // so a sample outside them has every window about it followed. Asking
    // for a window of such samples in a row, a press that slammed shut at
    // the crack and then stroked between its stops (strokes of 0.12 s, a
    // bump at each stop) never settled, and all its trace was left out
    // (development seed 3212).
    std::vector<bool> snap(n, false);
    if (r.break_at != SIZE_MAX) {
      double settled = -1;  // s, when the motion settled
      for (size_t i = r.break_at; i < n; ++i) {
        if (settled < 0 && !blurred[i]) settled = r.t[i];
        if (settled >= 0 && r.t[i] - settled >= model.sensor_latency + kLongestDelay) break;
        snap[i] = true;
      }
    }
    // Within the fit's half-width of either end the rates are one-sided.
    assign_phases(r, at_limit, snap, blurred, d.half_width, model.friction_torque);
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<Replay> replay_plates(const Model& model, const Measurement& m) {
  const double thickness = actee_geometry(model, Rig::plates).thickness;
  std::vector<Replay> out;
  for (const Trace& trace : m.traces) {
    Replay r;
    r.file = trace.file;
    r.rig = Rig::plates;
    r.t = trace[Signal::t];
    r.x = trace[Signal::displacement];
    const Derivatives d = differentiate(r, trace.resolution[static_cast<size_t>(Signal::displacement)]);
    r.resolution = trace.resolution[static_cast<size_t>(Signal::force)];
    const size_t n = r.t.size();
    r.measured = trace[Signal::force];
    r.nominal.resize(n);
    r.deflection.resize(n);
    r.slope.resize(n);
    r.weight.assign(n, 1.0);
    std::vector<bool> at_limit(n, false), broken(n, false);
    // The shell gives way at its peak before the first large drop.
    size_t rupture = n;
    double peak = 0;
    for (size_t i = 0; i < n; ++i) {
      if (r.measured[i] > peak) peak = r.measured[i];
      if (peak > 0.1 * model.actee_limit && r.measured[i] < 0.9 * peak) {
        rupture = i;
        break;
      }
    }
    for (size_t i = 0; i < n; ++i) {
      double slope = 0;
      r.deflection[i] = std::max(0.0, r.x[i]);
      r.nominal[i] = actee_force_law(model, r.deflection[i], thickness, &slope);
      r.slope[i] = slope;
      broken[i] = i >= rupture;
    }
    r.break_at = rupture < n ? rupture : SIZE_MAX;
    // The plates' law needs no rates (none is unresolved), and has no friction.
    assign_phases(r, at_limit, broken, std::vector<bool>(n, false), 0, 0.0);
    out.push_back(std::move(r));
  }
  return out;
}

ActeeGeometry actee_geometry(const Model& model, Rig rig) {
  ActeeGeometry g;
  if (rig == Rig::plates) {
    const Eigen::Vector3d d = model.actee_direction;
    g.thickness = model.actee().support(d) + model.actee().support(-d);
  } else {
    const auto state = make_state(model);
    g.arm = std::abs(state->load_distance);
    g.thickness = state->actee_thickness;
  }
  return g;
}

std::vector<double> actee_term(const Model& model, const Replay& r, const ActeeGeometry& g, double exponent,
                               double reference, double zero_m) {
  std::vector<double> out(r.t.size(), 0.0);
  for (size_t i = 0; i < out.size(); ++i) {
    const double deflection = r.deflection[i] - zero_m;
    if (deflection <= 0) continue;  // most samples: the jaws are off the actee
    double slope = 0;
    out[i] = actee_law(model.actee_stiffness, exponent, reference, deflection, g.thickness, &slope) * g.arm;
  }
  return out;
}

}  // namespace afford
