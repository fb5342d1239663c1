// The baseline the frame time is measured against: one frame of the same
// session in MuJoCo, from the scene `afford export --mjcf` writes of it
// (mjcf/mjcf_scene.h, which says what each element stands for), run by the
// harness its header comment describes: the hand's commanded angle follows
// the script's schedule, the actee breaks at its limit. One iteration is one
// frame of the session (1 ms): `substeps` mj_step calls, as many as the
// actee's contact stiffness needs. Over and over through the session, as in
// BM_Frame; the scene is reset (outside the timing) at its end. Counters:
// contacts per step, and when the actee breaks in a whole pass of the
// session (s, 0: never; run once before the timing), to set beside the
// engine's verdict. Built only when CMake finds MuJoCo.
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

// The harness of the scene's header comment, one frame at a time.
class Harness {
 public:
  explicit Harness(const mjModel* m) {
    hand_ = mj_name2id(m, mjOBJ_ACTUATOR, "hand");
    actee_geom_ = mj_name2id(m, mjOBJ_GEOM, "actee");
    arm_ = mj_name2id(m, mjOBJ_BODY, "moving_arm");
    if (hand_ < 0 || actee_geom_ < 0) throw std::runtime_error("the scene has no hand or no actee");
    actee_ = m->geom_bodyid[actee_geom_];
    const int id = mj_name2id(m, mjOBJ_NUMERIC, "hand_schedule");
    schedule_ = m->numeric_data + m->numeric_adr[id];
    pairs_ = m->numeric_size[id] / 2;
    substeps_ = static_cast<int>(*numeric(m, "substeps"));
    limit_ = *numeric(m, "actee_limit");
    breaks_ = *numeric(m, "actee_breaks") != 0;
    affinity_ = m->geom_conaffinity[actee_geom_];
  }

  int substeps() const { return substeps_; }
  double duration() const { return schedule_[2 * pairs_ - 2]; }  // s

  void restart(mjModel* m, mjData* d) const {
    mj_resetDataKeyframe(m, d, 0);
    m->geom_conaffinity[actee_geom_] = affinity_;
  }

  // One frame; true when the actee broke in it. Adds the contacts of each
  // step to *contacts.
  bool frame(mjModel* m, mjData* d, std::int64_t* contacts) const {
    d->ctrl[hand_] = scheduled(schedule_, pairs_, d->time);
    for (int s = 0; s < substeps_; ++s) {
      mj_step(m, d);
      *contacts += d->ncon;
    }
    // The actee's load: the normal force of its contacts with the moving arm.
    double load = 0;
    for (int i = 0; i < d->ncon; ++i) {
      const int b1 = m->geom_bodyid[d->contact[i].geom1], b2 = m->geom_bodyid[d->contact[i].geom2];
      if ((b1 == arm_ && b2 == actee_) || (b1 == actee_ && b2 == arm_)) {
        mjtNum f[6];
        mj_contactForce(m, d, i, f);
        load += f[0];
      }
    }
    if (!breaks_ || load <= limit_ || m->geom_conaffinity[actee_geom_] == 0) return false;
    m->geom_conaffinity[actee_geom_] = 0;
    return true;
  }

 private:
  int hand_ = -1, actee_geom_ = -1, arm_ = -1, actee_ = -1, pairs_ = 0, substeps_ = 1, affinity_ = 0;
  const mjtNum* schedule_ = nullptr;
  double limit_ = 0;
  bool breaks_ = true;
};

void BM_MujocoStep(benchmark::State& bench, const char* name) {
  const CompiledSession session = load_session(kSource + "/sessions/" + name + ".yaml");
  const auto m = load_scene(session);
  const std::unique_ptr<mjData, DataDeleter> d(mj_makeData(m.get()));
  const Harness harness(m.get());
  std::int64_t contacts = 0;
  // One whole pass first, untimed: when the actee breaks (0: never).
  double broke_at = 0;  // s
  harness.restart(m.get(), d.get());
  while (d->time < harness.duration()) {
    if (harness.frame(m.get(), d.get(), &contacts)) broke_at = d->time;
  }
  harness.restart(m.get(), d.get());
  contacts = 0;
  std::int64_t frames = 0;
  for (auto _ : bench) {
    if (d->time >= harness.duration()) {
      bench.PauseTiming();
      harness.restart(m.get(), d.get());
      bench.ResumeTiming();
    }
    harness.frame(m.get(), d.get(), &contacts);
    ++frames;
  }
  const double steps = static_cast<double>(std::max<std::int64_t>(frames, 1) * harness.substeps());
  bench.counters["ncon"] = static_cast<double>(contacts) / steps;
  bench.counters["substeps"] = harness.substeps();
  bench.counters["broke_at_s"] = broke_at;
}

BENCHMARK_CAPTURE(BM_MujocoStep, paper_nutcracker, "paper-nutcracker");

}  // namespace
}  // namespace afford
