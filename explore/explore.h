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
  // Each actee's effort axis from 0 N to a little above its last turn
  // (effort_axes.h) rather than to max_effort for all.
  bool scale_efforts = true;
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
  std::vector<double> efforts;     // N, its effort axis (GridInfo::efforts unless scaled to its turns)
  bool operator==(const GridActee&) const = default;
};

// What a grid is, as plain data: everything its reports need besides the
// results (and all that a shard's file carries for the merge).
struct GridInfo {
  std::string object;                 // the tool's name
  std::vector<GridActee> actees;      // in the order given
  std::vector<double> thumbs;         // m
  std::vector<std::string> grasps;    // grasp type names; "-" for a model without a taxonomy
  std::vector<double> grasp_limit;    // N, the hand's push limit in each grasp: efforts above are pushed at it
  std::vector<double> efforts;        // N, the common effort axis, 0 to max_effort
  bool efforts_scaled = false;        // each actee's axis fitted to its turns (GridActee::efforts)
  std::vector<std::string> functions; // the function models' names
  std::vector<int> strength;          // per function, its rank in the models' `strength` (0 the weakest)
  double tolerance = 0.5;             // N
  bool operator==(const GridInfo&) const = default;
};

struct Explorer {
  GridInfo grid;
  std::vector<int> grasp_types;  // per grasp: index into the taxonomy (-1: none)
  std::vector<std::vector<std::shared_ptr<const Model>>> models;  // [actee][placement]
  std::vector<std::vector<ForcedLever>> jaws;                      // [actee][placement]
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
  int outcome = -1;            // the strongest function reached while the effort was applied (outcome.h); -1 none
  double applied_from = -1;    // s, when the effort was applied (or the actee broke before); -1 never
  std::vector<double> first;   // s, per function: when it was first inferred, at any time; -1 never
  double peak_effort = 0;      // N, the largest push of the hand at the thumb
  double peak_actee_force = 0; // N, the largest force on the actee
  double broke_at = -1;        // s, when the actee broke; -1 never
};

// The effort the hand pushes with when asked for `effort_n` in grasp k: at
// most the grasp's limit (a point above it is "beyond the grasp's cap").
double applied_effort(const GridInfo& g, int grasp, double effort_n);

// Runs one point through the engine. `effort` overrides the actee's effort
// of the point (the thresholds' bisection); either is applied_effort()'s.
PointResult run_point(const Explorer& e, const GridPoint& p);
PointResult run_point(const Explorer& e, const GridPoint& p, double effort_n);

// A point's outcome (PointResult::outcome, outcome.h): the strongest
// function, in the function models' own order, reached while the hand
// applied the effort; -1 none. No function is named here: the maps and
// thresholds follow whatever the function models say.
inline int outcome(const PointResult& r) { return r.outcome; }

}  // namespace afford
