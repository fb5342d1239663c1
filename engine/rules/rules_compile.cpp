// rules/functions.yaml -> RuleSet: every `when` parsed, type-checked with
// units, and compiled into one flat program in which an expression written
// several times (in one function or in several) has one slot.
#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>

#include "did_you_mean.h"
#include "rules_impl.h"
#include "yaml_reader.h"

namespace afford {
namespace {

struct Type {
  bool boolean = false;
  Dimension dimension;
};

std::string describe_type(const Type& t) { return t.boolean ? "a condition" : describe_dimension(t.dimension); }

class Compiler {
 public:
  explicit Compiler(RuleSet& rules) : rules_(rules) {}

  // Compiles one node's tree; returns the slot of its root.
  int compile(RuleNode& node) {
    const size_t n = node.tree.nodes.size();
    node.tree_slot.assign(n, -1);
    node.details.clear();
    node.tree_dimension.assign(n, dim::none);
    node.tree_boolean.assign(n, false);
    // Children come before their parents: one pass in index order, no
    // recursion, linear in the length of the expression.
    for (size_t i = 0; i < n; ++i) visit(node, static_cast<int>(i));
    const Type t = type_of(node, node.tree.root);
    if (!t.boolean) {
      const ExprNode& root = node.tree.nodes[static_cast<size_t>(node.tree.root)];
      fail(root.loc, "a condition (a comparison, or a signal that is true or false)",
           shorten(node.tree.text(root)) + ", " + describe_type(t));
    }
    return node.tree_slot[static_cast<size_t>(node.tree.root)];
  }

 private:
  int emit(const Instr& in) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &in.k, sizeof bits);
    const auto key = std::make_tuple(static_cast<int>(in.op), in.a, in.b, bits, in.signal);
    auto it = seen_.find(key);
    if (it != seen_.end()) return it->second;  // shared: evaluated once per frame
    rules_.program.push_back(in);
    const int slot = static_cast<int>(rules_.program.size()) - 1;
    seen_.emplace(key, slot);
    return slot;
  }

  // The type of a node already visited.
  static Type type_of(const RuleNode& node, int index) {
    Type t;
    t.boolean = node.tree_boolean[static_cast<size_t>(index)];
    t.dimension = node.tree_dimension[static_cast<size_t>(index)];
    return t;
  }

  Type visit(RuleNode& node, int index) {
    const ExprNode& e = node.tree.nodes[static_cast<size_t>(index)];
    Type t;
    int slot = -1;
    switch (e.kind) {
      case ExprKind::number:
        t.dimension = e.dimension;
        slot = emit({Op::constant, -1, -1, e.value, nullptr});
        break;
      case ExprKind::boolean:
        t.boolean = true;
        slot = emit({Op::constant, -1, -1, e.value, nullptr});
        break;
      case ExprKind::call: {
        const Signal* s = resolve(e, node.tree.text(e));
        t.boolean = s->boolean;
        t.dimension = s->dimension;
        slot = emit({Op::signal, -1, -1, 0, s});
        if (const Signal* why = explaining_signal(*s)) node.details.push_back({why});
        break;
      }
      case ExprKind::unary: {
        const Type inner = type_of(node, e.children[0]);
        const int a = node.tree_slot[static_cast<size_t>(e.children[0])];
        if (e.op == "not") {
          if (!inner.boolean) operand_error(node, e.children[0], "a condition after 'not'");
          t.boolean = true;
          slot = emit({Op::logical_not, a, -1, 0, nullptr});
        } else {
          if (inner.boolean) operand_error(node, e.children[0], "a number after '-'");
          t = inner;
          slot = emit({Op::neg, a, -1, 0, nullptr});
        }
        break;
      }
      case ExprKind::binary:
        std::tie(t, slot) = binary(node, e);
        break;
    }
    node.tree_slot[static_cast<size_t>(index)] = slot;
    node.tree_dimension[static_cast<size_t>(index)] = t.dimension;
    node.tree_boolean[static_cast<size_t>(index)] = t.boolean;
    return t;
  }

