// Explanations: each node of an inference written out with the values that
// made it true, e.g. "force(object, actee) = 312 N > limit(actee) = 300 N".
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
    const ExprNode& e = node_.tree.nodes[static_cast<size_t>(index)];
    if (e.kind == ExprKind::binary && (e.op == "and" || e.op == "or")) {
      return write(e.children[0]) + " " + e.op + " " + write(e.children[1]);
    }
    if (e.kind == ExprKind::binary && is_comparison(e.op)) {
      const int digits = digits_for(index, e);
      return operand(e.children[0], digits) + " " + e.op + " " + operand(e.children[1], digits);
    }
    if (e.kind == ExprKind::unary && e.op == "not") return "not (" + write(e.children[0]) + ")";
    return operand(index);
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

  // A literal reads as written; anything else gets its value.
  std::string operand(int index, int digits = kDigits) const {
    const ExprNode& e = node_.tree.nodes[static_cast<size_t>(index)];
    if (e.kind == ExprKind::number || e.kind == ExprKind::boolean) return e.text;
    const size_t i = static_cast<size_t>(index);
    if (node_.tree_boolean[i] && values_[i] != 0) return e.text;  // a condition that held
    return e.text + " = " + shown(index, digits);
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

std::vector<Inference> inferences(const RuleSet& rules, const RuleState& rs) {
  std::vector<Inference> out;
  for (const RuleState::Record& r : rs.log) {
    const RuleFunction& fn = rules.functions[static_cast<size_t>(r.function)];
    Inference inf;
    inf.function = fn.name;
    inf.t = r.t;
    for (size_t i = 0; i < fn.nodes.size(); ++i) {
      const RuleNode& node = fn.nodes[i];
      const double t = rs.log_times[r.times_at + i];
      std::string text;
      if (node.required >= 0) {
        text = node.text;
      } else {
        text = explain_node(node, rs.log_values.data() + r.values_at + node.value_offset);
      }
      if (node.min_duration > 0) text += " (held for " + format_quantity(node.min_duration, dim::time) + ")";
      inf.nodes.push_back({text, t});
    }
    out.push_back(std::move(inf));
  }
  return out;
}

}  // namespace afford
