// afford render SESSION [--out DIR] [--fps N] [--size WxH] [--guides [FILE]]
// [--no-frames]: renders a session offscreen (OSMesa): PNG frames at N per
// second of session time (default 30), a contact sheet of the key moments,
// the timeline plot (PNG and SVG) and, when ffmpeg is on PATH, an MP4.
// --guides draws the guides of FILE (default: guides.yaml beside the
// session's function models, else the shipped rules/guides.yaml) in every
// picture.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include <filesystem>

#include "commands.h"
#include "data_dir.h"
#include "option_checks.h"
#include "output_file.h"
#include "progress.h"
#include "scripted_agent.h"
#include "derive.h"
#include "guides.h"
#include "session.h"
#include "session_render.h"

namespace afford::cli {

namespace {

// guides.yaml in the folder of a file the session read (its rules/ folder),
// else the shipped one (data_dir.h).
std::string default_guides(const CompiledSession& s) {
  namespace fs = std::filesystem;
  for (const std::string& f : s.files) {
    const fs::path p = fs::path(f).parent_path() / "guides.yaml";
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) return p.string();
  }
  return shipped_path("rules/guides.yaml");
}

struct RenderOptions {
  std::string file, guides_file, size;
  bool guides = false, no_frames = false, force = false;
  render::RenderSessionOptions o;
};

// A render of more frames than this says so before it starts.
constexpr double kAnnouncedFrames = 1000;

int render_command(RenderOptions ro) {
  render::RenderSessionOptions& o = ro.o;
  const std::string& file = ro.file;
  std::string& guides_file = ro.guides_file;
  read_size(ro.size, &o.width, &o.height);
  const CompiledSession session = load_session(file);  // DataError: file:line:col, exit 1
  if (o.out_dir.empty()) o.out_dir = "out/" + session.name + "/render";
  Guides computed;
  if (ro.guides && guides_file.empty()) guides_file = default_guides(session);
  std::vector<std::string> inputs = session.files;
  if (ro.guides) inputs.push_back(guides_file);
  const OutputScope scope({.writer = "render", .force = ro.force, .inputs = inputs});
  for (const char* name : {"contact_sheet.png", "timeline.png", "timeline.svg", "session.mp4"}) {
    if (!(o.frames && o.mp4) && std::string(name) == "session.mp4") continue;  // no MP4 to write
    check_output((std::filesystem::path(o.out_dir) / name).string());  // refused now, not after the frames
  }
  const double frames = std::floor(ScriptedAgent(session.script).duration() * o.fps + 1e-9) + 1;
  if (o.frames && frames > kAnnouncedFrames) {
    std::fprintf(stderr, "render: %.0f frames of %dx%d to draw; progress on stderr\n", frames, o.width, o.height);
  }
  if (ro.guides) {
    std::vector<ActeeFit> fits;
    if (session.model.has_actee) fits.push_back(fit_actee(session.model));
    computed = compute_guides(session.model, load_guides(guides_file), fits);
    o.guides = &computed;
    std::printf("guides from %s: %zu drawn\n", guides_file.c_str(), computed.guides.size());
  }
  render::RenderSessionResult r;
  {
    TerminalProgress progress;
    o.progress = [&progress](int done, int total) { progress.update(done, total); };
    r = render::render_session(session, o);
  }
  clear_stale_outputs(o.out_dir);  // what an earlier render wrote there and this one did not
  std::printf("session %s: %d frames at %g fps, %dx%d, in %s\n", session.name.c_str(), r.frames, o.fps, o.width,
              o.height, o.out_dir.c_str());
  std::printf("key moments (contact_sheet.png):\n");
  for (const render::KeyMoment& k : r.moments) std::printf("  %8.3f s  %s\n", k.t, k.what.c_str());
  std::printf("wrote contact_sheet.png, timeline.png, timeline.svg%s\n",
              r.files.empty() || r.files.back().ends_with(".mp4") ? ", session.mp4" : "");
  if (!r.note.empty()) std::printf("%s\n", r.note.c_str());
  return 0;
}

}  // namespace

void add_render(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "render", "render a session offscreen: PNG frames, contact sheet, timeline plot, MP4 with ffmpeg");
  auto r = std::make_shared<RenderOptions>();
  cmd->add_option("SESSION", r->file, "a session file (sessions/*.yaml), required")->type_name(kFile);
  cmd->add_option("--out", r->o.out_dir, "the folder of the pictures (default out/<session>/render)")
      ->type_name(kDir);
  cmd->add_option("--fps", r->o.fps, "frames per second of session time, up to 1000")
      ->type_name("N")
      ->check(frames_per_second())
      ->capture_default_str();
  r->size = std::to_string(r->o.width) + "x" + std::to_string(r->o.height);
  cmd->add_option("--size", r->size, "picture size in pixels, from 64x48 to 3840x2160")
      ->type_name("WxH")
      ->check(picture_size())->capture_default_str();
  cmd->add_option("--guides", r->guides_file,
                  "draw the guides of FILE (default: guides.yaml beside the session's function models)")
      ->expected(0, 1)
      ->type_name(kFile);
  cmd->add_flag("--no-frames", r->no_frames, "write the contact sheet and the plots, not the frames");
  cmd->add_flag("--force", r->force, "replace existing files in the folder that afford did not write");
  cmd->callback([run, r, cmd] {
    r->guides = cmd->count("--guides") > 0;
    r->o.frames = !r->no_frames;
    // "render --guides S.yaml": the file was the session, not guides.
    if (r->file.empty()) std::swap(r->file, r->guides_file);
    if (r->file.empty()) throw CLI::RequiredError("SESSION");
    *run = [r] { return render_command(*r); };
  });
}

}  // namespace afford::cli
