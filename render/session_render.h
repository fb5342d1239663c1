// `afford render`: a whole session to pictures. Runs the session twice
// (deterministic, so both runs are the same): first to find the box the
// tool and the actee sweep (the default camera frames all of it), then to
// render frames at a fixed rate with their text in bars around the scene
// (frame_overlay.h), the key moments (the
// start, each inferred function, each change of the number of tool-actee
// contacts, the break) into a contact sheet, and the timeline plot.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "frame_overlay.h"
#include "image.h"
#include "scene.h"
#include "session.h"

namespace afford::render {

struct RenderSessionOptions {
  std::string out_dir;        // created if missing
  double fps = 30;            // frames per second of session time
  int width = 640, height = 480;
  int supersample = 2;
  bool frames = true;         // write frame_NNNNN.png
  bool mp4 = true;            // and session.mp4 through ffmpeg, when on PATH
  int max_moments = 16;       // tiles on the contact sheet
  const Guides* guides = nullptr;  // drawn in every picture when set (not owned)
  // Draws extra content into each rendered scene picture (a frame's is the
  // part between its bars), after the scene: given the image, the camera
  // and the state.
  std::function<void(Image&, const Camera&, const State&)> overlay;
  // Called after each PNG frame is written with the frames done and the
  // frames the session will have (for progress on a terminal).
  std::function<void(int done, int total)> progress;
};

struct KeyMoment {
  double t = 0;       // s
  std::string what;   // "pinch inferred", "actee contacts 0 -> 2", "walnut broke"; moments of one frame joined by ", "
  Image tile;
};

struct RenderSessionResult {
  int frames = 0;                  // PNG frames written
  std::vector<KeyMoment> moments;  // on the contact sheet, in time order
  std::vector<std::string> files;  // every file written
  std::string note;                // e.g. why there is no MP4
};

RenderSessionResult render_session(const CompiledSession& session, const RenderSessionOptions& options);

// The camera render_session uses: the session's `camera:` if given, else
// one that frames everything the tool and the actee sweep in the session;
// `ground_z` gets the height of the grid under it (m, world).
Camera session_camera(const CompiledSession& session, double aspect, double* ground_z);

// How render_session lays out a session's frames of width x height px: the
// bars and the scene between them (frame_overlay.h), the scene's camera,
// the contact sheet tiles' camera (no bars) and the ground's height (m).
struct FramePlan {
  FrameLayout layout;
  Camera camera, tile_camera;
  double ground_z = 0;
};
FramePlan plan_frames(const CompiledSession& session, int width, int height);

// Whether an executable is on PATH.
bool on_path(const std::string& program);

}  // namespace afford::render
