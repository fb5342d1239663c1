#include "run.h"

#include <cmath>
#include <limits>
#include <memory>

namespace afford {

RunResult run_session(const Model& model, const RuleSet& rules, SampleSource& source,
                      std::span<Observer* const> observers) {
  std::unique_ptr<State> state = make_state(model);
  RuleStatePtr rule_state = make_rule_state(rules);
  for (Observer* o : observers) o->on_start(model, *state, rules);
  // The last frame is the one at the source's end, within rounding: a
  // script of 2 s at 1 ms runs 2000 frames.
  const double duration = source.duration();
  const double last = std::isfinite(duration) ? std::floor(duration / model.timestep + 1e-9) : std::numeric_limits<double>::infinity();
  RunResult result;
  Sample sample;
  for (std::int64_t k = 1; static_cast<double>(k) <= last; ++k) {
    const double t = static_cast<double>(k) * model.timestep;
    if (!source.sample_at(std::min(t, duration), &sample)) break;
    sample.t = t;
    step(model, *state, sample);
    evaluate(rules, *rule_state, model, *state);
    for (Observer* o : observers) o->on_frame(model, *state, rules, *rule_state);
    result.frames = k;
    result.end_time = t;
  }
  for (Observer* o : observers) o->on_end(model, *state, rules, *rule_state);
  result.inferences = inferences(rules, *rule_state);
  return result;
}

}  // namespace afford
