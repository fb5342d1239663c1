// What a grid writes for people and for other programs, from the grid and
// its results alone (so that a merge of shards writes the same bytes as the
// whole grid run at once):
//
//   points.csv      one row per point: actee, placement, thumb, grasp,
//                   effort, the effort applied (at most the grasp's cap),
//                   outcome (outcome.h), when the effort was applied, when
//                   each function was first inferred, the peaks, when the
//                   actee broke
//   thresholds.csv  one row per turn of the outcome along the effort
//   summary.txt     per actee in words
//   explore.json    all of it (and what `afford explore --merge` reads)
//   maps/ACTEE.svg, maps/ACTEE.png   the outcome over placement x effort
#pragma once

#include <string>
#include <vector>

#include "results.h"

namespace afford {

// "none" for -1, else the function's name.
std::string outcome_name(const GridInfo& g, int outcome);
// -1 (none), then every function from the weakest to the strongest.
std::vector<int> outcomes_by_strength(const GridInfo& g);

std::string points_csv(const GridInfo& g, const ExploreResult& r);
std::string thresholds_csv(const GridInfo& g, const ExploreResult& r);

// Per actee, in words: where it does not fit and why; for each outcome the
// lowest effort that reaches it, with where (placement, thumb, grasp) and
// the lever that explains it; the grasps that never reach it.
std::string summary_text(const GridInfo& g, const ExploreResult& r);

// The guides' "amplify or decline" made concrete (paper Sec. 4.4): per
// actee and turn of the outcome (carry -> crash), the least and the most
// effort at which it happens over the grid, each with where and the
// mechanical advantage; `afford guide` prints them where a grid was run.
struct TurnSpan {
  std::string actee, from, to;  // outcome names
  double low = 0, high = 0;     // N
  const SeriesResult* at_low = nullptr;
  const SeriesResult* at_high = nullptr;
};
std::vector<TurnSpan> turn_spans(const GridInfo& g, const ExploreResult& r);
std::string turn_span_text(const GridInfo& g, const TurnSpan& t);

// Writes every file above into dir (made if missing); returns their paths.
// A failed write throws WriteError (engine/base/files.h) naming the path.
std::vector<std::string> write_explore(const std::string& dir, const GridInfo& g, const ExploreResult& r);

}  // namespace afford
