// Offscreen rendering (render/): PNG by hand, fixed scenes against stored
// reference images, determinism, the actee where it must be, the timeline
// plot, the contact sheet's key moments, the session's camera.
//
// Reference images live in tests/data/render/. After an intended change of
// the pictures, regenerate them with
//   AFFORD_UPDATE_REFERENCES=1 ./afford_tests --gtest_filter='Render*'
// (from the build folder), look at them, and commit them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <sstream>

#include "errors.h"
#include "backdrop.h"
#include "guides.h"
#include "plot.h"
#include "png.h"
#include "run.h"
#include "scene.h"
#include "scripted_agent.h"
#include "session.h"
#include "session_render.h"
#include "test_sessions.h"
#include "test_util.h"

namespace afford {
using test::state_at;
namespace {
using test::paper_nutcracker;
using test::kSource;

namespace fs = std::filesystem;
using render::Image;

const std::string kReferences = kSource + "/tests/data/render/";

// One camera for every test scene: the tool and the walnut at rest.
render::Camera test_camera(double aspect) {
  const std::unique_ptr<State> rest = make_state(paper_nutcracker().model);
  return render::frame_scene(paper_nutcracker().model, render::scene_box(paper_nutcracker().model, *rest), aspect);
}

render::RenderOptions small() {
  render::RenderOptions o;
  o.width = 160;
  o.height = 120;
  o.ground_z = 0.09;
  return o;
}

Image render_at(render::Renderer& r, double t) {
  const std::unique_ptr<State> s = state_at(paper_nutcracker(), t);
  return r.render(paper_nutcracker().model, *s, test_camera(160.0 / 120), small());
}

struct Difference {
  double mean = 0;         // mean absolute difference per channel, 0..255
  double differing = 0;    // fraction of pixels with a channel off by more than 32
};

Difference compare(const Image& a, const Image& b) {
  Difference d;
  size_t off = 0;
  double sum = 0;
  for (size_t i = 0; i < a.rgb.size(); i += 3) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      const int e = std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c]));
      sum += e;
      worst = std::max(worst, e);
    }
    if (worst > 32) ++off;
  }
  d.mean = sum / static_cast<double>(a.rgb.size());
  d.differing = static_cast<double>(off) / static_cast<double>(a.rgb.size() / 3);
  return d;
}

// Compares with tests/data/render/<name>.png (or writes it, see the top).
void expect_reference(const Image& img, const std::string& name) {
  const std::string path = kReferences + name + ".png";
  if (std::getenv("AFFORD_UPDATE_REFERENCES") != nullptr) {
    render::write_png(path, img);
    GTEST_SKIP() << "wrote " << path;
  }
  const Image ref = render::read_png(path);
  ASSERT_EQ(ref.width, img.width);
  ASSERT_EQ(ref.height, img.height);
  const Difference d = compare(img, ref);
  EXPECT_LE(d.mean, 3.0) << name << ": mean absolute difference";
  EXPECT_LE(d.differing, 0.02) << name << ": fraction of pixels off by more than 32";
  if (d.mean > 3.0 || d.differing > 0.02) {
    const std::string got = (fs::temp_directory_path() / ("afford-" + name + "-got.png")).string();
    render::write_png(got, img);
    ADD_FAILURE() << "the picture differs from " << path << "; this run's is " << got;
  }
}

// ---------------------------------------------------------------- PNG

TEST(RenderPng, RoundTripsAnOddSize) {
  Image img(301, 257);  // 301*3+1 bytes a row: rows not aligned to anything
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      img.set(x, y, {static_cast<std::uint8_t>(x * 7 + y), static_cast<std::uint8_t>(y * 3),
                     static_cast<std::uint8_t>((x ^ y) & 0xFF)});
    }
  }
  const std::vector<std::uint8_t> bytes = render::encode_png(img);
  const Image back = render::decode_png(bytes);
  EXPECT_EQ(back.width, 301);
  EXPECT_EQ(back.height, 257);
  EXPECT_EQ(back.rgb, img.rgb);
  // And through a file.
  const std::string path = (fs::temp_directory_path() / "afford-roundtrip.png").string();
  render::write_png(path, img);
  EXPECT_EQ(render::read_png(path).rgb, img.rgb);
  fs::remove(path);
}