  std::pair<Type, int> binary(RuleNode& node, const ExprNode& e) {
    const Type l = type_of(node, e.children[0]);
    const Type r = type_of(node, e.children[1]);
    const int a = node.tree_slot[static_cast<size_t>(e.children[0])];
    const int b = node.tree_slot[static_cast<size_t>(e.children[1])];
    const std::string& op = e.op;
    Type t;
    if (op == "and" || op == "or") {
      if (!l.boolean) operand_error(node, e.children[0], "a condition before '" + op + "'");
      if (!r.boolean) operand_error(node, e.children[1], "a condition after '" + op + "'");
      t.boolean = true;
      return {t, emit({op == "and" ? Op::logical_and : Op::logical_or, a, b, 0, nullptr})};
    }
    if (l.boolean) operand_error(node, e.children[0], "a number before '" + op + "'");
    if (r.boolean) operand_error(node, e.children[1], "a number after '" + op + "'");
    static const std::map<std::string, Op> kOps = {
        {"+", Op::add}, {"-", Op::sub}, {"*", Op::mul}, {"/", Op::div}, {"<", Op::lt}, {"<=", Op::le},
        {">", Op::gt},  {">=", Op::ge}, {"==", Op::eq}, {"!=", Op::ne}};
    const Op code = kOps.at(op);
    if (code == Op::mul || code == Op::div) {
      t.dimension = code == Op::mul ? l.dimension * r.dimension : l.dimension / r.dimension;
    } else {
      // Sums and comparisons need the same dimension on both sides.
      if (!(l.dimension == r.dimension)) {
        const ExprNode& rhs = node.tree.nodes[static_cast<size_t>(e.children[1])];
        const ExprNode& lhs = node.tree.nodes[static_cast<size_t>(e.children[0])];
        fail(rhs.loc, describe_type(l) + " to go with " + shorten(node.tree.text(lhs)),
             shorten(node.tree.text(rhs)) + ", " + describe_type(r));
      }
      t.dimension = l.dimension;
      t.boolean = code != Op::add && code != Op::sub;
      if (t.boolean) t.dimension = dim::none;
    }
    return {t, emit({code, a, b, 0, nullptr})};
  }

  [[noreturn]] void operand_error(const RuleNode& node, int index, const std::string& expected) {
    const ExprNode& e = node.tree.nodes[static_cast<size_t>(index)];
    fail(e.loc, expected, shorten(node.tree.text(e)));
  }

  const Signal* resolve(const ExprNode& e, const std::string& text) {
    std::vector<Entity> args;
    for (const std::string& a : e.args) {
      Entity entity;
      if (!parse_entity(a, &entity)) {
        fail(e.loc, "arguments among agent, object and actee in " + shorten(text),
             "'" + a + "'" + did_you_mean(a, {"agent", "object", "actee"}));
      }
      args.push_back(entity);
    }
    if (const Signal* s = find_signal(e.op, args)) return s;
    std::string forms;
    for (const Signal& s : signal_registry()) {
      if (e.op == s.name) forms += (forms.empty() ? "" : ", ") + signature(s);
    }
    if (forms.empty()) {
      const std::string hint = did_you_mean(e.op, signal_names());
      fail(e.loc, "a signal of the vocabulary (afford rules --list)", "'" + e.op + "'" + hint);
    }
    fail(e.loc, "one of " + forms, shorten(text));
  }

  RuleSet& rules_;
  std::map<std::tuple<int, int, int, std::uint64_t, const Signal*>, int> seen_;
};

