// One gap diagnosis of a 10 s trace at 1 kHz with the whole library, pairs
// included (forward selection goes on to a second effect here; with a
// detent outside the library, to the end and then through every pair): the
// nutcracker swept through a 1 Hz sine with 0.3 N*m of hidden friction and
// 0.05 N*m*s/rad of hidden damping, written by formulas (not the solver).
// With an actee the library adds actee_compliance, whose exponent is
// searched: the walnut at 60 mm squeezed about its contact at 1 Hz, its
// law a power of 1.5 and the pivot's friction 0.05 N*m more than nominal.
// Where the fits leave a gap and the turns ask for an inertia, the
// measurement is diagnosed a second time with it in the model.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "bench_source.h"
#include "diagnose.h"
#include "state.h"

namespace afford {
namespace {

using bench::kSource;

// `detent` (N*m): a bump of that height about 18 deg, 2 deg wide, in place
// of the friction and damping: outside the library, so that nothing
// explains it, forward selection runs its course and every pair is tried
// for the smallest set that explains (the slowest path).
std::string write_case(double detent = 0) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() /
                       ("afford-bench-gap-" + std::string(detent > 0 ? "detent-" : "") + std::to_string(::getpid()));
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
    const double bump = (theta - 18 * pi / 180) / (2 * pi / 180);
    const double torque = detent > 0 ? spring - 0.01 * (omega > 0 ? 1 : -1) + detent * std::exp(-0.5 * bump * bump)
                                     : spring - 0.31 * (omega > 0 ? 1 : -1) - 0.05 * omega;
    char row[96];
    std::snprintf(row, sizeof row, "%.3f,%.9f,%.6f,0\n", t, theta, torque / 0.16 + noise(random));
    csv << row;
  }
  std::ofstream(dir / "m.yaml") << "measurement: bench\nobject: " << kSource
                                << "/objects/nutcracker.yaml\neffort_at: 160 mm\ntrace: trace.csv\n";
  return (dir / "m.yaml").string();
}