TEST(RenderPng, RejectsCorruptFiles) {
  std::vector<std::uint8_t> bytes = render::encode_png(Image(8, 8, {10, 20, 30}));
  std::vector<std::uint8_t> bad = bytes;
  bad[bad.size() / 2] ^= 0x40;  // inside IDAT: the CRC no longer matches
  EXPECT_THROW(render::decode_png(bad), render::PngError);
  bad = bytes;
  bad[0] = 'x';
  EXPECT_THROW(render::decode_png(bad), render::PngError);
  bad.assign(bytes.begin(), bytes.begin() + 40);
  EXPECT_THROW(render::decode_png(bad), render::PngError);
}

// OpenGL's rows come bottom first; each output pixel is the rounded mean of
// its factor x factor block, alpha dropped.
TEST(RenderImage, GlPixelsAreFlippedAndAveraged) {
  // 4 x 2 RGBA, bottom row first: bottom row red 0, 10, 20, 30; top row 100, 101, 102, 255.
  const std::vector<std::uint8_t> rgba = {0,   1, 2, 9, 10,  1, 2, 9, 20,  1, 2, 9, 30,  1, 2, 9,
                                          100, 5, 6, 9, 101, 5, 6, 9, 102, 5, 6, 9, 255, 5, 6, 9};
  const Image same = render::from_gl_rgba(rgba.data(), 4, 2, 1);
  ASSERT_EQ(same.width, 4);
  ASSERT_EQ(same.height, 2);
  EXPECT_EQ(same.at(0, 0), (render::Rgb{100, 5, 6}));  // the top row is GL's last
  EXPECT_EQ(same.at(3, 1), (render::Rgb{30, 1, 2}));
  const Image half = render::from_gl_rgba(rgba.data(), 4, 2, 2);
  ASSERT_EQ(half.width, 2);
  ASSERT_EQ(half.height, 1);
  EXPECT_EQ(half.at(0, 0), (render::Rgb{53, 3, 4}));   // (0 + 10 + 100 + 101) / 4 = 52.75; (1+1+5+5)/4 = 3
  EXPECT_EQ(half.at(1, 0), (render::Rgb{102, 3, 4}));  // (20 + 30 + 102 + 255) / 4 = 101.75
  EXPECT_THROW(render::from_gl_rgba(rgba.data(), 4, 2, 5), std::invalid_argument);
}

// The colour is premultiplied by the alpha, the cover: C + (1 - A) B.
TEST(RenderImage, PremultipliedPictureIsPutOverTheBackdrop) {
  // 3 x 1: nothing drawn, opaque, and half covered by 50 (premultiplied).
  const std::vector<std::uint8_t> rgba = {0, 0, 0, 0, 10, 20, 30, 255, 50, 50, 50, 128};
  const Image under(3, 1, {200, 100, 0});
  const Image one = render::from_gl_rgba(rgba.data(), 3, 1, 1, &under);
  EXPECT_EQ(one.at(0, 0), (render::Rgb{200, 100, 0}));
  EXPECT_EQ(one.at(1, 0), (render::Rgb{10, 20, 30}));
  // 50 + 127 / 255 of (200, 100, 0): 149.6, 99.8, 50 (rounded from 150.1, 100.3, 50.5 with the half)
  EXPECT_EQ(one.at(2, 0), (render::Rgb{150, 100, 50}));
  // A 2 x 2 block, half of it opaque grey 100: half of 100 over 200 is 150.
  const std::vector<std::uint8_t> block = {0, 0, 0, 0, 100, 100, 100, 255, 100, 100, 100, 255, 0, 0, 0, 0};
  const Image grey(1, 1, {200, 200, 200});
  EXPECT_EQ(render::from_gl_rgba(block.data(), 2, 2, 2, &grey).at(0, 0), (render::Rgb{150, 150, 150}));
  EXPECT_THROW(render::from_gl_rgba(block.data(), 2, 2, 1, &grey), std::invalid_argument);  // not 2 x 2
}

