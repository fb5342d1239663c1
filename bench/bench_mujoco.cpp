// The baseline the frame time is measured against: one frame of the same
// session in MuJoCo, from the scene `afford export --mjcf` writes of it
// (mjcf/mjcf_scene.h, which says what each element stands for), run by the
// harness its header comment describes (mjcf/mujoco_harness.h): the hand's
// commanded angle follows the script's schedule, the actee breaks at its
// limit. One iteration is one frame of the session (1 ms): `substeps`
// mj_step calls, as many as the actee's contact stiffness needs. Over and
// over through the session, as in BM_Frame; the scene is reset (outside the
// timing) at its end. Counters: contacts at the end of a frame, and when the actee
// breaks in a whole pass of the session (s, 0: never; run once before the
// timing), to set beside the engine's verdict. Built only when CMake finds
// MuJoCo.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "bench_source.h"
#include "mujoco_harness.h"
#include "session.h"

namespace afford {
namespace {

using bench::kSource;

void BM_MujocoStep(benchmark::State& bench, const char* name) {
  const CompiledSession session = load_session(kSource + "/sessions/" + name + ".yaml");
  MujocoScene scene(session);
  // One whole pass first, untimed: when the actee breaks.
  double broke_at = 0;  // s
  while (scene.data()->time < scene.duration()) {
    if (scene.frame()) broke_at = scene.data()->time;
  }
  scene.restart();
  std::int64_t frames = 0, contacts = 0;
  for (auto _ : bench) {
    if (scene.data()->time >= scene.duration()) {
      bench.PauseTiming();
      scene.restart();
      bench.ResumeTiming();
    }
    scene.frame();
    contacts += scene.data()->ncon;
    ++frames;
  }
  bench.counters["ncon"] = static_cast<double>(contacts) / static_cast<double>(std::max<std::int64_t>(frames, 1));
  bench.counters["substeps"] = scene.substeps();
  bench.counters["broke_at_s"] = broke_at;
}

BENCHMARK_CAPTURE(BM_MujocoStep, paper_nutcracker, "paper-nutcracker");

}  // namespace
}  // namespace afford
