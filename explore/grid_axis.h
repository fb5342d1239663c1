// The values along a grid's axes: spread evenly, each the double nearest a
// short decimal (so that points.csv reads 0.04125, not 0.041249999999999995,
// and still round-trips), and an actee's effort axis fitted to where its
// outcome turns.
#pragma once

#include <vector>

namespace afford {

// v as the double nearest its 12 significant digits: a grid value moves by
// at most 5e-12 of itself, far below anything the engine resolves.
double tidy(double v);

// n values spread evenly over [from, to], ends included, each tidy; one:
// the middle.
std::vector<double> spread(double from, double to, int n);

// The top of an effort axis of n efforts from 0 N that shows a turn at
// `last_turn` N in its upper part: a little above it (kTurnMargin), rounded
// up so that the step top / (n - 1) is 1, 1.5, 2, 2.5, 3, 4, 5, 6 or 8
// times a power of ten, that step at least `min_step` (the thresholds'
// tolerance: a finer axis shows nothing more), and at most `max_effort`.
inline constexpr double kTurnMargin = 1.1;
double effort_axis_top(double last_turn, int n, double max_effort, double min_step);

}  // namespace afford
