#include "run.h"

#include <cmath>
#include <limits>
#include <memory>

#include "session.h"

namespace afford {

namespace {

// The run loop; `changes` take the actees of `models` at their times.
RunResult run_with_changes(const Model& first, std::span<const Model> models, std::span<const ActeeChange> changes,
                           const RuleSet& rules, SampleSource& source, std::span<Observer* const> observers) {
  const Model* model = &first;
  size_t next = 0;  // the next change
  std::unique_ptr<State> state = make_state(first);
  RuleStatePtr rule_state = make_rule_state(rules);
  for (Observer* o : observers) o->on_start(first, *state, rules);
  // The last frame is the one at the source's end, within rounding: a
  // script of 2 s at 1 ms runs 2000 frames.
  const double duration = source.duration();
  const double last = std::isfinite(duration) ? std::floor(duration / first.timestep + 1e-9)
                                               : std::numeric_limits<double>::infinity();
  RunResult result;
  Sample sample;
  for (std::int64_t k = 1; static_cast<double>(k) <= last; ++k) {
    const double t = static_cast<double>(k) * first.timestep;
    if (!source.sample_at(std::min(t, duration), &sample)) break;
    sample.t = t;
    // A keyframe's actee is on the tool from the first frame at its time.
    for (; next < changes.size() && changes[next].t <= t + 1e-9 * model->timestep; ++next) {
      model = &models[changes[next].actee];
      change_actee(*model, *state);
    }
    step(*model, *state, sample);
    evaluate(rules, *rule_state, *model, *state);
    for (Observer* o : observers) o->on_frame(*model, *state, rules, *rule_state);
    result.frames = k;
    result.end_time = t;
  }
  for (Observer* o : observers) o->on_end(*model, *state, rules, *rule_state);
  result.inferences = inferences(rules, *rule_state);
  return result;
}

}  // namespace

RunResult run_session(const Model& model, const RuleSet& rules, SampleSource& source,
                      std::span<Observer* const> observers) {
  return run_with_changes(model, {}, {}, rules, source, observers);
}

RunResult run_session(const CompiledSession& s, const RuleSet& rules, SampleSource& source,
                      std::span<Observer* const> observers) {
  return run_with_changes(s.model, s.actee_models, s.actee_changes, rules, source, observers);
}

}  // namespace afford
