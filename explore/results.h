// A grid's results: for every series (an actee at a placement, a thumb
// position, a grasp type) the outcome at each effort of the grid, and the
// thresholds where the outcome turns, found by bisection on the effort.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "explore.h"

namespace afford {

// Where the outcome of a series turns from one function to another (or
// from none, -1): between `below` (the highest effort seen with `from`) and
// `effort` (the lowest seen with `to`), less than the tolerance apart.
struct Threshold {
  int from = -1, to = -1;     // outcome (function index), -1: none
  double below = 0;           // N
  double effort = 0;          // N
  PointResult at;             // the run at `effort`
};

struct SeriesResult {
  int index = 0;  // the series' place in the whole grid (series_count)
  GridPoint key;  // actee, placement, thumb, grasp (effort unused)
  std::vector<PointResult> points;  // one per effort of the grid
  std::vector<Threshold> thresholds;
  double mechanical_advantage = 0;  // |thumb| / |placement|
  // N: the effort at the thumb that the static lever balance says brings the
  // actee to its limit (spring included, no friction or motion terms), for
  // the summary's "explained by".
  double lever_effort_at_limit = 0;
};

// A part of the grid: the series with index % count == part - 1.
struct Shard {
  int part = 1, count = 1;  // 1-based part of count
  bool whole() const { return count == 1; }
};

struct ExploreResult {
  Shard shard;
  std::vector<SeriesResult> series;  // by index
};

// The series of a grid, in order (actee, placement, thumb, grasp).
std::vector<GridPoint> grid_series(const GridInfo& g);
// Every point of a grid: each series at each of its actee's efforts, in that order.
std::vector<GridPoint> grid_points(const GridInfo& g);

// Whether effort i of a series is pushed as effort i - 1 is (both beyond
// its grasp's cap), so that one run serves both.
bool repeats_previous(const GridInfo& g, const GridPoint& series, size_t i);

// Every effort of each series on its actee's axis, on `threads` threads;
// an effort that repeats_previous() is run once. Same bits whatever the
// number of threads.
std::vector<std::vector<PointResult>> run_series(const Explorer& e, const std::vector<GridPoint>& series, int threads,
                                                 const std::function<void(std::size_t, std::size_t)>& progress = {});

// Runs the grid's series of `shard` on `threads` threads: every effort of
// each series, then the thresholds between them. `progress(done, total)`
// counts simulated sessions. Same bits whatever the number of threads.
ExploreResult explore(const Explorer& e, Shard shard, int threads,
                      const std::function<void(std::size_t, std::size_t)>& progress = {});

// The grasp types that an actee's map shows alike: groups (each in grid
// order, the groups by their first) of grasps whose series, at every
// placement and thumb, end the same at every effort and turn between the
// same outcomes at efforts within the tolerance of each other.
std::vector<std::vector<int>> alike_grasps(const GridInfo& g, const ExploreResult& r, int actee);

// Joins shards of one grid into the whole; throws std::runtime_error when a
// series is missing or given twice.
ExploreResult merge(const GridInfo& g, std::vector<ExploreResult> parts);

}  // namespace afford