// A camera 1 m above the ground looking straight down, tan(fov / 2) = 0.5,
// 100 x 100 pixels: pixel (x, y) sees the ground at x_w = (2x + 1) / 200 - 0.5,
// y_w = 0.5 - (2y + 1) / 200, 1 cm a pixel. The square from -0.195 m, 4
// cells of 0.1 m, has lines at x_w = -0.195, -0.095, 0.005, 0.105, 0.205,
// through the centres of columns 30, 40, 50, 60 and 70, and of rows 69, 59,
// 49, 39 and 29 for y_w = -0.195 ... 0.205.
TEST(RenderBackdrop, GridLinesAndEdgesFallWhereTheyProject) {
  render::Camera down;
  down.position = Eigen::Vector3d(0, 0, 1);
  down.target = Eigen::Vector3d::Zero();
  down.fov = 2 * std::atan(0.5);
  const render::Ground ground{0.0, -0.195, -0.195, 0.1, 4};
  const Image img = render::Backdrop(down, 100, 100, &ground).draw();
  const render::Rgb line{194, 201, 214}, plain{230, 232, 237};  // 255 (0.76, 0.79, 0.84) and (0.90, 0.91, 0.93)
  for (int x : {30, 40, 50, 60, 70}) EXPECT_EQ(img.at(x, 45), line) << "column " << x;
  for (int y : {29, 39, 49, 59, 69}) EXPECT_EQ(img.at(45, y), line) << "row " << y;
  for (int x : {31, 45, 49, 51, 69}) EXPECT_EQ(img.at(x, 45), plain) << "column " << x;  // a pixel or more off
  // Outside the square (a pixel past the border line and more) the sky:
  // at row 45 its gradient is 0.545 of the way from (0.80, 0.84, 0.89) to (0.97, 0.98, 0.99).
  const render::Rgb sky{228, 234, 241};  // 255 (0.89265, 0.9163, 0.9445) = (227.6, 233.7, 240.8)
  for (int x : {0, 29, 71, 99}) EXPECT_EQ(img.at(x, 45), sky) << "column " << x;
  // Half a pixel off a line (x_w = 0.01: column 50.5), half its colour: a
  // camera moved 5 mm puts a line there between columns 50 and 51.
  down.position.x() = down.target.x() = -0.005;
  const Image half = render::Backdrop(down, 100, 100, &ground).draw();
  EXPECT_EQ(half.at(50, 45), (render::Rgb{212, 217, 226})) << "(230 + 194) / 2, (232 + 201) / 2, (237 + 214) / 2";
  EXPECT_EQ(half.at(51, 45), (render::Rgb{212, 217, 226}));
}

// Looking level from 1 m up: the upper half sees only sky, the lower half the ground.
TEST(RenderBackdrop, NothingOfTheGroundAboveTheHorizon) {
  render::Camera level;
  level.position = Eigen::Vector3d(0, 0, 1);
  level.target = Eigen::Vector3d(1, 0, 1);
  const render::Ground ground{0.0, -50, -50, 1.0, 100};
  const Image img = render::Backdrop(level, 64, 48, &ground).draw();
  const Image sky_only = render::Backdrop(level, 64, 48, nullptr).draw();
  for (int y = 0; y < 24; ++y) {
    for (int x = 0; x < 64; ++x) ASSERT_EQ(img.at(x, y), sky_only.at(x, y)) << x << ", " << y;
  }
  // The bottom row looks down by 0.979 tan(20 deg): it meets the ground 2.81 m
  // ahead, 0.19 m (1.6 pixels) from the line x = 3; column 40 is 0.36 m (8.5
  // pixels) to the side of the line y = 0.
  EXPECT_EQ(img.at(40, 47), (render::Rgb{230, 232, 237}));
  EXPECT_NE(img.at(40, 47), sky_only.at(40, 47));
}

