// Offscreen rendering of one frame of a session with OSMesa (no display, no
// GPU) and legacy fixed-function OpenGL: the acting object at its angle with
// every part, the actee in its file's colours (intact; squeezed: flattened
// along its force direction by its compression and tinted by its load;
// broken: as its file's look says, in halves, crushed or in shards, the
// inside showing), the fingertips and a translucent hand, contact points,
// and force arrows whose lengths scale with the force.
//
// Determinism: identical input gives identical pixels. Mesa's llvmpipe is
// told to rasterise in the calling thread, with no shader cache on disk
// (LP_NUM_THREADS=0 and MESA_SHADER_CACHE_DISABLE=true, set with setenv
// before the first context unless the environment already sets them).
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <stdexcept>

#include "guides.h"
#include "image.h"
#include "model.h"
#include "state.h"

namespace afford::render {

struct RenderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Camera {
  Eigen::Vector3d position = Eigen::Vector3d(0, -0.5, 0.5);  // m, world: the eye
  Eigen::Vector3d target = Eigen::Vector3d::Zero();          // m, world: looked at
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();              // world
  double fov = 0.6981317007977318;                            // rad, vertical (40 deg)
  bool operator==(const Camera&) const = default;
};

struct RenderOptions {
  int width = 640, height = 480;  // pixels of the image returned
  int supersample = 2;            // rendered at this many times the size, then averaged (anti-aliasing)
  bool hand = true;               // the translucent palm and fingers (fingertips are always drawn)
  bool contacts = true;           // contact point markers
  bool forces = true;             // force arrows
  bool ground = true;             // a grid under the scene
  double force_scale = 0;         // m of arrow per N; 0: from the scene (see force_scale())
  double ground_z = 0;            // m, world height of the grid (frame_scene sets it)
  // The guides (guides/guides.h) to draw over the scene, posed with the
  // arm: surfaces translucent, the advantage map as coloured lines, the
  // labels as text. Not owned; nullptr: none.
  const Guides* guides = nullptr;
};

// The camera's up, or another when it is parallel to the view.
Eigen::Vector3d usable_up(const Camera& camera);

// World box of the tool (every part at the state's angle) and the actee.
Eigen::AlignedBox3d scene_box(const Model& model, const State& state);

// A camera that frames `box` (m, world): looks at its centre from above the
// tool's pivot axis, turned a little toward the fixed arm's outer side so
// that the arms' faces show, far enough back for the whole box to fit at
// aspect (width / height) >= 1.
Camera frame_scene(const Model& model, const Eigen::AlignedBox3d& box, double aspect);

// Arrow length per newton: 90 % of the box's half-diagonal at the larger of
// the actee's limit and the hand's largest force (arrows are drawn at least
// 8 % of it long, so that a small force still shows).
double force_scale(const Model& model, const Eigen::AlignedBox3d& box);

// Where a world point lands in an image of w x h pixels: x right, y down
// from the top-left corner, in pixels.
Eigen::Vector2d project(const Camera& camera, int w, int h, const Eigen::Vector3d& world);

// The RGB an actee without a `look` is drawn with before lighting (intact
// and unloaded), and the one the model's actee is drawn with (its look).
Rgb actee_base_colour();
Rgb actee_colour(const Model& model);

// Owns one OSMesa context and its buffer. Not thread-safe: one per thread.
class Renderer {
 public:
  Renderer();  // throws RenderError when OSMesa cannot create a context
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  Image render(const Model& model, const State& state, const Camera& camera, const RenderOptions& options);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace afford::render
