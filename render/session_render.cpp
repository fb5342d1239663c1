#include "session_render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <unistd.h>

#include "plot.h"
#include "png.h"
#include "run.h"
#include "scripted_agent.h"

namespace afford::render {
namespace {

namespace fs = std::filesystem;

constexpr Rgb kWhite{255, 255, 255}, kInk{40, 44, 52};

// Darkens a rectangle toward c by a (text backgrounds over the picture), as
// Image::blend does each pixel, by a table of the 256 values of each channel.
void shade(Image& img, int x, int y, int w, int h, Rgb c, double a) {
  Image lookup(256, 1);
  for (int v = 0; v < 256; ++v) {
    lookup.set(v, 0, Rgb{static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v)});
    lookup.blend(v, 0, c, a);
  }
  const std::uint8_t* table = lookup.rgb.data();  // value v of channel k: table[3 v + k]
  const int i0 = std::max(x, 0), i1 = std::min(x + w, img.width);
  for (int j = std::max(y, 0); j < std::min(y + h, img.height); ++j) {
    std::uint8_t* p = &img.rgb[(static_cast<size_t>(j) * static_cast<size_t>(img.width) + static_cast<size_t>(i0)) * 3];
    for (int i = i0; i < i1; ++i, p += 3) {
      for (int k = 0; k < 3; ++k) p[k] = table[3 * p[k] + k];
    }
  }
}

// Pass 1: the box swept by the tool and the actee.
class BoundsObserver : public Observer {
 public:
  void on_start(const Model& m, const State& s, const RuleSet&) override { box.extend(scene_box(m, s)); }
  void on_frame(const Model& m, const State& s, const RuleSet&, const RuleState&) override {
    if (s.frame % 10 == 0) box.extend(scene_box(m, s));
  }
  Eigen::AlignedBox3d box;
};

std::string fmt(const char* f, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, a);
  return buf;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Pass 2: frames, key moments, the timeline.
class FrameObserver : public Observer {
 public:
  FrameObserver(const RenderSessionOptions& o, const Camera& frame_cam, const Camera& tile_cam, double ground_z,
                double force_per_newton, RenderSessionResult* result)
      : o_(o), frame_cam_(frame_cam), tile_cam_(tile_cam), result_(result) {
    frame_opt_.width = o.width;
    frame_opt_.height = o.height;
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
      inferred_.push_back(function_name(rules, e->function) + fmt(" %.2f s", e->t));
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
  void decorate(Image& img, const Model& m, const State& s, const Camera& cam) {
    if (o_.overlay) o_.overlay(img, cam, s);
    draw_overlay(img, m, s, inferred_);
  }

  void write_frame(const Model& m, const State& s) {
    Image img = renderer_.render(m, s, frame_cam_, frame_opt_);
    decorate(img, m, s, frame_cam_);
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
  draw_text(sheet, pad, 12, session.name + ": key moments", kInk, 2);
  draw_text(sheet, pad, 30, session.description, {90, 96, 108}, 1);
  for (int i = 0; i < n; ++i) {
    const int x = pad + (i % cols) * (tw + pad), y = title + (i / cols) * (th + caption + pad);
    fill_rect(sheet, x - 1, y - 1, tw + 2, th + caption + 2, {190, 194, 202});
    blit(sheet, moments[static_cast<size_t>(i)].tile, x, y);
    fill_rect(sheet, x, y + th, tw, caption, kWhite);
    char t[32];
    std::snprintf(t, sizeof t, "%.3f s", moments[static_cast<size_t>(i)].t);
    draw_text(sheet, x + 6, y + th + 6, t, kInk, 2);
    const std::string& what = moments[static_cast<size_t>(i)].what;
    const int scale = text_width(what, 2) <= tw - 12 ? 2 : 1;
    draw_text(sheet, x + 6, y + th + 22, what, {160, 40, 30}, scale);
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
  BoundsObserver bounds;
  {
    Observer* const obs[] = {&bounds};
    ScriptedAgent agent(session.script);
    run_session(session.model, *session.rules, agent, obs);
  }
  const Eigen::AlignedBox3d& box = bounds.box;
  if (ground_z != nullptr) *ground_z = box.min().z() - 0.002;
  if (session.camera.set) {
    Camera c;
    c.position = session.camera.position;
    c.target = session.camera.target;
    c.up = session.camera.up;
    c.fov = session.camera.fov;
    return c;
  }
  return frame_scene(session.model, box, aspect);
}

void draw_overlay(Image& img, const Model& m, const State& s, const std::vector<std::string>& inferred) {
  const int scale = img.width >= 480 ? 2 : 1;
  const int lh = (kGlyphHeight + 4) * scale;
  std::vector<std::string> lines;
  lines.push_back(fmt("t %.3f s", s.t) + fmt("   angle %.1f deg", s.theta * 180 / std::numbers::pi));
  std::string forces = fmt("effort %.1f N", s.effort_force);
  if (m.has_actee) forces += fmt("   actee %.1f", s.actee_force) + fmt(" / %.0f N", m.actee_limit);
  lines.push_back(forces);
  if (m.has_actee) {
    lines.push_back(m.actee_name + ": " + condition_name(s.condition) + "   contacts " +
                    std::to_string(s.object_actee.count) + (s.grasped ? "   grasped" : ""));
  }
  int w = 0;
  for (const std::string& l : lines) w = std::max(w, text_width(l, scale));
  shade(img, 0, 0, w + 12 * scale, static_cast<int>(lines.size()) * lh + 6 * scale, {20, 24, 32}, 0.62);
  for (size_t i = 0; i < lines.size(); ++i) {
    draw_text(img, 6 * scale, 4 * scale + static_cast<int>(i) * lh, lines[i], kWhite, scale);
  }
  // A key to the markers and arrows (scene.cpp's palette), bottom right.
  {
    struct Key {
      Rgb c;
      const char* text;
    };
    const Key keys[] = {{{250, 158, 13}, "effort"}, {{217, 26, 26}, "jaw force"}, {{38, 204, 77}, "jaw contact"},
                        {{26, 166, 242}, "finger contact"}};
    const int ks = 1, klh = kGlyphHeight + 5;  // small: the key must not hide the scene
    int kw = 0;
    for (const Key& k : keys) kw = std::max(kw, text_width(k.text, ks));
    const int box_w = kw + 22 * ks, box_h = 4 * klh + 6 * ks;
    const int x0 = img.width - box_w, y0 = img.height - box_h - (inferred.empty() ? 0 : lh + 6 * scale);
    shade(img, x0, y0, box_w, box_h, {20, 24, 32}, 0.55);
    for (int i = 0; i < 4; ++i) {
      const int y = y0 + 4 * ks + i * klh;
      fill_rect(img, x0 + 5 * ks, y, 7 * ks, 7 * ks, keys[i].c);
      draw_text(img, x0 + 16 * ks, y, keys[i].text, kWhite, ks);
    }
  }
  if (!inferred.empty()) {
    std::string l = "inferred:";
    for (const std::string& f : inferred) l += "  " + f;
    const int y = img.height - lh - 4 * scale;
    shade(img, 0, y - 3 * scale, text_width(l, scale) + 12 * scale, lh + 4 * scale, {20, 24, 32}, 0.62);
    draw_text(img, 6 * scale, y, l, {255, 220, 120}, scale);
  }
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
  const double aspect = static_cast<double>(o.width) / o.height;
  double ground_z = 0;
  const Camera camera = session_camera(session, aspect, &ground_z);
  // The arrows' scale stays fixed over the session.
  const double per_newton = [&] {
    std::unique_ptr<State> s = make_state(session.model);
    return force_scale(session.model, scene_box(session.model, *s));
  }();

  TimelineRecorder timeline(session.name);
  {
    FrameObserver frames(o, camera, camera, ground_z, per_newton, &result);
    Observer* const obs[] = {&frames, &timeline};
    ScriptedAgent agent(session.script);
    frames.total_frames_ = static_cast<int>(std::floor(agent.duration() * o.fps + 1e-9)) + 1;
    run_session(session.model, *session.rules, agent, obs);
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
      const std::string cmd = "ffmpeg -y -loglevel error -framerate " + fmt("%g", o.fps) + " -i " +
                              shell_quote((out / "frame_%05d.png").string()) +
                              " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -pix_fmt yuv420p " + shell_quote(mp4) +
                              " </dev/null";
      if (std::system(cmd.c_str()) == 0) {
        result.files.push_back(mp4);
      } else {
        result.note = "no MP4: ffmpeg failed (" + cmd + ")";
      }
    }
  }
  return result;
}

}  // namespace afford::render
