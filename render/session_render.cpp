#include "session_render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "frame_overlay.h"
#include "output_file.h"
#include "palette.h"
#include "plot.h"
#include "png.h"
#include "run.h"
#include "scripted_agent.h"
#include "text_fit.h"

namespace afford::render {
namespace {

namespace fs = std::filesystem;

// Pass 1: the box swept by the tool and the actee, the most lines of info
// a frame needs at the frames' width, and every function inferred (the
// bars around the frames are sized from them).
class SurveyObserver : public Observer {
 public:
  SurveyObserver(int width, int height) : width_(width), height_(height) {}
  void on_start(const Model& m, const State& s, const RuleSet&) override { box.extend(scene_box(m, s)); }
  void on_frame(const Model& m, const State& s, const RuleSet& rules, const RuleState& rs) override {
    if (s.frame % 10 == 0) box.extend(scene_box(m, s));
    if (width_ > 0) {
      info_lines = std::max(info_lines, info_lines_needed(m, s, width_, height_));
    }
    for (const Event* e = events_begin(rs); e != events_end(rs); ++e) {
      if (e->kind == EventKind::inferred) inferred.push_back(inferred_item(function_name(rules, e->function), e->t));
    }
  }
  Eigen::AlignedBox3d box;
  size_t info_lines = 1;
  std::vector<std::string> inferred;

