// afford_step SESSION: steps a shipped session from your own program, frame
// by frame, with your own thumb (docs/libraries.md "Step a session from your
// own program"). The hand's pose and its other fingers come from the
// session's script; the thumb is the script's, pushed OFFSET_MM millimetres
// further toward the fixed arm (a negative offset: away from it; a controller
// of yours would set it). Prints
// each function as it is inferred and the largest force on the actee.
#include <afford/base/data_dir.h>
#include <afford/base/errors.h>
#include <afford/model/state.h>
#include <afford/rules/rules.h>
#include <afford/session/session.h>
#include <afford/devices/scripted_agent.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: afford_step SESSION OFFSET_MM (a session path in the shipped data)\n");
    return 2;
  }
  try {
    // Parse, then compile: the session's model, rules and script.
    const afford::CompiledSession session = afford::load_session(afford::shipped_path(argv[1]));
    const double offset = std::atof(argv[2]) / 1000;  // m
    // The mutable state of the simulation and of the function models.
    std::unique_ptr<afford::State> state = afford::make_state(session.model);
    afford::RuleStatePtr rules = afford::make_rule_state(*session.rules);
    afford::ScriptedAgent script(session.script);  // the rest of the hand

    afford::Sample sample;
    double peak = 0;  // N
    const auto frames = static_cast<long>(script.duration() / session.model.timestep + 1e-9);
    for (long k = 1; k <= frames; ++k) {
      const double t = static_cast<double>(k) * session.model.timestep;  // s, never accumulated
      script.sample_at(t, &sample);
      sample.t = t;
      sample.fingertip[0].y() -= offset;  // the thumb: your controller's target, m, world
      afford::step(session.model, *state, sample);                   // the physics of one frame
      afford::evaluate(*session.rules, *rules, session.model, *state);  // then the function models
      for (const afford::Event* e = afford::events_begin(*rules); e != afford::events_end(*rules); ++e) {
        if (e->kind == afford::EventKind::inferred) {
          std::printf("%s at %.3f s\n", afford::function_name(*session.rules, e->function).c_str(), e->t);
        }
      }
      peak = std::max(peak, state->actee_force);
    }
    std::printf("%ld frames, largest force on the actee %.1f N\n", frames, peak);
    return 0;
  } catch (const afford::DataError& e) {
    std::fprintf(stderr, "%s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "afford_step: %s\n", e.what());
  }
  return 1;
}
