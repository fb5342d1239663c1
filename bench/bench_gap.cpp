// One gap diagnosis of a 10 s trace at 1 kHz with the whole library, pairs
// included (forward selection goes on to a second effect here): the
// nutcracker swept through a 1 Hz sine with 0.3 N*m of hidden friction and
// 0.05 N*m*s/rad of hidden damping, written by formulas (not the solver).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "diagnose.h"

namespace afford {
namespace {

const std::string kSource = AFFORD_SOURCE_DIR;

std::string write_case() {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("afford-bench-gap-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::ofstream csv(dir / "trace.csv");
  csv << "t,angle,effort_force,actee_force\n";
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < 10000; ++i) {
    const double t = i * 1e-3, w = 2 * pi;
    const double theta = (18 + 10 * std::sin(w * t)) * pi / 180;
    const double omega = 10 * pi / 180 * w * std::cos(w * t);
    const double spring = 2000 * 0.01 * (30 * pi / 180 - theta) * 0.01 + 1.5 * 0.01;
    const double torque = spring - 0.31 * (omega > 0 ? 1 : -1) - 0.05 * omega;
    char row[96];
    std::snprintf(row, sizeof row, "%.3f,%.9f,%.6f,0\n", t, theta, torque / 0.16 + noise(random));
    csv << row;
  }
  std::ofstream(dir / "m.yaml") << "measurement: bench\nobject: " << kSource
                                << "/objects/nutcracker.yaml\neffort_at: 160 mm\ntrace: trace.csv\n";
  return (dir / "m.yaml").string();
}

void BM_GapDiagnosis(benchmark::State& bench) {
  const Measurement m = load_measurement(write_case());
  Verdict verdict = Verdict::none;
  size_t effects = 0;
  for (auto _ : bench) {
    const Diagnosis d = diagnose(m);
    verdict = d.verdict;
    effects = d.effects.size();
    benchmark::DoNotOptimize(d.shrink);
  }
  bench.counters["samples"] = static_cast<double>(m.traces.front().size());
  bench.counters["effects_found"] = static_cast<double>(effects);
  bench.SetLabel(verdict_name(verdict));
}
BENCHMARK(BM_GapDiagnosis)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace afford
