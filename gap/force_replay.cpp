#include "force_replay.h"

#include <algorithm>
#include <cmath>

#include "forced_lever.h"
#include "replay.h"
#include "state.h"

namespace afford {
namespace {

// The measured effort `delay` later: a sensor with latency reports it late.
double effort_at(const Trace& trace, size_t i, double delay) {
  const std::vector<double>& f = trace[Signal::effort_force];
  return delay <= 0 ? f[i] : value_at(trace[Signal::t], f, trace[Signal::t][i] + delay);
}

// When the measurement saw the actee touched and broken.
void measured_events(const Trace& trace, double limit, double contact_angle, EventGap* contact, EventGap* broke) {
  const std::vector<double>& t = trace[Signal::t];
  const size_t n = t.size();
  for (size_t i = 0; i < n && contact->measured_t < 0; ++i) {
    const bool touched = trace.has(Signal::actee_force) ? trace[Signal::actee_force][i] > 0.01 * limit
                                                         : trace[Signal::angle][i] < contact_angle;
    if (touched) contact->measured_t = t[i];
  }
  if (trace.has(Signal::broken)) {
    for (size_t i = 0; i < n; ++i) {
      if (trace[Signal::broken][i] > 0.5) {
        broke->measured_t = t[i];
        // The force it broke at: on the row that says so, or the one before.
        if (trace.has(Signal::actee_force)) {
          const std::vector<double>& f = trace[Signal::actee_force];
          broke->measured_force = f[i] > 0 || i == 0 ? f[i] : f[i - 1];
        }
        return;
      }
    }
    return;
  }
  if (!trace.has(Signal::actee_force)) return;
  // The peak before the force first falls below half of it.
  const std::vector<double>& f = trace[Signal::actee_force];
  double peak = 0;
  size_t at = 0;
  for (size_t i = 0; i < n; ++i) {
    if (f[i] > peak) {
      peak = f[i];
      at = i;
    }
    if (peak > 0.1 * limit && f[i] < 0.5 * peak) {
      broke->measured_t = t[at];
      broke->measured_force = peak;
      return;
    }
  }
}

}  // namespace

std::vector<ForceGap> replay_force(const Model& model, const Measurement& m) {
  const auto state = make_state(model);
  ForcedLever lever;
  lever.effort_distance = std::abs(m.effort_at);
  lever.actee = model.has_actee && state->between_jaws;
  lever.load_distance = std::abs(state->load_distance);
  lever.contact_angle = state->contact_angle;
  lever.thickness = state->actee_thickness;
  lever.object_rotation = model.object_start.linear();
  std::vector<ForceGap> out;
  for (const Trace& trace : m.traces) {
    ForceGap g;
    g.file = trace.file;
    const std::vector<double>& t = trace[Signal::t];
    const std::vector<double>& angle = trace[Signal::angle];
    EventGap contact{"contact"}, broke{"break"};
    if (lever.actee) measured_events(trace, model.actee_limit, lever.contact_angle, &contact, &broke);
    ForcedLever now = lever;
    now.turn = trace.turned;
    double theta = angle.front(), omega = 0, sq = 0;
    size_t counted = 0;
    for (size_t i = 1; i < t.size(); ++i) {
      const ForcedStep step = step_forced_lever(model, now, theta, omega, effort_at(trace, i, model.sensor_latency), t[i] - t[i - 1]);
      theta = step.theta;
      omega = step.omega;
      // Touched as a force sensor would tell (1 % of the limit), as measured.
      if (now.actee && contact.simulated_t < 0 && step.actee_force > 0.01 * model.actee_limit) contact.simulated_t = t[i];
      if (now.actee && model.actee_breaks && step.actee_force > model.actee_limit) {
        broke.simulated_t = t[i];
        broke.simulated_force = step.actee_force;
        now.actee = false;  // the shell gave way
      }
      const bool before_break = (broke.measured_t < 0 || t[i] < broke.measured_t) && (broke.simulated_t < 0 || t[i] < broke.simulated_t);
      if (before_break) {
        sq += (theta - angle[i]) * (theta - angle[i]);
        ++counted;
      }
    }
    g.angle_rmse = counted > 0 ? std::sqrt(sq / static_cast<double>(counted)) : 0.0;
    if (lever.actee) g.events = {contact, broke};
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace afford
