// Inside the rule engine: the compiled program and the per-session trace.
// Internal to the engine (rules.h is the interface).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "expr.h"
#include "rules.h"
#include "vocabulary.h"

namespace afford {

// One instruction of the flat program; its result is the slot of the same
// index. Operands always come earlier, so one pass in order evaluates all.
enum class Op : std::uint8_t { constant, signal, neg, logical_not, add, sub, mul, div, lt, le, gt, ge, eq, ne, logical_and, logical_or };

struct Instr {
  Op op = Op::constant;
  int a = -1, b = -1;             // operand slots
  double k = 0;                   // constant
  const Signal* signal = nullptr;  // signal
};

struct RuleNode {
  std::string text;           // the `when` as written, or "<name> inferred" for a requirement
  SourceLoc loc;
  int slot = -1;              // the condition's slot; -1 for a requirement
  int required = -1;          // the function that must be inferred (a requirement node)
  double min_duration = 0;    // s, how long the condition must hold before the node is reached
  ExprTree tree;              // for explanations
  std::vector<int> tree_slot;            // per tree node, its slot
  std::vector<Dimension> tree_dimension;  // per tree node, its dimension
  std::vector<bool> tree_boolean;        // per tree node, whether it is a condition
  // Values that explain a condition signal of the tree (explaining_signal),
  // read from the state and recorded after the tree's values when the node
  // is reached (not part of the program: no frame computes them otherwise).
  struct Detail {
    const Signal* signal = nullptr;
  };
  std::vector<Detail> details;
  int value_offset = 0;       // where its tree's values start in the function's value block
};

struct RuleFunction {
  std::string name;
  std::string description;
  SourceLoc loc;
  std::vector<RuleNode> nodes;
  int value_count = 0;  // values recorded per reach of all its nodes
  int strength = 0;     // rank in the file's `strength` list, 0 the weakest
};

struct RuleSet {
  std::string file;
  std::vector<Instr> program;
  std::vector<RuleFunction> functions;  // a function comes after those it required
};

struct RuleState {
  std::vector<double> value;  // per slot, this frame

  struct Trace {
    int stage = 0;           // the next node to reach
    bool completed = false;  // inferred, and no node has failed since
  };
  std::vector<Trace> trace;         // per function
  std::vector<int> node_base;       // per function: its first node in the flat per-node arrays
  std::vector<int> value_base;      // per function: its block in reached_values
  std::vector<std::uint8_t> holds;  // per node, this frame
  std::vector<double> true_since;   // per node, s; -1 while it does not hold
  std::vector<double> reached_at;   // per node, s
  std::vector<double> reached_values;  // per function block: every tree value of each node when reached
  std::vector<std::uint8_t> ever_reached;

  std::array<Event, kMaxEventsPerFrame> events{};
  int event_count = 0;
  long events_dropped = 0;

  // Every inference: the function, its time, and where its node times and
  // values were copied. Capacity is reserved up front; beyond it inferences
  // are counted, not recorded, so that a frame never allocates.
  struct Record {
    int function = 0;
    double t = 0;
    size_t times_at = 0, values_at = 0;
  };
  std::vector<Record> log;
  std::vector<double> log_times;
  std::vector<double> log_values;
  long dropped_inferences = 0;
};

inline constexpr size_t kMaxRecordedInferences = 4096;

// A node's condition written out with the values of its tree (one per tree
// node, in tree order): "load(actee) = 312 N > limit(actee) = 300 N".
std::string explain_node(const RuleNode& node, const double* tree_values);

// The node's details (RuleNode::details) with their values, in order:
// "grip_margin(actee) = 46.26 N"; empty when it has none.
std::string explain_details(const RuleNode& node, const double* detail_values);

// True for < <= > >= == !=.
bool is_comparison(const std::string& op);

}  // namespace afford
