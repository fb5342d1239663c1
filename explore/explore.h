// Functional improvisation (paper Sec. 2.2): one tool tried on every actee,
// placement along the jaws, thumb position along the handles, grasp type
// and squeezing effort, each point a generated session (point_session.h)
// run through the same engine and function models as `afford run`.
//
// The models are compiled once, one per actee and placement, before any
// point runs; the points then share them (and the rules) read-only across
// threads (sweep.h).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "model.h"
#include "point_session.h"
#include "rules.h"

namespace afford {

// What the grid spans. Counts are points spread evenly over their range,
// ends included (one point: the middle).
struct GridOptions {
  int placements = 3;  // per actee, over the part of the application region where it fits
  int thumbs = 3;      // over the emphasis region
  int efforts = 9;     // from 0 N up to max_effort (one: max_effort only)
  double max_effort = 0;  // N; 0: the hand's limit (the agent's max_force)
  std::vector<std::string> grasps;  // grasp types tried; empty: every type of the taxonomy
  double tolerance = 0.5;  // N, to which the thresholds are found
};

// A grid asked for that cannot be run (a count out of range, a grasp type
// the taxonomy lacks): the command line's mistake, not a file's.
class GridError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Limits on a grid, so that a typo does not start a week-long run.
inline constexpr int kMaxPerAxis = 1000;
inline constexpr long long kMaxPoints = 10'000'000;

struct ExploreFiles {
  std::string object, agent, rules, grasps;  // paths
  std::vector<std::string> actees;           // paths
};

// An actee and where it was tried; `fits` false: never, and why.
struct GridActee {
  std::string name, file;
  bool fits = false;
  std::string why;
  double limit = 0;     // N
  bool breaks = true;
  std::vector<double> placements;  // m, signed distances along the fixed arm
  bool operator==(const GridActee&) const = default;
};

// What a grid is, as plain data: everything its reports need besides the
// results (and all that a shard's file carries for the merge).
struct GridInfo {
  std::string object;                 // the tool's name
  std::vector<GridActee> actees;      // in the order given
  std::vector<double> thumbs;         // m
  std::vector<std::string> grasps;    // grasp type names; "-" for a model without a taxonomy
  std::vector<double> grasp_limit;    // N, the hand's push limit in each grasp
  std::vector<double> efforts;        // N
  std::vector<std::string> functions; // the function models' names
  double tolerance = 0.5;             // N
  bool operator==(const GridInfo&) const = default;
};

struct Explorer {
  GridInfo grid;
  std::vector<int> grasp_types;  // per grasp: index into the taxonomy (-1: none)
  std::vector<std::vector<std::shared_ptr<const Model>>> models;  // [actee][placement]
  std::vector<std::vector<JawsAtRest>> jaws;                      // [actee][placement]
  std::shared_ptr<const RuleSet> rules;
  PointTiming timing;
};

// Loads and compiles everything; throws DataError at the first bad file
// or grid value (a grasp type the taxonomy does not have, ...).
Explorer make_explorer(const ExploreFiles& files, const GridOptions& grid);

// One point: an actee that fits at one of its placements, a thumb, a
// grasp, an effort; indices into the explorer's lists.
struct GridPoint {
  int actee = 0, placement = 0, thumb = 0, grasp = 0, effort = 0;
};

struct PointResult {
  std::vector<double> first;   // s, per function: when it was first inferred, -1 never
  double peak_effort = 0;      // N, the largest push of the hand at the thumb
  double peak_actee_force = 0; // N, the largest force on the actee
  double broke_at = -1;        // s, when the actee broke; -1 never
};

// Runs one point through the engine. `effort` overrides the grid's effort
// (the thresholds' bisection).
PointResult run_point(const Explorer& e, const GridPoint& p);
PointResult run_point(const Explorer& e, const GridPoint& p, double effort_n);

// A point's outcome: the function it inferred last (the state the session
// ended in: crash after pinch and hold), ties to the one later in the
// function-model file; -1 when it inferred none. No function is named
// here: the maps and thresholds follow whatever the function models say.
int outcome(const PointResult& r);

}  // namespace afford
