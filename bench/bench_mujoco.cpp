// The baseline the frame time is measured against: one frame of the same
// session in MuJoCo, from the scene `afford export --mjcf` writes of it
// (mjcf/mjcf_scene.h, which says what each element stands for), run by the
// harness its header comment describes: the hand's commanded angle follows
// the script's schedule, the actee breaks at its limit. One iteration is one
// frame of the session (1 ms): `substeps` mj_step calls, as many as the
// actee's contact stiffness needs. Over and over through the session, as in
// BM_Frame; the scene is reset (outside the timing) at its end. Counters:
// contacts per step, and when the actee broke (s, 0: never), to set beside
// the engine's verdict. Built only when CMake finds MuJoCo.
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "files.h"
#include "mjcf_scene.h"
#include "session.h"

namespace afford {
namespace {

namespace fs = std::filesystem;

const std::string kSource = AFFORD_SOURCE_DIR;

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

// The session's scene, exported and loaded (through a temporary file:
// MuJoCo 2.2.2 reads XML from files).
std::unique_ptr<mjModel, ModelDeleter> load_scene(const CompiledSession& session) {
  const fs::path file =
      fs::temp_directory_path() / ("afford-bench-" + session.name + "-" + std::to_string(::getpid()) + ".xml");
  write_file_checked(file.string(), mjcf_scene(session));
  std::array<char, 1000> error{};
  mjModel* m = mj_loadXML(file.c_str(), nullptr, error.data(), static_cast<int>(error.size()));
  fs::remove(file);
  if (m == nullptr) throw std::runtime_error(session.name + ": " + error.data());
  return std::unique_ptr<mjModel, ModelDeleter>(m);
}

const mjtNum* numeric(const mjModel* m, const char* name) {
  const int id = mj_name2id(m, mjOBJ_NUMERIC, name);
  if (id < 0) throw std::runtime_error(std::string("the scene has no numeric ") + name);
  return m->numeric_data + m->numeric_adr[id];
}

// The commanded angle at t: the schedule (t, angle pairs) interpolated.
double scheduled(const mjtNum* schedule, int pairs, double t) {
  if (t <= schedule[0]) return schedule[1];
  for (int k = 1; k < pairs; ++k) {
    if (t <= schedule[2 * k]) {
      const double w = (t - schedule[2 * k - 2]) / (schedule[2 * k] - schedule[2 * k - 2]);
      return (1 - w) * schedule[2 * k - 1] + w * schedule[2 * k + 1];
    }
  }
  return schedule[2 * pairs - 1];
}

void BM_MujocoStep(benchmark::State& bench, const char* name) {
  const CompiledSession session = load_session(kSource + "/sessions/" + name + ".yaml");
  const auto m = load_scene(session);
  const std::unique_ptr<mjData, DataDeleter> d(mj_makeData(m.get()));
  const int hand = mj_name2id(m.get(), mjOBJ_ACTUATOR, "hand");
  const int actee_geom = mj_name2id(m.get(), mjOBJ_GEOM, "actee");
  const int arm = mj_name2id(m.get(), mjOBJ_BODY, "moving_arm");
  if (hand < 0 || actee_geom < 0) {
    bench.SkipWithError("the scene has no hand or no actee");
    return;
  }
  const int actee = m->geom_bodyid[actee_geom];
  const int hand_id = mj_name2id(m.get(), mjOBJ_NUMERIC, "hand_schedule");
  const mjtNum* schedule = m->numeric_data + m->numeric_adr[hand_id];
  const int pairs = m->numeric_size[hand_id] / 2;
  const int substeps = static_cast<int>(*numeric(m.get(), "substeps"));
  const double limit = *numeric(m.get(), "actee_limit");
  const bool breaks = *numeric(m.get(), "actee_breaks") != 0;
  const int affinity = m->geom_conaffinity[actee_geom];
  const double duration = schedule[2 * pairs - 2];  // s

  const auto restart = [&] {
    mj_resetDataKeyframe(m.get(), d.get(), 0);
    m->geom_conaffinity[actee_geom] = affinity;
  };
  restart();
  double broke_at = 0;  // s, in the last pass
  std::int64_t steps = 0, contacts = 0;
  for (auto _ : bench) {
    if (d->time >= duration) {
      bench.PauseTiming();
      restart();
      bench.ResumeTiming();
    }
    d->ctrl[hand] = scheduled(schedule, pairs, d->time);
    for (int s = 0; s < substeps; ++s) {
      mj_step(m.get(), d.get());
      contacts += d->ncon;
    }
    steps += substeps;
    // The actee's load: the normal force of its contacts with the moving arm.
    double load = 0;
    for (int i = 0; i < d->ncon; ++i) {
      const int b1 = m->geom_bodyid[d->contact[i].geom1], b2 = m->geom_bodyid[d->contact[i].geom2];
      if ((b1 == arm && b2 == actee) || (b1 == actee && b2 == arm)) {
        mjtNum f[6];
        mj_contactForce(m.get(), d.get(), i, f);
        load += f[0];
      }
    }
    if (breaks && load > limit && m->geom_conaffinity[actee_geom] != 0) {
      m->geom_conaffinity[actee_geom] = 0;
      broke_at = d->time;
    }
  }
  bench.counters["ncon"] = static_cast<double>(contacts) / static_cast<double>(std::max<std::int64_t>(steps, 1));
  bench.counters["substeps"] = substeps;
  bench.counters["broke_at_s"] = broke_at;
}

BENCHMARK_CAPTURE(BM_MujocoStep, paper_nutcracker, "paper-nutcracker");

}  // namespace
}  // namespace afford
