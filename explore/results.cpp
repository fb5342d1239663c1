#include "results.h"

#include <cmath>
#include <stdexcept>

#include "derive.h"
#include "lever.h"
#include "parallel.h"

namespace afford {
namespace {

// Where one series' outcome turns between two neighbouring efforts of the
// grid: bisection on the effort until the two ends are closer than the
// tolerance. The lower end keeps the outcome of the lower effort; any other
// outcome moves the upper end, so the first turn is the one found; then the
// same from there up, until the outcome is the upper effort's (a carry
// that turns into a crash may pass through a hold).
void bisect(const Explorer& e, const GridPoint& key, double lo, const PointResult& at_lo, double hi,
            const PointResult& at_hi, std::vector<Threshold>* out) {
  const int from = outcome(at_lo);
  Threshold t;
  t.from = from;
  t.below = lo;
  t.effort = hi;
  t.at = at_hi;
  while (t.effort - t.below > e.grid.tolerance) {
    const double mid = 0.5 * (t.below + t.effort);
    PointResult r = run_point(e, key, mid);
    if (outcome(r) == from) {
      t.below = mid;
    } else {
      t.effort = mid;
      t.at = std::move(r);
    }
  }
  t.to = outcome(t.at);
  out->push_back(t);
  if (t.to != outcome(at_hi) && hi - t.effort > e.grid.tolerance) bisect(e, key, t.effort, t.at, hi, at_hi, out);
}

// A bisection to run: series s (its place in the shard's list) between
// efforts i and i + 1.
struct Turn {
  size_t series;
  size_t effort;
};

}  // namespace

std::vector<GridPoint> grid_series(const GridInfo& g) {
  std::vector<GridPoint> series;
  for (size_t a = 0; a < g.actees.size(); ++a) {
    for (size_t p = 0; p < g.actees[a].placements.size(); ++p) {
      for (size_t t = 0; t < g.thumbs.size(); ++t) {
        for (size_t k = 0; k < g.grasps.size(); ++k) {
          series.push_back({static_cast<int>(a), static_cast<int>(p), static_cast<int>(t), static_cast<int>(k), 0});
        }
      }
    }
  }
  return series;
}

std::vector<GridPoint> grid_points(const GridInfo& g) {
  std::vector<GridPoint> points;
  for (const GridPoint& s : grid_series(g)) {
    for (size_t k = 0; k < g.efforts.size(); ++k) {
      points.push_back(s);
      points.back().effort = static_cast<int>(k);
    }
  }
  return points;
}

ExploreResult explore(const Explorer& e, Shard shard, int threads,
                      const std::function<void(std::size_t, std::size_t)>& progress) {
  const GridInfo& g = e.grid;
  ExploreResult result;
  result.shard = shard;
  const std::vector<GridPoint> all = grid_series(g);
  for (size_t i = 0; i < all.size(); ++i) {
    if (static_cast<int>(i % static_cast<size_t>(shard.count)) != shard.part - 1) continue;
    SeriesResult s;
    s.index = static_cast<int>(i);
    s.key = all[i];
    s.points.resize(g.efforts.size());
    const Model& m = *e.models[static_cast<size_t>(s.key.actee)][static_cast<size_t>(s.key.placement)];
    const double thumb = g.thumbs[static_cast<size_t>(s.key.thumb)];
    // The load acts where the moving jaw touches the actee (jaw_contact.cpp).
    const JawsAtRest& jaws = e.jaws[static_cast<size_t>(s.key.actee)][static_cast<size_t>(s.key.placement)];
    s.mechanical_advantage = mechanical_advantage(thumb, jaws.lever.load_distance);
    s.lever_effort_at_limit = effort_for_load(m, jaws.contact_angle, thumb, jaws.lever.load_distance, m.actee_limit);
    result.series.push_back(std::move(s));
  }

  // Every effort of every series, then every turn between two of them.
  const size_t efforts = g.efforts.size();
  const size_t points = result.series.size() * efforts;
  std::vector<Turn> turns;
  auto report = [&](size_t done, size_t) {
    if (progress) progress(done, points + turns.size());
  };
  parallel_for(points, threads, [&](size_t i) {
    SeriesResult& s = result.series[i / efforts];
    GridPoint p = s.key;
    p.effort = static_cast<int>(i % efforts);
    s.points[i % efforts] = run_point(e, p);
  }, report);

  for (size_t s = 0; s < result.series.size(); ++s) {
    const std::vector<PointResult>& pts = result.series[s].points;
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
      if (outcome(pts[i]) != outcome(pts[i + 1])) turns.push_back({s, i});
    }
  }
  std::vector<std::vector<Threshold>> found(turns.size());
  parallel_for(turns.size(), threads, [&](size_t i) {
    const SeriesResult& s = result.series[turns[i].series];
    const size_t k = turns[i].effort;
    bisect(e, s.key, g.efforts[k], s.points[k], g.efforts[k + 1], s.points[k + 1], &found[i]);
  }, [&](size_t done, size_t) {
    if (progress) progress(points + done, points + turns.size());
  });
  for (size_t i = 0; i < turns.size(); ++i) {
    std::vector<Threshold>& to = result.series[turns[i].series].thresholds;
    to.insert(to.end(), found[i].begin(), found[i].end());
  }
  return result;
}

ExploreResult merge(const GridInfo& g, std::vector<ExploreResult> parts) {
  const std::vector<GridPoint> keys = grid_series(g);
  const size_t total = keys.size();
  ExploreResult whole;
  whole.series.resize(total);
  std::vector<bool> seen(total, false);
  for (ExploreResult& part : parts) {
    for (SeriesResult& s : part.series) {
      const size_t i = static_cast<size_t>(s.index);
      if (i >= total) throw std::runtime_error("series " + std::to_string(i) + " is not part of this grid");
      if (seen[i]) throw std::runtime_error("series " + std::to_string(i) + " is in two shards");
      const GridPoint& k = keys[i];
      if (s.key.actee != k.actee || s.key.placement != k.placement || s.key.thumb != k.thumb || s.key.grasp != k.grasp) {
        throw std::runtime_error("series " + std::to_string(i) + " is not where this grid has it");
      }
      seen[i] = true;
      whole.series[i] = std::move(s);
    }
  }
  for (size_t i = 0; i < total; ++i) {
    if (!seen[i]) throw std::runtime_error("series " + std::to_string(i) + " is in no shard: a part is missing");
  }
  return whole;
}

}  // namespace afford
