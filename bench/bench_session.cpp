// Whole shipped sessions: sessions per second (one core), and allocations
// per frame over the whole run (the run loop and the frame must add none).
#include <benchmark/benchmark.h>

#include "alloc_counter.h"
#include "bench_source.h"
#include "observer.h"
#include "run.h"
#include "scripted_agent.h"
#include "session.h"

namespace afford {
namespace {

using bench::kSource;

// Counts the allocations made from the end of the first frame to the end of
// the last: what the frames themselves allocate.
class AllocationProbe : public Observer {
 public:
  void on_frame(const Model&, const State&, const RuleSet&, const RuleState&) override {
    if (first_) start_ = allocation_count();
    first_ = false;
    last_ = allocation_count();
  }
  long during_frames() const { return last_ - start_; }

 private:
  bool first_ = true;
  long start_ = 0, last_ = 0;
};

void BM_Session(benchmark::State& bench, const char* name) {
  const CompiledSession session = load_session(kSource + "/sessions/" + name + ".yaml");
  std::int64_t frames = 0;
  long allocations = 0;
  for (auto _ : bench) {
    ScriptedAgent agent(session.script);
    AllocationProbe probe;
    Observer* const observers[] = {&probe};
    RunResult r = run_session(session, *session.rules, agent, observers);
    frames += r.frames;
    allocations += probe.during_frames();
    benchmark::DoNotOptimize(r);
  }
  bench.counters["frames"] = static_cast<double>(frames) / static_cast<double>(bench.iterations());
  bench.counters["sessions_per_s"] = benchmark::Counter(static_cast<double>(bench.iterations()), benchmark::Counter::kIsRate);
  bench.counters["frames_per_s"] = benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
  bench.counters["allocs_per_frame"] = static_cast<double>(allocations) / static_cast<double>(frames);
}

BENCHMARK_CAPTURE(BM_Session, paper_tongs, "paper-tongs")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Session, paper_nutcracker, "paper-nutcracker")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Session, sponge_tongs, "sponge-tongs")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Session, too_large, "too-large")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Session, push_without_grasp, "push-without-grasp")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace afford
