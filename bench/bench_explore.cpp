// afford explore's grid: simulated frames per second per core, and the
// scaling from one thread to two (Arg = threads; compare the two rows'
// frames_per_s side by side). The grid's points only, as `explore` runs
// them before its thresholds: every point is one whole generated session
// of point_duration() seconds, so the frames are counted exactly.
#include <benchmark/benchmark.h>

#include <cmath>

#include "bench_source.h"
#include "explore.h"
#include "parallel.h"
#include "results.h"

namespace afford {
namespace {

using bench::kSource;

const Explorer& nutcracker_grid() {
  static const Explorer e = [] {
    ExploreFiles f;
    f.object = kSource + "/objects/nutcracker.yaml";
    f.agent = kSource + "/agents/hand.yaml";
    f.rules = kSource + "/rules/functions.yaml";
    f.grasps = kSource + "/rules/grasps.yaml";
    for (const char* a : {"walnut", "hazelnut", "peanut", "pecan"}) f.actees.push_back(kSource + "/actees/" + a + ".yaml");
    GridOptions g;
    g.placements = 2;
    g.thumbs = 2;
    g.efforts = 4;
    g.grasps = {"medium_wrap", "tip_pinch"};
    return make_explorer(f, g);
  }();
  return e;
}

void BM_ExploreGrid(benchmark::State& bench) {
  const Explorer& e = nutcracker_grid();
  const int threads = static_cast<int>(bench.range(0));
  const std::vector<GridPoint> points = grid_points(e.grid);
  const double frames_per_point = std::floor(point_duration(e.timing) / e.models[0][0]->timestep + 1e-9);
  std::vector<PointResult> results(points.size());
  for (auto _ : bench) {
    parallel_for(points.size(), threads, [&](size_t i) { results[i] = run_point(e, points[i]); });
    benchmark::DoNotOptimize(results.data());
  }
  const double frames = frames_per_point * static_cast<double>(points.size() * bench.iterations());
  bench.counters["points"] = static_cast<double>(points.size());
  bench.counters["frames_per_s"] = benchmark::Counter(frames, benchmark::Counter::kIsRate);
  bench.counters["frames_per_s_per_thread"] =
      benchmark::Counter(frames / threads, benchmark::Counter::kIsRate);
}
// Wall time: with threads the process's CPU time would hide the scaling.
BENCHMARK(BM_ExploreGrid)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace afford