TEST(RenderFont, DrawsEveryPrintableCharacter) {
  for (char c = 33; c < 127; ++c) {
    Image img(8, 10, {0, 0, 0});
    render::draw_text(img, 1, 0, std::string(1, c), {255, 255, 255});
    int lit = 0;
    for (size_t i = 0; i < img.rgb.size(); i += 3) lit += img.rgb[i] > 0;
    EXPECT_GT(lit, 0) << "'" << c << "' has no pixels";
  }
  EXPECT_EQ(render::text_width("abc", 2), (3 * 6 - 1) * 2);
}

// ---------------------------------------------------------------- scenes

TEST(RenderScene, IdenticalInputGivesIdenticalPixels) {
  render::Renderer a, b;
  const Image first = render_at(a, 2.0);
  const Image again = render_at(a, 2.0);
  const Image other = render_at(b, 2.0);
  EXPECT_EQ(render::encode_png(first), render::encode_png(again));
  EXPECT_EQ(render::encode_png(first), render::encode_png(other));
  // A renderer keeps its last backdrop while the camera and the ground stay;
  // another camera gets its own, as a fresh renderer draws it.
  const std::unique_ptr<State> s = state_at(paper_nutcracker(), 2.0);
  render::Camera moved = test_camera(160.0 / 120);
  moved.position += Eigen::Vector3d(0.03, 0.0, 0.05);
  render::Renderer fresh;
  const Image seen = a.render(paper_nutcracker().model, *s, moved, small());
  EXPECT_EQ(render::encode_png(seen), render::encode_png(fresh.render(paper_nutcracker().model, *s, moved, small())));
  EXPECT_NE(render::encode_png(seen), render::encode_png(first));
}

// Mesa rasterises in the calling thread: a thread of its alive at exit once
// crashed LeakSanitizer's stop-the-world in CI (scene.cpp).
TEST(RenderScene, RenderingStartsNoThread) {
  const auto threads = [] {
    return std::distance(fs::directory_iterator("/proc/self/task"), fs::directory_iterator());
  };
  const auto before = threads();
  {
    render::Renderer r;
    render_at(r, 2.0);
    EXPECT_EQ(threads(), before);
  }
  EXPECT_EQ(threads(), before);
}

TEST(RenderScene, NutcrackerAtRestMatchesItsReference) {
  render::Renderer r;
  expect_reference(render_at(r, 0.4), "nutcracker_rest");
}

TEST(RenderScene, NutcrackerMidSqueezeMatchesItsReference) {
  render::Renderer r;
  expect_reference(render_at(r, 2.0), "nutcracker_squeeze");
}

TEST(RenderScene, NutcrackerBrokenWalnutMatchesItsReference) {
  render::Renderer r;
  expect_reference(render_at(r, 3.2), "nutcracker_broken");
}

