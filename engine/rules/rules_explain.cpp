// Explanations: each node of an inference written out with the values that
// made it true, e.g. "force(object, actee) = 312 N > limit(actee) = 300 N".
#include "rules_explain.h"

#include <algorithm>
#include <cstdio>

#include "rules_impl.h"

namespace afford {
namespace {

constexpr int kDigits = 4;     // significant digits of a value, unless more are needed
constexpr int kMaxDigits = 17;  // enough to tell any two doubles apart

std::string format_value(double v, bool boolean, const Dimension& d, int digits = kDigits) {
  if (boolean) return v != 0 ? "true" : "false";
  if (d == dim::none) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
  }
  return format_quantity(v, d, digits);
}

// A strict comparison that held must not read "35 N > 35 N": the digits
// grow until its two sides print differently (rounding keeps the order).
bool strict(const std::string& op) { return op == "<" || op == ">" || op == "!="; }

class Writer {
 public:
  Writer(const RuleNode& node, const double* values) : node_(node), values_(values) {}

  std::string write(int index) const {
    // A chain "a and b and c" is a left-deep tree and "not not x" a deep
    // one: walk both spines in a loop, so that a long chain does not recurse.
    std::string nots;
    size_t closing = 0;
    while (is_not(index)) {
      nots += "not (";
      ++closing;
      index = node(index).children[0];
    }
    std::vector<int> spine;  // the logical operators down the left side
    while (is_logical(index)) {
      spine.push_back(index);
      index = node(index).children[0];
    }
    std::string s = nots + leaf(index);
    for (size_t i = spine.size(); i-- > 0;) {
      const ExprNode& e = node(spine[i]);
      s += " " + e.op + " " + write(e.children[1]);
    }
    return s + std::string(closing, ')');
  }

 private:
  std::string shown(int index, int digits) const {
    const size_t i = static_cast<size_t>(index);
    return format_value(values_[i], node_.tree_boolean[i], node_.tree_dimension[i], digits);
  }

  int digits_for(int index, const ExprNode& e) const {
    int digits = kDigits;
    if (!strict(e.op) || values_[static_cast<size_t>(index)] == 0) return digits;
    while (digits < kMaxDigits && shown(e.children[0], digits) == shown(e.children[1], digits)) ++digits;
    return digits;
  }

  const ExprNode& node(int index) const { return node_.tree.nodes[static_cast<size_t>(index)]; }
  bool is_not(int index) const { return node(index).kind == ExprKind::unary && node(index).op == "not"; }
  bool is_logical(int index) const {
    const ExprNode& e = node(index);
    return e.kind == ExprKind::binary && (e.op == "and" || e.op == "or");
  }

  // Neither a 'not' nor 'and'/'or'.
  std::string leaf(int index) const {
    const ExprNode& e = node(index);
    if (is_not(index)) return write(index);  // "(not a) and b"
    if (e.kind == ExprKind::binary && is_comparison(e.op)) {
      const int digits = digits_for(index, e);
      return operand(e.children[0], digits) + " " + e.op + " " + operand(e.children[1], digits);
    }
    return operand(index);
  }

  // A literal reads as written; anything else gets its value.
  std::string operand(int index, int digits = kDigits) const {
    const ExprNode& e = node_.tree.nodes[static_cast<size_t>(index)];
    const std::string text = node_.tree.text(e);
    if (e.kind == ExprKind::number || e.kind == ExprKind::boolean) return text;
    const size_t i = static_cast<size_t>(index);
    if (node_.tree_boolean[i] && values_[i] != 0) return text;  // a condition that held
    return text + " = " + shown(index, digits);
  }

  const RuleNode& node_;
  const double* values_;
};


}  // namespace

bool is_comparison(const std::string& op) {
  return op == "<" || op == "<=" || op == ">" || op == ">=" || op == "==" || op == "!=";
}

std::string explain_node(const RuleNode& node, const double* tree_values) {
  return Writer(node, tree_values).write(node.tree.root);
}

std::string explain_details(const RuleNode& node, const double* detail_values) {
  std::string text;
  for (size_t k = 0; k < node.details.size(); ++k) {
    const Signal& s = *node.details[k].signal;
    text += (k ? "; " : "") + signature(s) + " = " + format_value(detail_values[k], s.boolean, s.dimension);
  }
  return text;
}

size_t inference_count(const RuleState& rs) { return rs.log.size(); }

InferenceValues inference_values(const RuleState& rs, size_t index) {
  const RuleState::Record& r = rs.log[index];
  const size_t times_end = index + 1 < rs.log.size() ? rs.log[index + 1].times_at : rs.log_times.size();
  const size_t values_end = index + 1 < rs.log.size() ? rs.log[index + 1].values_at : rs.log_values.size();
  return {r.function, r.t, std::span<const double>(rs.log_times.data() + r.times_at, times_end - r.times_at),
          std::span<const double>(rs.log_values.data() + r.values_at, values_end - r.values_at)};
}

size_t max_inference_nodes(const RuleSet& rules) {
  size_t n = 0;
  for (const RuleFunction& fn : rules.functions) n = std::max(n, fn.nodes.size());
  return n;
}

size_t max_inference_values(const RuleSet& rules) {
  size_t n = 0;
  for (const RuleFunction& fn : rules.functions) n = std::max(n, static_cast<size_t>(fn.value_count));
  return n;
}

Inference explain_inference(const RuleSet& rules, int function, double t, std::span<const double> node_times,
                            std::span<const double> values) {
  const RuleFunction& fn = rules.functions[static_cast<size_t>(function)];
  Inference inf;
  inf.function = fn.name;
  inf.t = t;
  for (size_t i = 0; i < fn.nodes.size(); ++i) {
    const RuleNode& node = fn.nodes[i];
    std::string text;
    if (node.required >= 0) {
      text = node.text;
    } else {
      text = explain_node(node, values.data() + node.value_offset);
    }
    if (node.min_duration > 0) text += " (held for " + format_quantity(node.min_duration, dim::time) + ")";
    inf.nodes.push_back({text, node_times[i]});
    inf.node_details.push_back(
        node.details.empty() ? std::string()
                             : explain_details(node, values.data() + node.value_offset + node.tree.nodes.size()));
  }
  return inf;
}

std::vector<Inference> inferences(const RuleSet& rules, const RuleState& rs) {
  std::vector<Inference> out;
  for (size_t i = 0; i < inference_count(rs); ++i) {
    const InferenceValues v = inference_values(rs, i);
    out.push_back(explain_inference(rules, v.function, v.t, v.node_times, v.values));
  }
  return out;
}

}  // namespace afford
