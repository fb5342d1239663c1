#include "effort_axes.h"

#include <algorithm>

#include "grid_axis.h"
#include "parallel.h"
#include "results.h"

namespace afford {
namespace {

// The last turn between lo and hi (N; the outcome at hi is `last`): the
// lowest effort from which the outcome stays `last`, to the tolerance.
double last_turn(const Explorer& e, const GridPoint& key, double lo, double hi, int last) {
  while (hi - lo > e.grid.tolerance) {
    const double mid = 0.5 * (lo + hi);
    (outcome(run_point(e, key, mid)) == last ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

void fit_effort_axes(Explorer& e, int threads, const std::function<void(std::size_t, std::size_t)>& progress) {
  GridInfo& g = e.grid;
  const size_t n = g.efforts.size();
  if (n < 2) return;
  const std::vector<GridPoint> series = grid_series(g);
  size_t runs = 0;
  const std::vector<std::vector<PointResult>> points = run_series(e, series, threads, [&](size_t done, size_t total) {
    runs = total;
    if (progress) progress(done, runs + series.size());
  });
  std::vector<double> turn(series.size(), -1);  // N, per series; -1 none
  parallel_for(series.size(), threads, [&](size_t s) {
    const std::vector<PointResult>& p = points[s];
    for (size_t k = n - 1; k-- > 0;) {
      if (outcome(p[k]) == outcome(p[k + 1])) continue;
      turn[s] = last_turn(e, series[s], g.efforts[k], applied_effort(g, series[s].grasp, g.efforts[k + 1]),
                          outcome(p[k + 1]));
      break;
    }
  }, [&](size_t done, size_t) {
    if (progress) progress(runs + done, runs + series.size());
  });
  for (size_t a = 0; a < g.actees.size(); ++a) {
    double last = -1;
    for (size_t s = 0; s < series.size(); ++s) {
      if (series[s].actee == static_cast<int>(a)) last = std::max(last, turn[s]);
    }
    if (!g.actees[a].fits || last <= 0) continue;
    const double top = effort_axis_top(last, static_cast<int>(n), g.efforts.back(), g.tolerance);
    g.actees[a].efforts = spread(0, top, static_cast<int>(n));
  }
  g.efforts_scaled = true;
}

}  // namespace afford
