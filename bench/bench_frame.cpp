// One frame of the paper's scenes (contacts, solver, rules), timed over the
// frames of the shipped sessions, and the allocations per frame, which
// must be zero.
#include <benchmark/benchmark.h>

#include "alloc_counter.h"
#include "bench_source.h"
#include "rules.h"
#include "scripted_agent.h"
#include "session.h"
#include "state.h"

namespace afford {
namespace {

using bench::kSource;

// Steps through every frame of a session, over and over (the state is reset
// between passes, outside the timing and the allocation count).
void BM_Frame(benchmark::State& bench, const char* name) {
  const CompiledSession session = load_session(kSource + "/sessions/" + name + ".yaml");
  const Model& model = session.model;
  const std::vector<Sample> samples = script_samples(session.script, model.timestep);
  auto state = make_state(model);
  auto rules = make_rule_state(*session.rules);
  size_t next = 0;
  long allocations = 0;
  for (auto _ : bench) {
    if (next == samples.size()) {
      bench.PauseTiming();
      reset(model, *state);
      reset(*session.rules, *rules);
      next = 0;
      bench.ResumeTiming();
    }
    const long before = allocation_count();
    step(model, *state, samples[next++]);
    evaluate(*session.rules, *rules, model, *state);
    allocations += allocation_count() - before;
  }
  bench.counters["allocs_per_frame"] =
      static_cast<double>(allocations) / static_cast<double>(std::max<std::int64_t>(bench.iterations(), 1));
  bench.counters["frames_in_session"] = static_cast<double>(samples.size());
}

BENCHMARK_CAPTURE(BM_Frame, paper_nutcracker, "paper-nutcracker");
BENCHMARK_CAPTURE(BM_Frame, paper_tongs, "paper-tongs");
BENCHMARK_CAPTURE(BM_Frame, sponge_tongs, "sponge-tongs");

}  // namespace
}  // namespace afford

BENCHMARK_MAIN();
