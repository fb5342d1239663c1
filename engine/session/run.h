// The session loop: one frame per timestep, the rules after each frame,
// then every observer (DESIGN.md "Data flow").
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "observer.h"
#include "rules.h"
#include "sample_source.h"

namespace afford {

struct RunResult {
  std::vector<Inference> inferences;  // every inference, explained, in order
  std::int64_t frames = 0;            // frames stepped
  double end_time = 0;                // s, the last frame's time
};

// Steps at model.timestep from t = timestep (frame k at t = k * timestep,
// never accumulated) until the source's duration or until it ends: for
// each frame step(model, state, sample), then evaluate(rules, ...), then
// each observer's on_frame. The model must have its agent. Only the
// observers may allocate per frame; the loop itself does not.
RunResult run_session(const Model& model, const RuleSet& rules, SampleSource& source,
                      std::span<Observer* const> observers = {});

}  // namespace afford