// The pixel at the walnut's projected centre has the walnut's warm colour
// (red above green above blue), at rest and mid-squeeze.
TEST(RenderScene, ActeeIsAtItsProjectedCentre) {
  render::Renderer r;
  for (double t : {0.4, 2.0}) {
    const std::unique_ptr<State> s = state_at(paper_nutcracker(), t);
    const render::Camera cam = test_camera(160.0 / 120);
    const Image img = r.render(paper_nutcracker().model, *s, cam, small());
    const Eigen::Vector2d p = render::project(cam, 160, 120, s->actee_pose.translation());
    const render::Rgb c = img.at(static_cast<int>(p.x()), static_cast<int>(p.y()));
    EXPECT_GT(c.r, c.g) << "t = " << t;
    EXPECT_GT(int(c.g), int(c.b)) << "t = " << t;
    EXPECT_GT(int(c.r) - int(c.b), 60) << "t = " << t;
    // Away from the tool, in a corner, the background: grey-blue and bright.
    const render::Rgb bg = img.at(2, 2);
    EXPECT_GE(int(bg.b), int(bg.r)) << "t = " << t;
    EXPECT_GT(int(bg.r), 150) << "t = " << t;
  }
  // The base colour itself is the one the palette promises.
  EXPECT_GT(render::actee_base_colour().r, render::actee_base_colour().b);
}

TEST(RenderScene, FramedSceneFitsTheTool) {
  const std::unique_ptr<State> s = make_state(paper_nutcracker().model);
  const Eigen::AlignedBox3d box = render::scene_box(paper_nutcracker().model, *s);
  const render::Camera cam = render::frame_scene(paper_nutcracker().model, box, 4.0 / 3);
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector2d p = render::project(cam, 640, 480, box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)));
    EXPECT_GE(p.x(), 0);
    EXPECT_LE(p.x(), 640);
    EXPECT_GE(p.y(), 0);
    EXPECT_LE(p.y(), 480);
  }
}

// The guides (guides/guides.h) appear where they must: the advantage map's
// segments in their colours, the symmetry plane tinting the view with its
// colour.
TEST(RenderScene, GuidesAppearWhereTheyMust) {
  const CompiledSession& s = paper_nutcracker();
  const Guides guides = compute_guides(s.model, load_guides(kSource + "/rules/guides.yaml"));
  const std::unique_ptr<State> state = state_at(s, 0.4);
  const render::Camera cam = test_camera(4.0 / 3);
  render::RenderOptions o;
  o.width = 320;
  o.height = 240;
  o.hand = false;
  o.ground_z = 0.09;
  render::Renderer r;
  const Image plain = r.render(s.model, *state, cam, o);
  o.guides = &guides;
  const Image with = r.render(s.model, *state, cam, o);
  const Guides posed = posed_guides(guides, state->theta, state->object_pose);

  int seen = 0, segments = 0;
  for (const GuideSegment& seg : posed.segments) {
    ++segments;
    const Eigen::Vector2d p = render::project(cam, o.width, o.height, (seg.a + seg.b) / 2);
    const render::Rgb c = with.at(static_cast<int>(p.x()), static_cast<int>(p.y()));
    const int d = std::max({std::abs(c.r - int(std::lround(seg.colour.r * 255))),
                            std::abs(c.g - int(std::lround(seg.colour.g * 255))),
                            std::abs(c.b - int(std::lround(seg.colour.b * 255)))});
    seen += d < 60;
  }
  ASSERT_GT(segments, 10);
  EXPECT_GE(seen, segments / 3) << seen << " of " << segments << " advantage segments show their colour";

  const int plane = guides.find("stable_orientation");
  ASSERT_GE(plane, 0);
  int tinted = 0, rects = 0;
  for (const GuideRect& rect : posed.rects) {
    if (rect.guide != plane) continue;
    ++rects;
    const Eigen::Vector3d corner = rect.centre + 0.85 * rect.half_u * rect.u + 0.85 * rect.half_v * rect.v;
    const Eigen::Vector2d p = render::project(cam, o.width, o.height, corner);
    const render::Rgb a = plain.at(static_cast<int>(p.x()), static_cast<int>(p.y()));
    const render::Rgb b = with.at(static_cast<int>(p.x()), static_cast<int>(p.y()));
    tinted += (int(b.b) - int(b.r)) > (int(a.b) - int(a.r)) + 10;
  }
  EXPECT_EQ(rects, 1);
  EXPECT_EQ(tinted, rects);
}

// ---------------------------------------------------------------- plot, sheet, camera

