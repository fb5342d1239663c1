// Inferences without allocating: what the rule state recorded of each
// (its function, time, node times and values) can be counted and copied
// in a frame, and written out as text later, elsewhere (a server's sender
// thread). `inferences()` (rules.h) is the same text for all of them.
#pragma once

#include <cstddef>
#include <span>

#include "rules.h"

namespace afford {

// How many inferences the rule state has recorded so far (they are never
// removed until reset). Allocates nothing.
size_t inference_count(const RuleState& rs);

// What one recorded inference kept: enough to explain it. The spans point
// into the rule state (valid until reset). Allocates nothing.
struct InferenceValues {
  int function = 0;
  double t = 0;                         // s, when it was inferred
  std::span<const double> node_times;   // s, per node, when it was reached
  std::span<const double> values;       // the function's value block (rules_impl.h)
};
InferenceValues inference_values(const RuleState& rs, size_t index);

// The largest node count and value block of any function of the rules:
// the room a copy of any InferenceValues needs.
size_t max_inference_nodes(const RuleSet& rules);
size_t max_inference_values(const RuleSet& rules);

// The inference explained, as inferences() explains it (allocates).
// node_times and values as inference_values() gives them, or copies.
Inference explain_inference(const RuleSet& rules, int function, double t, std::span<const double> node_times,
                            std::span<const double> values);

}  // namespace afford