// Orders functions so that each comes after those it required; a cycle is
// an error at the first function in it.
void order_by_requirement(RuleSet& rules, const std::vector<std::vector<int>>& required) {
  const size_t n = rules.functions.size();
  std::vector<int> state(n, 0);  // 0 new, 1 visiting, 2 done
  std::vector<int> order;
  std::vector<int> mapping(n);
  std::vector<int> path;  // the functions being visited, outermost first
  auto visit = [&](auto&& self, int f) -> void {
    if (state[static_cast<size_t>(f)] == 2) return;
    if (state[static_cast<size_t>(f)] == 1) {
      // The circle: from f's place on the path back round to f.
      std::string circle;
      for (size_t i = 0; i < path.size(); ++i) {
        if (!circle.empty() || path[i] == f) circle += rules.functions[static_cast<size_t>(path[i])].name + " requires ";
      }
      const RuleFunction& fn = rules.functions[static_cast<size_t>(f)];
      fail(fn.loc, "functions that do not require each other in a circle", circle + fn.name);
    }
    state[static_cast<size_t>(f)] = 1;
    path.push_back(f);
    for (int r : required[static_cast<size_t>(f)]) self(self, r);
    path.pop_back();
    state[static_cast<size_t>(f)] = 2;
    order.push_back(f);
  };
  for (size_t f = 0; f < n; ++f) visit(visit, static_cast<int>(f));
  std::vector<RuleFunction> sorted;
  for (size_t i = 0; i < n; ++i) mapping[static_cast<size_t>(order[i])] = static_cast<int>(i);
  for (int f : order) sorted.push_back(std::move(rules.functions[static_cast<size_t>(f)]));
  for (RuleFunction& fn : sorted) {
    for (RuleNode& node : fn.nodes) {
      if (node.required >= 0) node.required = mapping[static_cast<size_t>(node.required)];
    }
  }
  rules.functions = std::move(sorted);
}

// `strength`: every function once, weakest first (afford explore reports a
// point by the strongest function it reached). Without it, file order.
void read_strength(MapReader& top, const std::vector<std::string>& names, RuleSet& rules) {
  for (size_t i = 0; i < rules.functions.size(); ++i) rules.functions[i].strength = static_cast<int>(i);
  const std::optional<Node> list = top.optional("strength");
  if (!list) return;
  if (!list->is_sequence()) list->fail("a sequence of the function names, weakest first, e.g. [pinch, hold]");
  std::vector<bool> listed(names.size(), false);
  for (size_t j = 0; j < list->size(); ++j) {
    const Node item = (*list)[j];
    const std::string n = read_name(item);
    const auto it = std::find(names.begin(), names.end(), n);
    if (it == names.end()) item.fail("the name of a function in this file", "'" + n + "'" + did_you_mean(n, names));
    const size_t f = static_cast<size_t>(it - names.begin());
    if (listed[f]) item.fail("each function once", "'" + n + "' again");
    listed[f] = true;
    rules.functions[f].strength = static_cast<int>(j);
  }
  for (size_t f = 0; f < names.size(); ++f) {
    if (!listed[f]) list->fail("every function of the file, once", "no '" + names[f] + "'");
  }
}

const MapSchema& condition_schema() {
  using namespace schema;
  static const MapSchema kCondition{
      "a condition node: an expression that must hold, for a while",
      {required_key("when", expression(), "a predicate expression (afford rules --list)"),
       optional_key("for", quantity(dim::time), "how long it must hold (default 0 s)")}};
  return kCondition;
}

const MapSchema& function_model_schema() {
  using namespace schema;
  static const MapSchema kFunction{
      "a function model: the conditions under which a function is inferred",
      {required_key("name", name(), "the function's name, unique in the file"),
       required_key("description", text(), "what the function is, in a sentence"),
       optional_key("requires", sequence(name()), "functions that must have been inferred first"),
       required_key("nodes", sequence(mapping(condition_schema()), 1), "the conditions, in order")}};
  return kFunction;
}

