// afford render SESSION [--out DIR] [--fps N] [--size WxH] [--guides [FILE]]
// [--no-frames]: renders a session offscreen (OSMesa): PNG frames at N per
// second of session time (default 30), a contact sheet of the key moments,
// the timeline plot (PNG and SVG) and, when ffmpeg is on PATH, an MP4.
// --guides draws the guides of FILE (default: guides.yaml beside the
// session's function models, else the shipped rules/guides.yaml) in every
// picture.
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include <filesystem>

#include "commands.h"
#include "data_dir.h"
#include "progress.h"
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

}  // namespace

int run_render(const Args& args) {
  std::string file, guides_file;
  bool guides = false;
  render::RenderSessionOptions o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--out") {
      if (i + 1 >= args.size()) return usage_error("--out needs a DIR");
      o.out_dir = args[++i];
    } else if (a == "--fps") {
      if (i + 1 >= args.size()) return usage_error("--fps needs a number");
      char* end = nullptr;
      o.fps = std::strtod(args[++i].c_str(), &end);
      if (end == args[i].c_str() || *end != '\0' || !(o.fps > 0) || o.fps > 1000) {
        return usage_error("--fps needs a number of frames per second in (0, 1000], found '" + args[i] + "'");
      }
    } else if (a == "--size") {
      if (i + 1 >= args.size()) return usage_error("--size needs WxH");
      int w = 0, h = 0;
      char tail = 0;
      if (std::sscanf(args[++i].c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 64 || h < 48 || w > 3840 ||
          h > 2160) {
        return usage_error("--size needs WxH between 64x48 and 3840x2160, found '" + args[i] + "'");
      }
      o.width = w;
      o.height = h;
    } else if (a == "--guides") {
      guides = true;
      if (i + 1 < args.size() && args[i + 1].ends_with(".yaml") && !file.empty()) guides_file = args[++i];
    } else if (a == "--no-frames") {
      o.frames = false;
    } else if (!a.empty() && a[0] == '-') {
      return usage_error("render: unknown option '" + a + "'");
    } else if (file.empty()) {
      file = a;
    } else {
      return usage_error("render takes one SESSION file");
    }
  }
  if (file.empty()) return usage_error("render needs a SESSION file");
  const CompiledSession session = load_session(file);  // DataError: file:line:col, exit 1
  if (o.out_dir.empty()) o.out_dir = "out/" + session.name + "/render";
  Guides computed;
  if (guides) {
    if (guides_file.empty()) guides_file = default_guides(session);
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
  std::printf("session %s: %d frames at %g fps, %dx%d, in %s\n", session.name.c_str(), r.frames, o.fps, o.width,
              o.height, o.out_dir.c_str());
  std::printf("key moments (contact_sheet.png):\n");
  for (const render::KeyMoment& k : r.moments) std::printf("  %8.3f s  %s\n", k.t, k.what.c_str());
  std::printf("wrote contact_sheet.png, timeline.png, timeline.svg%s\n",
              r.files.empty() || r.files.back().ends_with(".mp4") ? ", session.mp4" : "");
  if (!r.note.empty()) std::printf("%s\n", r.note.c_str());
  return 0;
}

}  // namespace afford::cli