std::string write_actee_case() {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("afford-bench-gap-actee-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string head = "measurement: bench\nobject: " + kSource + "/objects/nutcracker.yaml\nactee: {file: " +
                           kSource + "/actees/walnut.yaml, at: 60 mm}\neffort_at: 160 mm\ntrace: trace.csv\n";
  {  // a placeholder trace, to compile the model and find the contact
    std::ofstream csv(dir / "trace.csv");
    csv << "t,angle,effort_force,actee_force\n";
    for (int i = 0; i < 60; ++i) csv << i * 1e-3 << ",0.3,0,0\n";
  }
  std::ofstream(dir / "m.yaml") << head;
  const Model model = compile_measurement(load_measurement((dir / "m.yaml").string()));
  const auto state = make_state(model);
  const double a = 0.060, h = state->actee_thickness, theta_c = state->contact_angle;
  const double k = 250e3, limit = 378, reference = limit / k, pi = 3.14159265358979323846;
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.02), angle_noise(0.0, 1e-4);
  std::ofstream csv(dir / "trace.csv");
  csv << "t,angle,effort_force,actee_force\n";
  for (int i = 0; i < 10000; ++i) {
    const double t = i * 1e-3, w = 2 * pi;
    const double theta = theta_c + 0.6 * reference / a * std::sin(w * t);
    const double omega = 0.6 * reference / a * w * std::cos(w * t);
    const double d = std::max(0.0, a * (theta_c - theta));
    const double force = d > 0 ? k * reference * std::pow(d / reference, 1.5) * h / (h - d) : 0.0;
    const double spring = 2000 * 0.01 * (30 * pi / 180 - theta) * 0.01 + 1.5 * 0.01;
    const double torque = spring + force * a - 0.06 * (omega > 0 ? 1 : -1);
    char row[128];
    std::snprintf(row, sizeof row, "%.3f,%.9f,%.6f,%.3f\n", t, theta + angle_noise(random), torque / 0.16 + noise(random),
                  force);
    csv << row;
  }
  return (dir / "m.yaml").string();
}

// An arm with 0.004 kg*m^2 the file lacks, in strokes of 20 deg at an even
// 0.4 rad/s turned about in 50 ms, the angle read to 3e-4 rad: the fits
// leave a gap, and the inertia the turns ask for is judged again in the
// model (the diagnosis run twice: the slowest path where it is taken).
std::string write_turns_case() {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("afford-bench-gap-turns-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.02), angle_noise(0.0, 3e-4);
  std::ofstream csv(dir / "trace.csv");
  csv << "t,angle,effort_force,actee_force\n";
  const double pi = 3.14159265358979323846, deg = pi / 180;
  const double speed = 0.4, turn = 0.05, w = pi / turn;  // rad/s, s, rad/s
  const double x0 = 8 * deg + speed / w, x1 = 28 * deg - speed / w, stroke = (x1 - x0) / speed;
  for (int i = 0; i < 10000; ++i) {
    const double t = i * 1e-3;
    double u = std::fmod(t, 2 * (stroke + turn)), theta = 0, alpha = 0, omega = 0;
    if (u < stroke) {
      theta = x1 - speed * u, omega = -speed;
    } else if ((u -= stroke) < turn) {
      theta = x0 - speed / w * std::sin(w * u), omega = -speed * std::cos(w * u), alpha = speed * w * std::sin(w * u);
    } else if ((u -= turn) < stroke) {
      theta = x0 + speed * u, omega = speed;
    } else {
      u -= stroke;
      theta = x1 + speed / w * std::sin(w * u), omega = speed * std::cos(w * u), alpha = -speed * w * std::sin(w * u);
    }
    const double spring = 2000 * 0.01 * (30 * deg - theta) * 0.01 + 1.5 * 0.01;
    const double torque = spring - 0.01 * (omega > 0 ? 1 : -1) - 0.004 * alpha;
    char row[96];
    std::snprintf(row, sizeof row, "%.3f,%.9f,%.6f,0\n", t, theta + angle_noise(random), torque / 0.16 + noise(random));
    csv << row;
  }
  std::ofstream(dir / "m.yaml") << "measurement: bench\nobject: " << kSource
                                << "/objects/nutcracker.yaml\neffort_at: 160 mm\ntrace: trace.csv\n";
  return (dir / "m.yaml").string();
}

// Diagnoses the measurement in `file` once per iteration.
void diagnose_each_time(benchmark::State& bench, const std::string& file) {
  const Measurement m = load_measurement(file);
  Verdict verdict = Verdict::none;
  size_t effects = 0;
  bool judged_again = false;
  for (auto _ : bench) {
    const Diagnosis d = diagnose(m);
    verdict = d.verdict;
    effects = d.effects.size();
    judged_again = std::any_of(d.steps.begin(), d.steps.end(),
                               [](const std::string& s) { return s.find("judged again") != std::string::npos; });
    benchmark::DoNotOptimize(d.shrink);
  }
  bench.counters["samples"] = static_cast<double>(m.traces.front().size());
  bench.counters["effects_found"] = static_cast<double>(effects);
  bench.counters["judged_again"] = judged_again ? 1 : 0;
  bench.SetLabel(verdict_name(verdict));
}

void BM_GapDiagnosis(benchmark::State& bench) { diagnose_each_time(bench, write_case()); }
void BM_GapDiagnosisWithActee(benchmark::State& bench) { diagnose_each_time(bench, write_actee_case()); }
void BM_GapDiagnosisUnexplained(benchmark::State& bench) { diagnose_each_time(bench, write_case(0.05)); }
void BM_GapDiagnosisJudgedAgain(benchmark::State& bench) { diagnose_each_time(bench, write_turns_case()); }
BENCHMARK(BM_GapDiagnosisUnexplained)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GapDiagnosisJudgedAgain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GapDiagnosisWithActee)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GapDiagnosis)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace afford