std::shared_ptr<const RuleSet> compile_rules(const Node& root) {
  auto rules = std::make_shared<RuleSet>();
  rules->file = root.loc().file;
  MapReader top(root, "a function-model file", functions_schema());
  const Node list = top.required("functions");
  if (!list.is_sequence() || list.size() == 0) list.fail("a sequence of function models");
  Compiler compiler(*rules);

  // Names first, so that `required` may name a function defined later.
  std::vector<std::string> names;
  for (size_t i = 0; i < list.size(); ++i) {
    MapReader f(list[i], "a function model", function_model_schema());
    const Node name = f.required("name");
    const std::string n = read_name(name);
    for (const std::string& other : names) {
      if (other == n) name.fail("a function name used once", "'" + n + "' again");
    }
    names.push_back(n);
  }
  std::vector<std::vector<int>> required(list.size());
  for (size_t i = 0; i < list.size(); ++i) {
    MapReader f(list[i], "a function model", function_model_schema());
    RuleFunction fn;
    fn.loc = list[i].loc();
    fn.name = names[i];
    fn.description = read_string(f.required("description"));
    if (std::optional<Node> req = f.optional("requires")) {
      if (!req->is_sequence()) req->fail("a sequence of function names, e.g. [hold]");
      for (size_t j = 0; j < req->size(); ++j) {
        const std::string r = read_name((*req)[j]);
        int index = -1;
        for (size_t k = 0; k < names.size(); ++k) {
          if (names[k] == r) index = static_cast<int>(k);
        }
        if (index < 0) (*req)[j].fail("the name of a function in this file", "'" + r + "'" + did_you_mean(r, names));
        if (index == static_cast<int>(i)) (*req)[j].fail("another function", "'" + r + "', itself");
        required[i].push_back(index);
        RuleNode node;
        node.text = r + " inferred";
        node.loc = (*req)[j].loc();
        node.required = index;
        fn.nodes.push_back(std::move(node));
      }
    }
    const Node nodes = f.required("nodes");
    if (!nodes.is_sequence() || nodes.size() == 0) nodes.fail("a sequence of condition nodes");
    for (size_t j = 0; j < nodes.size(); ++j) {
      MapReader nm(nodes[j], "a condition node", condition_schema());
      const Node when = nm.required("when");
      RuleNode node;
      node.text = read_string(when);
      node.loc = when.loc();
      // yaml-cpp tags a quoted scalar "!": its text starts one column later.
      node.tree = parse_expression(node.text, node.loc, when.yaml().Tag() == "!");
      node.slot = compiler.compile(node);
      if (std::optional<Node> d = nm.optional("for")) {
        node.min_duration = read_non_negative(*d, dim::time);
      }
      node.value_offset = fn.value_count;
      fn.value_count += static_cast<int>(node.tree.nodes.size() + node.details.size());
      fn.nodes.push_back(std::move(node));
    }
    rules->functions.push_back(std::move(fn));
  }
  read_strength(top, names, *rules);
  order_by_requirement(*rules, required);
  return rules;
}

}  // namespace

const MapSchema& functions_schema() {
  using namespace schema;
  static const MapSchema kFunctions{
      "a function-model file: the functions afford infers (rules/README.md)",
      {required_key("functions", sequence(mapping(function_model_schema()), 1), "the function models"),
       optional_key("strength", sequence(name()),
                    "every function once, weakest first: afford explore reports a point by the strongest it "
                    "reached (default: the order of the file)")}};
  return kFunctions;
}

int function_strength(const RuleSet& rules, int f) { return rules.functions[static_cast<size_t>(f)].strength; }

std::shared_ptr<const RuleSet> load_rules(const std::string& path) { return compile_rules(load_yaml_file(path)); }

std::shared_ptr<const RuleSet> read_rules(const std::string& yaml_text, const std::string& name) {
  return compile_rules(load_yaml_string(yaml_text, name));
}

std::shared_ptr<const RuleSet> read_rules(const Node& root) { return compile_rules(root); }

std::vector<SignalDoc> vocabulary() {
  std::vector<SignalDoc> docs;
  for (const Signal& s : signal_registry()) {
    std::string type = "condition";
    if (!s.boolean && s.dimension == dim::none) type = "number";
    if (!s.boolean && !(s.dimension == dim::none)) {
      // "a force (e.g. '30 N')" -> "force [N]"
      std::string name = describe_dimension(s.dimension);
      name = name.substr(name.find(' ') + 1);
      name = name.substr(0, name.find(" ("));
      const std::string one = format_quantity(1.0, s.dimension);
      type = name + " [" + one.substr(one.find(' ') + 1) + "]";
    }
    docs.push_back({signature(s), type, s.doc});
  }
  return docs;
}

}  // namespace afford
