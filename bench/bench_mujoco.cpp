// The baseline the frame time is measured against: one MuJoCo step
// (mj_step) of the same nutcracker + walnut scene (nutcracker_walnut.xml,
// which says how it was built and which settings differ from MuJoCo's
// defaults), with the thumb squeezing and releasing as in BM_Frame: a
// triangle wave of 30 mm of thumb travel over 2000 frames, 1 ms a frame.
// Built only when CMake finds MuJoCo.
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

namespace afford {
namespace {

const std::string kSource = AFFORD_SOURCE_DIR;

constexpr double kRest = 0.5235987756;  // rad, the arm's and the thumb's rest angle (30 deg)
constexpr double kEffort = 0.17;        // m, where the thumb pushes: BM_Frame's effort distance

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

std::unique_ptr<mjModel, ModelDeleter> load_model(const std::string& path) {
  std::array<char, 1000> error{};
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error.data(), static_cast<int>(error.size()));
  if (m == nullptr) throw std::runtime_error(path + ": " + error.data());
  return std::unique_ptr<mjModel, ModelDeleter>(m);
}

void BM_MujocoStep(benchmark::State& bench, const char* scene) {
  const auto m = load_model(kSource + "/bench/" + scene + ".xml");
  const std::unique_ptr<mjData, DataDeleter> d(mj_makeData(m.get()));
  const int thumb = mj_name2id(m.get(), mjOBJ_ACTUATOR, "thumb");
  const int walnut = mj_name2id(m.get(), mjOBJ_JOINT, "walnut");
  if (thumb < 0 || walnut < 0) {
    bench.SkipWithError("the scene has no thumb actuator or no walnut joint");
    return;
  }
  const int qadr = m->jnt_qposadr[walnut];
  const int vadr = m->jnt_dofadr[walnut];
  d->ctrl[thumb] = kRest;
  mj_forward(m.get(), d.get());
  std::array<mjtNum, 7> walnut_rest{};
  std::copy_n(d->qpos + qadr, 7, walnut_rest.begin());
  std::int64_t frames = 0;
  std::int64_t contacts = 0;
  for (auto _ : bench) {
    // Squeeze slowly and release, over and over: free motion and contact.
    const std::int64_t frame = frames % 2000;
    if (frame == 0) {
      // Each squeeze starts with the walnut at rest on the fixed jaw (see
      // the scene file: with no gravity it drifts off between squeezes).
      std::copy(walnut_rest.begin(), walnut_rest.end(), d->qpos + qadr);
      std::fill_n(d->qvel + vadr, 6, 0.0);
    }
    const double phase = static_cast<double>(frame) / 1000.0;
    const double closing = 0.03 * (phase < 1 ? phase : 2 - phase);
    d->ctrl[thumb] = kRest - closing / kEffort;
    mj_step(m.get(), d.get());
    contacts += d->ncon;
    ++frames;
  }
  bench.counters["ncon"] =
      static_cast<double>(contacts) / static_cast<double>(std::max<std::int64_t>(frames, 1));
}

BENCHMARK_CAPTURE(BM_MujocoStep, nutcracker_walnut, "nutcracker_walnut");

}  // namespace
}  // namespace afford
