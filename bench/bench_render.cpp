// Rendering speed (render/): frames per second of a typical scene, the
// nutcracker mid-squeeze with the hand, contacts and force arrows, at
// 640x480 and 1280x720, with and without 2x supersampling (the default of
// `afford render`). The "fps" counter is the rate; each frame includes
// reading the pixels back and the supersampling average. BM_RenderAndWrite
// is what `afford render` does per frame: the picture and its PNG file
// (libdeflate level 1; the goal is 60 frames/s at 640x480, 2x, on one core).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "png.h"
#include "scene.h"
#include "scripted_agent.h"
#include "session.h"

namespace {

using namespace afford;

struct Scene {
  CompiledSession session;
  std::unique_ptr<State> state;
  render::Camera camera;
};

const Scene& scene() {
  static const Scene kScene = [] {
    Scene s{load_session(std::string(AFFORD_SOURCE_DIR) + "/sessions/paper-nutcracker.yaml"), nullptr, {}};
    s.state = make_state(s.session.model);
    ScriptedAgent agent(s.session.script);
    Sample sample;
    for (int k = 1; k <= 2000; ++k) {  // to 2 s: the walnut squeezed
      agent.sample_at(k * s.session.model.timestep, &sample);
      sample.t = k * s.session.model.timestep;
      step(s.session.model, *s.state, sample);
    }
    s.camera = render::frame_scene(s.session.model, render::scene_box(s.session.model, *s.state), 4.0 / 3);
    return s;
  }();
  return kScene;
}

void BM_Render(benchmark::State& bs) {
  const Scene& s = scene();
  render::Renderer renderer;
  render::RenderOptions o;
  o.width = static_cast<int>(bs.range(0));
  o.height = static_cast<int>(bs.range(1));
  o.supersample = static_cast<int>(bs.range(2));
  o.ground_z = 0.09;
  for (auto _ : bs) {
    render::Image img = renderer.render(s.session.model, *s.state, s.camera, o);
    benchmark::DoNotOptimize(img.rgb.data());
  }
  bs.counters["fps"] = benchmark::Counter(static_cast<double>(bs.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Render)
    ->ArgNames({"w", "h", "ss"})
    ->Args({640, 480, 1})
    ->Args({640, 480, 2})
    ->Args({1280, 720, 1})
    ->Args({1280, 720, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_RenderAndWrite(benchmark::State& bs) {
  const Scene& s = scene();
  render::Renderer renderer;
  render::RenderOptions o;
  o.ground_z = 0.09;  // 640x480, 2x supersampling: the defaults of `afford render`
  const std::string path = (std::filesystem::temp_directory_path() / "afford-bench-frame.png").string();
  for (auto _ : bs) render::write_png(path, renderer.render(s.session.model, *s.state, s.camera, o));
  bs.counters["fps"] = benchmark::Counter(static_cast<double>(bs.iterations()), benchmark::Counter::kIsRate);
  bs.counters["png_bytes"] = static_cast<double>(std::filesystem::file_size(path));
  std::filesystem::remove(path);
}
BENCHMARK(BM_RenderAndWrite)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
