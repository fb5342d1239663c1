// One frame of the shipped scenes (contacts, solver), and allocations per
// frame, which must be zero.
#include <benchmark/benchmark.h>

#include <cmath>

#include "alloc_counter.h"
#include "load.h"
#include "model.h"
#include "rules.h"
#include "state.h"

namespace afford {
namespace {

const std::string kSource = AFFORD_SOURCE_DIR;

struct Scene {
  Model model;
  double effort;  // m, where the thumb pushes
};

Scene make_scene(const char* tool, const char* actee) {
  const ObjectSpec o = load_object(kSource + "/objects/" + tool + ".yaml");
  const ActeeSpec a = load_actee(kSource + "/actees/" + actee + ".yaml");
  const AgentSpec h = load_agent(kSource + "/agents/hand.yaml");
  ModelOptions options;
  options.actee.distance = o.application.to - 0.1 * (o.application.to - o.application.from);
  return {compile(o, &a, &h, options), std::abs(o.emphasis.to) > std::abs(o.emphasis.from) ? o.emphasis.to - 0.01 : o.emphasis.from + 0.01};
}

// The thumb on the moving arm's outer face, the index on the fixed arm.
Sample grasp_sample(const Model& m, const State& s, double effort, double closing_m) {
  Sample sample;
  const double side = effort > 0 ? 1.0 : -1.0;
  const double reach = side * (0.006 + m.tip_radius[0] - 1e-4);
  const double angle = s.theta - closing_m / std::abs(effort);
  const Eigen::Vector3d thumb(std::cos(angle) * effort - std::sin(angle) * reach,
                              std::sin(angle) * effort + std::cos(angle) * reach, 0);
  sample.fingertip[0] = m.object_start * thumb;
  sample.fingertip[1] = m.object_start * Eigen::Vector3d(effort, -side * (0.006 + m.tip_radius[1] - 1e-4), 0);
  for (size_t f = 2; f < kFingers; ++f) sample.fingertip[f] = Eigen::Vector3d(0, 0, 2.0);
  return sample;
}

// One frame: contacts, solver and the shipped function models.
void BM_Frame(benchmark::State& bench, const char* tool, const char* actee) {
  const Scene scene = make_scene(tool, actee);
  const auto rules = load_rules(kSource + "/rules/functions.yaml");
  auto rule_state = make_rule_state(*rules);
  auto state = make_state(scene.model);
  Sample sample = grasp_sample(scene.model, *state, scene.effort, 0);
  step(scene.model, *state, sample);
  const long before = allocation_count();
  std::int64_t frames = 0;
  for (auto _ : bench) {
    // Squeeze slowly and release, over and over: free motion and contact.
    const double phase = static_cast<double>(frames % 2000) / 1000.0;
    const double closing = 0.03 * (phase < 1 ? phase : 2 - phase);
    sample = grasp_sample(scene.model, *state, scene.effort, closing);
    sample.t = static_cast<double>(frames + 2) * scene.model.timestep;
    step(scene.model, *state, sample);
    evaluate(*rules, *rule_state, scene.model, *state);
    ++frames;
  }
  bench.counters["allocs_per_frame"] =
      static_cast<double>(allocation_count() - before) / static_cast<double>(std::max<std::int64_t>(frames, 1));
  bench.counters["grasped"] = state->grasped ? 1 : 0;
  bench.counters["inferences"] = static_cast<double>(inferences(*rules, *rule_state).size());
}

BENCHMARK_CAPTURE(BM_Frame, nutcracker_walnut, "nutcracker", "walnut");
BENCHMARK_CAPTURE(BM_Frame, tongs_egg, "tongs", "egg");
BENCHMARK_CAPTURE(BM_Frame, pliers_hazelnut, "pliers", "hazelnut");

}  // namespace
}  // namespace afford

BENCHMARK_MAIN();
