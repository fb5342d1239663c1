#include "results.h"

#include <algorithm>
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
    for (size_t k = 0; k < g.actees[static_cast<size_t>(s.actee)].efforts.size(); ++k) {
      points.push_back(s);
      points.back().effort = static_cast<int>(k);
    }
  }
  return points;
}

bool repeats_previous(const GridInfo& g, const GridPoint& series, size_t i) {
  const std::vector<double>& efforts = g.actees[static_cast<size_t>(series.actee)].efforts;
  return i > 0 && applied_effort(g, series.grasp, efforts[i]) == applied_effort(g, series.grasp, efforts[i - 1]);
}

std::vector<std::vector<PointResult>> run_series(const Explorer& e, const std::vector<GridPoint>& series, int threads,
                                                 const std::function<void(std::size_t, std::size_t)>& progress) {
  std::vector<std::vector<PointResult>> out(series.size());
  std::vector<std::pair<size_t, size_t>> runs;  // (series, effort)
  for (size_t s = 0; s < series.size(); ++s) {
    out[s].resize(e.grid.actees[static_cast<size_t>(series[s].actee)].efforts.size());
    for (size_t k = 0; k < out[s].size(); ++k) {
      if (!repeats_previous(e.grid, series[s], k)) runs.emplace_back(s, k);
    }
  }
  parallel_for(runs.size(), threads, [&](size_t i) {
    GridPoint p = series[runs[i].first];
    p.effort = static_cast<int>(runs[i].second);
    out[runs[i].first][runs[i].second] = run_point(e, p);
  }, progress);
  for (size_t s = 0; s < series.size(); ++s) {
    for (size_t k = 1; k < out[s].size(); ++k) {
      if (repeats_previous(e.grid, series[s], k)) out[s][k] = out[s][k - 1];
    }
  }
  return out;
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
    const Model& m = *e.models[static_cast<size_t>(s.key.actee)][static_cast<size_t>(s.key.placement)];
    const double thumb = g.thumbs[static_cast<size_t>(s.key.thumb)];
    // The load acts where the moving jaw touches the actee (jaw_contact.cpp).
    const ForcedLever& jaws = e.jaws[static_cast<size_t>(s.key.actee)][static_cast<size_t>(s.key.placement)];
    s.mechanical_advantage = mechanical_advantage(thumb, jaws.load_distance);
    s.lever_effort_at_limit = effort_for_load(m, jaws.contact_angle, thumb, jaws.load_distance, m.actee_limit);
    result.series.push_back(std::move(s));
  }

  // Every effort of every series, then every turn between two of them.
  std::vector<GridPoint> keys;
  for (const SeriesResult& s : result.series) keys.push_back(s.key);
  size_t points = 0;
  std::vector<Turn> turns;
  std::vector<std::vector<PointResult>> runs = run_series(e, keys, threads, [&](size_t done, size_t total) {
    points = total;
    if (progress) progress(done, total);
  });
  for (size_t s = 0; s < result.series.size(); ++s) result.series[s].points = std::move(runs[s]);

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
    // Beyond the grasp's cap the hand pushes with the cap: the turn is below it.
    const std::vector<double>& efforts = g.actees[static_cast<size_t>(s.key.actee)].efforts;
    bisect(e, s.key, efforts[k], s.points[k], applied_effort(g, s.key.grasp, efforts[k + 1]), s.points[k + 1],
           &found[i]);
  }, [&](size_t done, size_t) {
    if (progress) progress(points + done, points + turns.size());
  });
  for (size_t i = 0; i < turns.size(); ++i) {
    std::vector<Threshold>& to = result.series[turns[i].series].thresholds;
    to.insert(to.end(), found[i].begin(), found[i].end());
  }
  return result;
}

namespace {

bool same_map(const SeriesResult& a, const SeriesResult& b, double tolerance) {
  if (a.points.size() != b.points.size() || a.thresholds.size() != b.thresholds.size()) return false;
  for (size_t i = 0; i < a.points.size(); ++i) {
    if (outcome(a.points[i]) != outcome(b.points[i])) return false;
  }
  for (size_t i = 0; i < a.thresholds.size(); ++i) {
    const Threshold &x = a.thresholds[i], &y = b.thresholds[i];
    if (x.from != y.from || x.to != y.to || std::abs(x.effort - y.effort) > tolerance) return false;
  }
  return true;
}

}  // namespace

std::vector<std::vector<int>> alike_grasps(const GridInfo& g, const ExploreResult& r, int actee) {
  // series[grasp]: the actee's series of that grasp, in grid order (placement, thumb).
  std::vector<std::vector<const SeriesResult*>> series(g.grasps.size());
  for (const SeriesResult& s : r.series) {
    if (s.key.actee == actee) series[static_cast<size_t>(s.key.grasp)].push_back(&s);
  }
  std::vector<std::vector<int>> groups;
  for (size_t k = 0; k < g.grasps.size(); ++k) {
    auto alike = [&](const std::vector<int>& group) {
      const auto& first = series[static_cast<size_t>(group.front())];
      if (first.size() != series[k].size()) return false;
      // Alike up to where either grasp's cap cuts the axis.
      for (double effort : g.actees[static_cast<size_t>(actee)].efforts) {
        if (applied_effort(g, group.front(), effort) != applied_effort(g, static_cast<int>(k), effort)) return false;
      }
      for (size_t i = 0; i < first.size(); ++i) {
        if (!same_map(*first[i], *series[k][i], g.tolerance)) return false;
      }
      return true;
    };
    auto it = std::find_if(groups.begin(), groups.end(), alike);
    if (it == groups.end()) {
      groups.push_back({static_cast<int>(k)});
    } else {
      it->push_back(static_cast<int>(k));
    }
  }
  return groups;
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
