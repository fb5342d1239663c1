// The progress observer: each function's closest approach (closest_approach.h).
#include "closest_approach.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rules_impl.h"
#include "units.h"

namespace afford {
namespace {

// How close a node's condition came to holding this frame (larger is
// closer): for a comparison its margin, otherwise how many of its
// sub-conditions hold.
double closeness(const RuleNode& node, const std::vector<double>& value) {
  const ExprNode& root = node.tree.nodes[static_cast<size_t>(node.tree.root)];
  auto v = [&](int tree_index) {
    return value[static_cast<size_t>(node.tree_slot[static_cast<size_t>(tree_index)])];
  };
  if (root.kind == ExprKind::binary && is_comparison(root.op)) {
    const double a = v(root.children[0]), b = v(root.children[1]);
    if (root.op == ">" || root.op == ">=") return a - b;
    if (root.op == "<" || root.op == "<=") return b - a;
    if (root.op == "==") return -std::abs(a - b);
    return std::abs(a - b);
  }
  double held = 0;
  for (size_t i = 0; i < node.tree.nodes.size(); ++i) {
    if (node.tree_boolean[i] && v(static_cast<int>(i)) != 0) held += 1;
  }
  return held;
}

}  // namespace

void ProgressObserver::on_start(const Model&, const State&, const RuleSet& rules) {
  track_.assign(rules.functions.size(), Track{});
  for (size_t f = 0; f < rules.functions.size(); ++f) {
    size_t most = 0;
    for (const RuleNode& node : rules.functions[f].nodes) most = std::max(most, node.tree.nodes.size() + node.details.size());
    track_[f].values.assign(most, 0.0);
  }
}

void ProgressObserver::on_frame(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) {
  const double t = state.t;
  for (size_t f = 0; f < rules.functions.size(); ++f) {
    const RuleFunction& fn = rules.functions[f];
    Track& tr = track_[f];
    const int stage = rs.trace[f].stage;
    if (stage > tr.furthest) {
      tr.furthest = stage;
      tr.furthest_t = t;
      tr.has_values = false;
      tr.longest_hold = 0;
    }
    if (stage != tr.furthest || stage >= static_cast<int>(fn.nodes.size())) continue;
    const RuleNode& node = fn.nodes[static_cast<size_t>(stage)];
    if (node.required >= 0) continue;
    const size_t flat = static_cast<size_t>(rs.node_base[f] + stage);
    if (rs.holds[flat]) tr.longest_hold = std::max(tr.longest_hold, t - rs.true_since[flat]);
    const double score = closeness(node, rs.value);
    // Among equally close frames, the one whose explaining value (a grip
    // margin) came nearest to making it hold.
    const size_t tree = node.tree_slot.size();
    const bool nearer = !node.details.empty() && score == tr.score &&
                        node.details[0].signal->read(model, state) > tr.values[tree];
    if (!tr.has_values || score > tr.score || nearer) {
      for (size_t k = 0; k < node.tree_slot.size(); ++k) {
        tr.values[k] = rs.value[static_cast<size_t>(node.tree_slot[k])];
      }
      for (size_t k = 0; k < node.details.size(); ++k) tr.values[tree + k] = node.details[k].signal->read(model, state);
      tr.score = score;
      tr.values_t = t;
      tr.has_values = true;
    }
  }
}

void ProgressObserver::on_end(const Model&, const State&, const RuleSet& rules, const RuleState& rs) {
  progress_.clear();
  for (size_t f = 0; f < rules.functions.size(); ++f) {
    const RuleFunction& fn = rules.functions[f];
    const Track& tr = track_[f];
    FunctionProgress p;
    p.function = fn.name;
    p.nodes = static_cast<int>(fn.nodes.size());
    p.furthest = tr.furthest;
    p.furthest_t = tr.furthest_t;
    if (tr.furthest < p.nodes) p.stopped_at = stopped_at(rules, fn, tr);
    progress_.push_back(std::move(p));
  }
  coverage_.file = rules.file;
  coverage_.functions.clear();
  std::vector<size_t> order(rules.functions.size());
  for (size_t f = 0; f < order.size(); ++f) order[f] = f;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const SourceLoc& la = rules.functions[a].loc;
    const SourceLoc& lb = rules.functions[b].loc;
    return la.line != lb.line ? la.line < lb.line : la.column < lb.column;
  });
  for (size_t f : order) {
    const RuleFunction& fn = rules.functions[f];
    FunctionCoverage fc;
    fc.name = fn.name;
    for (size_t i = 0; i < fn.nodes.size(); ++i) {
      fc.nodes.push_back({fn.nodes[i].text, fn.nodes[i].loc, node_ever_reached(rs, static_cast<int>(f), static_cast<int>(i))});
    }
    coverage_.functions.push_back(std::move(fc));
  }
}

// The node a function stopped before, and why it did not count.
std::string ProgressObserver::stopped_at(const RuleSet& rules, const RuleFunction& fn, const Track& tr) {
  const RuleNode& node = fn.nodes[static_cast<size_t>(tr.furthest)];
  std::string s = "'" + node.text + "' (" + node.loc.str() + ")";
  if (node.required >= 0) {
    return s + ": " + rules.functions[static_cast<size_t>(node.required)].name + " was never inferred";
  }
  if (node.min_duration > 0 && tr.longest_hold > 0) {
    s += ": true for at most " + format_seconds(tr.longest_hold) + " of the " +
         format_quantity(node.min_duration, dim::time) + " it needs";
  } else {
    s += ": never true";
  }
  if (tr.has_values) {
    s += "; closest at " + format_seconds(tr.values_t) + ": " + explain_node(node, tr.values.data());
    if (!node.details.empty()) s += "; " + explain_details(node, tr.values.data() + node.tree.nodes.size());
  }
  return s;
}

std::string progress_text(const FunctionProgress& p) {
  std::string s;
  if (p.furthest == 0) {
    s = "its trace reached none of its " + std::to_string(p.nodes) + " nodes";
  } else {
    s = "its trace reached " + std::to_string(p.furthest) + " of its " + std::to_string(p.nodes) + " nodes (by " +
        format_seconds(p.furthest_t) + ")";
  }
  return s + ", then stopped at " + p.stopped_at;
}

std::string format_seconds(double t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", t);
  return buf;
}

}  // namespace afford