TEST(RenderPlot, SvgHasAxesCurvesLegendAndInferences) {
  const CompiledSession& s = paper_nutcracker();
  render::TimelineRecorder rec(s.name);
  Observer* const obs[] = {&rec};
  ScriptedAgent agent(s.script);
  run_session(s.model, *s.rules, agent, obs);
  const std::string svg = render::plot_svg(rec.timeline());
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  size_t polylines = 0;
  for (size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1)) ++polylines;
  EXPECT_EQ(polylines, 3u) << "angle, effort force, actee force";
  for (const char* text : {"angle [deg]", "force [N]", "time [s]", "actee limit", "effort force", "actee force",
                           "node reached", "node lost", ">pinch ", ">hold ", ">crash "}) {
    EXPECT_NE(svg.find(text), std::string::npos) << text;
  }
  const Image png = render::plot_png(rec.timeline());
  EXPECT_EQ(png.width, 1100);
  EXPECT_EQ(png.height, render::plot_height(rec.timeline()));
}

TEST(RenderSession, ContactSheetHasTheKeyMoments) {
  const std::string dir = (fs::temp_directory_path() / "afford-render-session").string();
  fs::remove_all(dir);
  render::RenderSessionOptions o;
  o.out_dir = dir;
  o.frames = false;
  o.width = 320;
  o.height = 240;
  o.supersample = 1;
  const render::RenderSessionResult r = render::render_session(paper_nutcracker(), o);
  std::string all;
  for (const render::KeyMoment& k : r.moments) all += k.what + "\n";
  for (const char* what : {"start", "pinch inferred", "hold inferred", "crash inferred", "walnut broke",
                           "actee contacts 1 -> 2", "end"}) {
    EXPECT_NE(all.find(what), std::string::npos) << what << " in\n" << all;
  }
  for (const char* f : {"contact_sheet.png", "timeline.png", "timeline.svg"}) {
    EXPECT_TRUE(fs::is_regular_file(fs::path(dir) / f)) << f;
  }
  EXPECT_EQ(r.frames, 0);
  fs::remove_all(dir);
}

TEST(RenderSession, CameraKeyIsReadAndChecked) {
  const std::string dir = (fs::temp_directory_path() / "afford-camera").string();
  fs::create_directories(dir);
  std::ifstream in(kSource + "/sessions/paper-nutcracker.yaml");
  std::stringstream buf;
  buf << in.rdbuf();
  std::string text = buf.str();
  for (const char* rel : {"../objects/", "../actees/", "../agents/", "../rules/"}) {
    for (size_t at = text.find(rel); at != std::string::npos; at = text.find(rel)) {
      text.replace(at, 3, kSource + "/");
    }
  }
  const std::string good = test::replace_once(
      text, "script:\n", "camera: {position: [100 mm, -300 mm, 400 mm], target: [90 mm, 0 mm, 100 mm], fov: 30 deg}\nscript:\n");
  std::ofstream(dir + "/good.yaml") << good;
  const CompiledSession s = load_session(dir + "/good.yaml");
  EXPECT_TRUE(s.camera.set);
  EXPECT_NEAR(s.camera.fov, 30 * std::numbers::pi / 180, 1e-12);
  EXPECT_NEAR(s.camera.target.x(), 0.09, 1e-12);
  const render::Camera cam = render::session_camera(s, 4.0 / 3, nullptr);
  EXPECT_NEAR(cam.position.z(), 0.4, 1e-12);

  const std::string bad = test::replace_once(
      text, "script:\n", "camera: {position: [1 mm, 0 mm, 4 mm], target: [1 mm, 0 mm, 4 mm], fvo: 30 deg}\nscript:\n");
  std::ofstream(dir + "/bad.yaml") << bad;
  try {
    load_session(dir + "/bad.yaml");
    ADD_FAILURE() << "expected a DataError";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("fvo"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace afford
