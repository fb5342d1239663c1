// Observers watch a running session (BehaviorTree.CPP's loggers): the run
// loop calls each after every frame, once the rules have been evaluated.
// The trace and timeline writers are in trace.h.
#pragma once

#include "model.h"
#include "rules.h"
#include "state.h"

namespace afford {

class Observer {
 public:
  virtual ~Observer() = default;
  // Before the first frame, with the state at rest (allocate here).
  virtual void on_start(const Model&, const State&, const RuleSet&) {}
  // After each frame's step and evaluate; the frame's events are in
  // events_begin(rs)..events_end(rs). The frame itself allocates nothing;
  // the trace, timeline and recorder observers keep it so, a renderer
  // (render/) allocates its images here.
  virtual void on_frame(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) = 0;
  // After the last frame.
  virtual void on_end(const Model&, const State&, const RuleSet&, const RuleState&) {}
};

}  // namespace afford
