// The rule engine (paper Sec. 4.5, Fig. 15): predicates over a vocabulary of
// signals, compiled once into flat form and evaluated every frame; function
// models as ordered condition nodes, traced as the session runs; every
// inference with its explanation.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "errors.h"
#include "model.h"
#include "state.h"

namespace afford {

class Node;
struct RuleSet;    // compiled, immutable; shared by sessions and threads
struct RuleState;  // per session
struct MapSchema;

// Loads a function-model file (rules/functions.yaml) and compiles it.
// Throws DataError naming file:line:col of the bad token.
std::shared_ptr<const RuleSet> load_rules(const std::string& path);
std::shared_ptr<const RuleSet> read_rules(const std::string& yaml_text, const std::string& name);
std::shared_ptr<const RuleSet> read_rules(const Node& root);  // an already parsed document
const MapSchema& functions_schema();  // the keys of a function-model file

// RuleState is opaque outside the engine; this deleter lets callers own one.
struct RuleStateDeleter {
  void operator()(RuleState* rs) const;
};
using RuleStatePtr = std::unique_ptr<RuleState, RuleStateDeleter>;

RuleStatePtr make_rule_state(const RuleSet& rules);
void reset(const RuleSet& rules, RuleState& rs);

enum class EventKind : std::uint8_t {
  node_reached,  // a function's node became true in order (its `for` met)
  node_lost,     // a reached node stopped holding: the trace falls back
  inferred,      // a function's last node was reached
};

struct Event {
  EventKind kind = EventKind::node_reached;
  double t = 0;   // s
  int function = 0;
  int node = 0;   // for node events
};

inline constexpr int kMaxEventsPerFrame = 64;

// Evaluates every predicate once and advances every function model. The
// frame's events are then in events(rs). Allocates nothing.
void evaluate(const RuleSet& rules, RuleState& rs, const Model& model, const State& state);

// This frame's events (valid until the next evaluate).
const Event* events_begin(const RuleState& rs);
const Event* events_end(const RuleState& rs);

// One inference and why: each node, when it became true and the values that
// made it so.
struct NodeExplanation {
  std::string text;  // "force(object, actee) = 312 N > limit(actee) = 300 N"
  double t = 0;      // s, when the node was reached
};
struct Inference {
  std::string function;
  double t = 0;  // s
  std::vector<NodeExplanation> nodes;
  // Per node, the values behind its conditions ("grip_margin(actee) =
  // 46.26 N" for held(actee)); empty when it has none.
  std::vector<std::string> node_details;
};

// Every inference so far, explained (allocates: call after frames, not in one).
std::vector<Inference> inferences(const RuleSet& rules, const RuleState& rs);

// Names for reporting.
int function_count(const RuleSet& rules);
const std::string& function_name(const RuleSet& rules, int function);
// The function's rank in the file's `strength` list (0 the weakest; without
// the list, its place in the file): which of two is the stronger outcome.
int function_strength(const RuleSet& rules, int function);
int node_count(const RuleSet& rules, int function);
const std::string& node_text(const RuleSet& rules, int function, int node);  // the `when` as written
SourceLoc node_loc(const RuleSet& rules, int function, int node);
// Whether a node was ever reached in this session (for coverage).
bool node_ever_reached(const RuleState& rs, int function, int node);

// The vocabulary, for `afford rules --list`: one line per signal with its
// arguments, type and unit, and what it means.
struct SignalDoc {
  std::string signature;  // "force(object, actee)"
  std::string type;       // "force [N]", "bool", "count"
  std::string doc;
};
std::vector<SignalDoc> vocabulary();

}  // namespace afford
