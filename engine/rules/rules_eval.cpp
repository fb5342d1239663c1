// Each frame: evaluate the flat program once, then trace every function
// model (Fig. 15) through its ordered nodes. Allocates nothing.
#include "rules_impl.h"

namespace afford {
namespace {

// Durations are compared in a time that accumulates frame steps: allow for
// the rounding of that sum.
constexpr double kTimeSlack = 1e-9;  // s

void emit(RuleState& rs, EventKind kind, double t, int function, int node) {
  if (rs.event_count == kMaxEventsPerFrame) {
    ++rs.events_dropped;
    return;
  }
  rs.events[static_cast<size_t>(rs.event_count++)] = Event{kind, t, function, node};
}

void run_program(const RuleSet& rules, RuleState& rs, const Model& m, const State& s) {
  double* v = rs.value.data();
  const size_t n = rules.program.size();
  for (size_t i = 0; i < n; ++i) {
    const Instr& in = rules.program[i];
    const double a = in.a >= 0 ? v[in.a] : 0.0;
    const double b = in.b >= 0 ? v[in.b] : 0.0;
    double r = 0;
    switch (in.op) {
      case Op::constant: r = in.k; break;
      case Op::signal: r = in.signal->read(m, s); break;
      case Op::neg: r = -a; break;
      case Op::logical_not: r = a != 0 ? 0.0 : 1.0; break;
      case Op::add: r = a + b; break;
      case Op::sub: r = a - b; break;
      case Op::mul: r = a * b; break;
      case Op::div: r = b != 0 ? a / b : 0.0; break;  // a signal may be 0 (no load yet)
      case Op::lt: r = a < b; break;
      case Op::le: r = a <= b; break;
      case Op::gt: r = a > b; break;
      case Op::ge: r = a >= b; break;
      case Op::eq: r = a == b; break;
      case Op::ne: r = a != b; break;
      case Op::logical_and: r = (a != 0 && b != 0) ? 1.0 : 0.0; break;
      case Op::logical_or: r = (a != 0 || b != 0) ? 1.0 : 0.0; break;
    }
    v[i] = r;
  }
}

void reach(const RuleFunction& fn, RuleState& rs, int f, int i, double t, const Model& m, const State& s) {
  const size_t flat = static_cast<size_t>(rs.node_base[static_cast<size_t>(f)] + i);
  const RuleNode& node = fn.nodes[static_cast<size_t>(i)];
  rs.reached_at[flat] = t;
  rs.ever_reached[flat] = 1;
  double* out = rs.reached_values.data() + rs.value_base[static_cast<size_t>(f)] + node.value_offset;
  for (size_t k = 0; k < node.tree_slot.size(); ++k) out[k] = rs.value[static_cast<size_t>(node.tree_slot[k])];
  out += node.tree_slot.size();
  for (size_t k = 0; k < node.details.size(); ++k) out[k] = node.details[k].signal->read(m, s);
  emit(rs, EventKind::node_reached, t, f, i);
}

void record_inference(const RuleFunction& fn, RuleState& rs, int f, double t) {
  emit(rs, EventKind::inferred, t, f, static_cast<int>(fn.nodes.size()) - 1);
  if (rs.log.size() == rs.log.capacity() ||
      rs.log_values.size() + static_cast<size_t>(fn.value_count) > rs.log_values.capacity() ||
      rs.log_times.size() + fn.nodes.size() > rs.log_times.capacity()) {
    ++rs.dropped_inferences;
    return;
  }
  rs.log.push_back({f, t, rs.log_times.size(), rs.log_values.size()});
  const size_t base = static_cast<size_t>(rs.node_base[static_cast<size_t>(f)]);
  for (size_t i = 0; i < fn.nodes.size(); ++i) rs.log_times.push_back(rs.reached_at[base + i]);
  const double* values = rs.reached_values.data() + rs.value_base[static_cast<size_t>(f)];
  for (int k = 0; k < fn.value_count; ++k) rs.log_values.push_back(values[k]);
}

}  // namespace

void RuleStateDeleter::operator()(RuleState* rs) const { delete rs; }

RuleStatePtr make_rule_state(const RuleSet& rules) {
  RuleStatePtr rs(new RuleState);
  reset(rules, *rs);
  return rs;
}

void reset(const RuleSet& rules, RuleState& rs) {
  rs.value.assign(rules.program.size(), 0.0);
  rs.trace.assign(rules.functions.size(), RuleState::Trace{});
  rs.node_base.clear();
  rs.value_base.clear();
  int nodes = 0, values = 0;
  for (const RuleFunction& fn : rules.functions) {
    rs.node_base.push_back(nodes);
    rs.value_base.push_back(values);
    nodes += static_cast<int>(fn.nodes.size());
    values += fn.value_count;
  }
  rs.holds.assign(static_cast<size_t>(nodes), 0);
  rs.true_since.assign(static_cast<size_t>(nodes), -1.0);
  rs.reached_at.assign(static_cast<size_t>(nodes), 0.0);
  rs.ever_reached.assign(static_cast<size_t>(nodes), 0);
  rs.reached_values.assign(static_cast<size_t>(values), 0.0);
  rs.event_count = 0;
  rs.events_dropped = 0;
  rs.log.clear();
  rs.log_times.clear();
  rs.log_values.clear();
  rs.log.reserve(kMaxRecordedInferences);
  rs.log_times.reserve(kMaxRecordedInferences * 8);
  rs.log_values.reserve(kMaxRecordedInferences * 64);
  rs.dropped_inferences = 0;
}

void evaluate(const RuleSet& rules, RuleState& rs, const Model& m, const State& s) {
  rs.event_count = 0;
  run_program(rules, rs, m, s);
  const double t = s.t;
  for (size_t f = 0; f < rules.functions.size(); ++f) {
    const RuleFunction& fn = rules.functions[f];
    RuleState::Trace& tr = rs.trace[f];
    const int base = rs.node_base[f];
    const int n = static_cast<int>(fn.nodes.size());
    for (int i = 0; i < n; ++i) {
      const RuleNode& node = fn.nodes[static_cast<size_t>(i)];
      // Requirements come earlier in the order, so their state is this frame's.
      const bool holds = node.required >= 0 ? rs.trace[static_cast<size_t>(node.required)].completed
                                            : rs.value[static_cast<size_t>(node.slot)] != 0;
      const size_t flat = static_cast<size_t>(base + i);
      if (holds && rs.true_since[flat] < 0) rs.true_since[flat] = t;
      if (!holds) rs.true_since[flat] = -1;
      rs.holds[flat] = holds;
    }
    // A reached node that stops holding sends the trace back to it.
    for (int i = 0; i < tr.stage; ++i) {
      if (!rs.holds[static_cast<size_t>(base + i)]) {
        emit(rs, EventKind::node_lost, t, static_cast<int>(f), i);
        tr.stage = i;
        tr.completed = false;
        break;
      }
    }
    // Climb as far as the nodes allow, in order.
    while (tr.stage < n) {
      const size_t flat = static_cast<size_t>(base + tr.stage);
      const RuleNode& node = fn.nodes[static_cast<size_t>(tr.stage)];
      if (!rs.holds[flat] || t - rs.true_since[flat] < node.min_duration - kTimeSlack) break;
      reach(fn, rs, static_cast<int>(f), tr.stage, t, m, s);
      ++tr.stage;
    }
    if (tr.stage == n && !tr.completed) {
      tr.completed = true;
      record_inference(fn, rs, static_cast<int>(f), t);
    }
  }
}

const Event* events_begin(const RuleState& rs) { return rs.events.data(); }
const Event* events_end(const RuleState& rs) { return rs.events.data() + rs.event_count; }

int function_count(const RuleSet& rules) { return static_cast<int>(rules.functions.size()); }
const std::string& function_name(const RuleSet& rules, int f) { return rules.functions[static_cast<size_t>(f)].name; }
int node_count(const RuleSet& rules, int f) { return static_cast<int>(rules.functions[static_cast<size_t>(f)].nodes.size()); }
const std::string& node_text(const RuleSet& rules, int f, int node) {
  return rules.functions[static_cast<size_t>(f)].nodes[static_cast<size_t>(node)].text;
}
SourceLoc node_loc(const RuleSet& rules, int f, int node) {
  return rules.functions[static_cast<size_t>(f)].nodes[static_cast<size_t>(node)].loc;
}
bool node_ever_reached(const RuleState& rs, int f, int node) {
  return rs.ever_reached[static_cast<size_t>(rs.node_base[static_cast<size_t>(f)] + node)] != 0;
}

}  // namespace afford
