// How far each function's trace got in a run: the closest approach of a
// function that was not inferred (the node it stopped before and the values
// that fell short), and which nodes were reached. `afford test` explains an
// unmet expectation with it, `afford run` a run that inferred nothing.
#pragma once

#include <string>
#include <vector>

#include "errors.h"
#include "observer.h"

namespace afford {

struct RuleFunction;  // rules_impl.h

// How far one function's trace got in a run: the explanation of a function
// that was not inferred.
struct FunctionProgress {
  std::string function;
  int nodes = 0;          // its node count
  int furthest = 0;       // the most nodes it had reached at once (== nodes: inferred)
  double furthest_t = 0;  // s, when it first got that far
  // The node it stopped before (furthest < nodes), as written with its
  // file:line:col, and why it did not count: its values at the frame it
  // came closest (a comparison: the largest margin; otherwise the most
  // sub-conditions true, or the longest hold for a node with `for`).
  std::string stopped_at;
};

struct NodeCoverage {
  std::string text;  // the `when` as written (or "<f> inferred")
  SourceLoc loc;
  bool reached = false;
};
struct FunctionCoverage {
  std::string name;
  std::vector<NodeCoverage> nodes;
};
// Which nodes of one function-model file the runs reached; functions in
// file order.
struct RulesCoverage {
  std::string file;
  std::vector<FunctionCoverage> functions;
};

// Watches a run: per function, the furthest its trace got, and for the node
// it stopped before, the values at the frame it came closest and its
// longest hold. Allocates only in on_start and on_end.
class ProgressObserver : public Observer {
 public:
  void on_start(const Model&, const State&, const RuleSet& rules) override;
  void on_frame(const Model&, const State& state, const RuleSet& rules, const RuleState& rs) override;
  void on_end(const Model&, const State&, const RuleSet& rules, const RuleState& rs) override;

  // One per function of the rules, in their order; filled by on_end.
  const std::vector<FunctionProgress>& progress() const { return progress_; }
  const RulesCoverage& coverage() const { return coverage_; }

 private:
  struct Track {
    int furthest = 0;
    double furthest_t = 0;
    bool has_values = false;
    double score = 0;
    double values_t = 0;
    double longest_hold = 0;  // s
    std::vector<double> values;  // per tree node of the node stopped before, at values_t
  };
  // The node a function stopped before, and why it did not count.
  static std::string stopped_at(const RuleSet& rules, const RuleFunction& fn, const Track& tr);

  std::vector<Track> track_;
  std::vector<FunctionProgress> progress_;
  RulesCoverage coverage_;
};

// "its trace reached 2 of its 3 nodes (by 0.490 s), then stopped at ..."
// for a function that was not inferred.
std::string progress_text(const FunctionProgress& p);

// "1.181 s": a time as the rule tests and run print it.
std::string format_seconds(double t);

}  // namespace afford