 private:
  int width_, height_;
};

struct Survey {
  Eigen::AlignedBox3d box;
  size_t info_lines = 1;
  std::vector<std::string> inferred;
};

// Runs the session once (width 0: the box alone).
Survey survey(const CompiledSession& session, int width, int height) {
  SurveyObserver obs(width, height);
  Observer* const list[] = {&obs};
  ScriptedAgent agent(session.script);
  run_session(session, *session.rules, agent, list);
  return {obs.box, obs.info_lines, obs.inferred};
}

Camera camera_for(const CompiledSession& session, const Eigen::AlignedBox3d& box, double aspect) {
  if (!session.camera.set) return frame_scene(session.model, box, aspect);
  Camera c;
  c.position = session.camera.position;
  c.target = session.camera.target;
  c.up = session.camera.up;
  c.fov = session.camera.fov;
  return c;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Pass 2: frames, key moments, the timeline.
class FrameObserver : public Observer {
 public:
  FrameObserver(const RenderSessionOptions& o, const FrameLayout& layout, const Camera& frame_cam,
                const Camera& tile_cam, double ground_z, double force_per_newton, RenderSessionResult* result)
      : o_(o), layout_(layout), frame_cam_(frame_cam), tile_cam_(tile_cam), result_(result) {
    frame_opt_.width = layout.scene.w;
    frame_opt_.height = layout.scene.h;
    frame_opt_.supersample = o.supersample;
    frame_opt_.ground_z = ground_z;
    frame_opt_.force_scale = force_per_newton;
    frame_opt_.guides = o.guides;
    tile_opt_ = frame_opt_;
    tile_opt_.width = kTileW;
    tile_opt_.height = kTileW * o.height / o.width;
  }
  static constexpr int kTileW = 320;
  int total_frames_ = 0;  // frames the whole session will have, for progress

  // The state before the first frame has no hand yet: the pictures start
  // with the first frame (frame_00000 is its picture).
  void on_start(const Model&, const State& s, const RuleSet&) override {
    last_contacts_ = s.object_actee.count;
    last_condition_ = s.condition;
  }

  void on_frame(const Model& m, const State& s, const RuleSet& rules, const RuleState& rs) override {
    if (s.frame <= 1) moment(m, s, "start");
    for (const Event* e = events_begin(rs); e != events_end(rs); ++e) {
      if (e->kind != EventKind::inferred) continue;
      inferred_.push_back(inferred_item(function_name(rules, e->function), e->t));
      moment(m, s, function_name(rules, e->function) + " inferred");
    }
    if (s.condition != last_condition_) {
      if (s.condition == ActeeCondition::broken) moment(m, s, m.actee_name + " broke");
      last_condition_ = s.condition;
    }
    if (s.object_actee.count != last_contacts_) {
      // The first frame's contacts are the start's; a contact that flickers
      // within 50 ms is one moment (from the first count to the latest).
      if (s.frame > 1) {
        const bool flicker = contact_moment_ >= 0 && contact_moment_ + 1 == static_cast<int>(result_->moments.size()) &&
                             s.t - result_->moments.back().t < 0.05;
        if (flicker) {
          result_->moments.pop_back();
        } else {
          contact_from_ = last_contacts_;
        }
        moment(m, s, "actee contacts " + std::to_string(contact_from_) + " -> " + std::to_string(s.object_actee.count));
        contact_moment_ = static_cast<int>(result_->moments.size()) - 1;
      }
      last_contacts_ = s.object_actee.count;
    }
    if (o_.frames && s.t + 1e-9 >= next_frame_ / o_.fps) write_frame(m, s);
  }

  void on_end(const Model& m, const State& s, const RuleSet&, const RuleState&) override { moment(m, s, "end"); }

 private:
  // The scene in the middle, the text in bars around it (frame_overlay.h).
  void write_frame(const Model& m, const State& s) {
    Image scene = renderer_.render(m, s, frame_cam_, frame_opt_);
    if (o_.overlay) o_.overlay(scene, frame_cam_, s);
    const Image img = compose_frame(scene, layout_, info_groups(m, s), inferred_);
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", next_frame_);
    const std::string path = (fs::path(o_.out_dir) / name).string();
    write_png(path, img);
    result_->files.push_back(path);
    ++result_->frames;
    ++next_frame_;
    if (o_.progress) o_.progress(result_->frames, total_frames_);
  }

  void moment(const Model& m, const State& s, const std::string& what) {
    // Two moments of one frame share a tile.
    if (!result_->moments.empty() && result_->moments.back().t == s.t) {
      result_->moments.back().what += ", " + what;
      return;
    }
    if (static_cast<int>(result_->moments.size()) >= o_.max_moments && what != "end") return;
    KeyMoment k;
    k.t = s.t;
    k.what = what;
    k.tile = renderer_.render(m, s, tile_cam_, tile_opt_);
    if (o_.overlay) o_.overlay(k.tile, tile_cam_, s);
    result_->moments.push_back(std::move(k));
  }

  const RenderSessionOptions& o_;
  FrameLayout layout_;
  Camera frame_cam_, tile_cam_;
  RenderOptions frame_opt_, tile_opt_;
  RenderSessionResult* result_;
  Renderer renderer_;
  int next_frame_ = 0;
  int last_contacts_ = 0;
  int contact_from_ = 0;     // the count before the latest contact moment
  int contact_moment_ = -1;  // its index in the moments, -1: none
  ActeeCondition last_condition_ = ActeeCondition::intact;
  std::vector<std::string> inferred_;
};

Image contact_sheet(const CompiledSession& session, const std::vector<KeyMoment>& moments) {
  const int n = static_cast<int>(moments.size());
  const int tw = moments.empty() ? 320 : moments.front().tile.width;
  const int th = moments.empty() ? 240 : moments.front().tile.height;
  const int cols = std::min(4, std::max(n, 1)), rows = (n + cols - 1) / cols;
  const int pad = 10, caption = 44, title = 44;
  Image sheet(pad + cols * (tw + pad), title + rows * (th + caption + pad) + pad, {236, 238, 242});
  draw_text(sheet, pad, 12, fit_text(session.name + ": key moments", sheet.width - 2 * pad, 2), kInk, 2);
  draw_text(sheet, pad, 30, fit_text(session.description, sheet.width - 2 * pad, 1), {90, 96, 108}, 1);
  for (int i = 0; i < n; ++i) {
    const int x = pad + (i % cols) * (tw + pad), y = title + (i / cols) * (th + caption + pad);
    fill_rect(sheet, x - 1, y - 1, tw + 2, th + caption + 2, {190, 194, 202});
    blit(sheet, moments[static_cast<size_t>(i)].tile, x, y);
    fill_rect(sheet, x, y + th, tw, caption, kWhite);
    char t[32];
    std::snprintf(t, sizeof t, "%.3f s", moments[static_cast<size_t>(i)].t);
    draw_text(sheet, x + 6, y + th + 6, t, kInk, 2);
    // The caption at scale 2 if it fits, else at 1 in up to two lines.
    const std::string& what = moments[static_cast<size_t>(i)].what;
    if (text_width(what, 2) <= tw - 12) {
      draw_text(sheet, x + 6, y + th + 22, what, {160, 40, 30}, 2);
    } else {
      std::vector<std::string> parts;
      for (size_t at = 0; at <= what.size();) {
        const size_t end = std::min(what.find(", ", at), what.size());
        parts.push_back(what.substr(at, end - at) + (end < what.size() ? "," : ""));
        at = end + 2;
      }
      const std::vector<std::string> lines = flow({parts}, tw - 12, 1, " ", 2);
      for (size_t k = 0; k < lines.size(); ++k) {
        draw_text(sheet, x + 6, y + th + 20 + 10 * static_cast<int>(k), lines[k], {160, 40, 30}, 1);
      }
    }
    char idx[16];
    std::snprintf(idx, sizeof idx, "%d", i + 1);
    draw_label(sheet, x + 6, y + 6, idx, kWhite, {60, 66, 80}, 2, 3);
  }
  return sheet;
}

}  // namespace

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::string p(path);
  size_t at = 0;
  while (at <= p.size()) {
    const size_t end = std::min(p.find(':', at), p.size());
    const std::string dir = p.substr(at, end - at);
    if (!dir.empty() && ::access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
    at = end + 1;
  }
  return false;
}

Camera session_camera(const CompiledSession& session, double aspect, double* ground_z) {
  const Survey sv = survey(session, 0, 0);
  if (ground_z != nullptr) *ground_z = sv.box.min().z() - 0.002;
  return camera_for(session, sv.box, aspect);
}

FramePlan plan_frames(const CompiledSession& session, int width, int height) {
  const Survey sv = survey(session, width, height);
  FramePlan p;
  p.layout = frame_layout(width, height, sv.info_lines, sv.inferred);
  p.ground_z = sv.box.min().z() - 0.002;
  // The frames' scene sits between the bars; the tiles have none.
  p.camera = camera_for(session, sv.box, static_cast<double>(p.layout.scene.w) / p.layout.scene.h);
  p.tile_camera = camera_for(session, sv.box, static_cast<double>(width) / height);
  return p;
}

RenderSessionResult render_session(const CompiledSession& session, const RenderSessionOptions& o) {
  if (!(o.fps > 0)) throw std::invalid_argument("the frame rate must be above 0");
  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  if (ec) throw std::runtime_error("cannot create " + o.out_dir + ": " + ec.message());
  // Old frames from a longer run would be mistaken for this one's.
  for (const auto& entry : fs::directory_iterator(o.out_dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("frame_", 0) == 0 && entry.path().extension() == ".png") fs::remove(entry.path(), ec);
  }

  RenderSessionResult result;
  const FramePlan plan = plan_frames(session, o.width, o.height);
  const FrameLayout& layout = plan.layout;
  const double ground_z = plan.ground_z;
  const Camera& frame_cam = plan.camera;
  const Camera& tile_cam = plan.tile_camera;
  // The arrows' scale stays fixed over the session.
  const double per_newton = [&] {
    std::unique_ptr<State> s = make_state(session.model);
    return force_scale(session.model, scene_box(session.model, *s));
  }();

  TimelineRecorder timeline(session.name);
  {
    FrameObserver frames(o, layout, frame_cam, tile_cam, ground_z, per_newton, &result);
    Observer* const obs[] = {&frames, &timeline};
    ScriptedAgent agent(session.script);
    frames.total_frames_ = static_cast<int>(std::floor(agent.duration() * o.fps + 1e-9)) + 1;
    run_session(session, *session.rules, agent, obs);
  }

  const fs::path out(o.out_dir);
  const std::string sheet = (out / "contact_sheet.png").string();
  write_png(sheet, contact_sheet(session, result.moments));
  result.files.push_back(sheet);
  const std::string plot = (out / "timeline.png").string();
  write_png(plot, plot_png(timeline.timeline()));
  result.files.push_back(plot);
  const std::string svg = (out / "timeline.svg").string();
  write_file_checked(svg, plot_svg(timeline.timeline()));
  result.files.push_back(svg);

  if (o.frames && o.mp4) {
    if (!on_path("ffmpeg")) {
      result.note = "no MP4: ffmpeg is not on PATH (the frames are there to encode by hand)";
    } else {
      const std::string mp4 = (out / "session.mp4").string();
      // ffmpeg writes the temporary file beside it (its name has no
      // extension: -f mp4), renamed into place only when ffmpeg succeeded.
      OutputFile file(mp4);
      const std::string cmd = "ffmpeg -y -loglevel error -framerate " + printf_number("%g", o.fps) + " -i " +
                              shell_quote((out / "frame_%05d.png").string()) +
                              " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -pix_fmt yuv420p -f mp4 " +
                              shell_quote(file.written_path()) + " </dev/null";
      if (std::system(cmd.c_str()) == 0) {
        file.commit();
        result.files.push_back(mp4);
      } else {
        result.note = "no MP4: ffmpeg failed (" + cmd + ")";
      }
    }
  }
  return result;
}

}  // namespace afford::render
