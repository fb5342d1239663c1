// An actee's look (actees/README.md, issue 26 item 8): its colour and its
// broken look come from its file, are read with located errors, and show
// in the rendered pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "errors.h"
#include "load.h"
#include "run.h"
#include "scene.h"
#include "scripted_agent.h"
#include "session.h"
#include "test_sessions.h"
#include "test_util.h"

namespace afford {
using test::state_at;
namespace {
using test::kSource;

namespace fs = std::filesystem;

const char* kActee = R"(actee: bead
description: a test bead
shape: {sphere: {radius: 10 mm}}
mass: 5 g
force_direction: [0, 1, 0]
limit: 50 N
stiffness: 100 N/mm
breaks: true
friction: {coefficient: 0.3, source: "a test"}
)";

ActeeSpec read(const std::string& extra) {
  return read_actee(load_yaml_string(std::string(kActee) + extra, "bead.yaml"));
}

std::string error_of(const std::string& extra) {
  return test::thrown<DataError>([&] { read(extra); });
}

TEST(ActeeLook, ReadFromTheFile) {
  const ActeeSpec a = read("look: {colour: \"#1a2B3c\", inside: \"#ffffff\", broken: halves}\n");
  EXPECT_EQ(a.look.colour, (ActeeLook::Srgb{0x1a, 0x2b, 0x3c}));
  EXPECT_EQ(a.look.inside, (ActeeLook::Srgb{255, 255, 255}));
  EXPECT_EQ(a.look.broken, ActeeLook::Broken::halves);
  // inside defaults to the colour halfway to white: (0x1a + 256) / 2 = 141.
  const ActeeSpec b = read("look: {colour: \"#1a2b3c\", broken: crushed}\n");
  EXPECT_EQ(b.look.inside, (ActeeLook::Srgb{141, 149, 158}));
  EXPECT_EQ(b.look.broken, ActeeLook::Broken::crushed);
  // No look: the documented default, tan, in shards.
  const ActeeSpec c = read("");
  EXPECT_EQ(c.look.colour, (ActeeLook::Srgb{0xc7, 0x8c, 0x4d}));
  EXPECT_EQ(c.look.inside, (ActeeLook::Srgb{0xe3, 0xc6, 0xa6}));
  EXPECT_EQ(c.look.broken, ActeeLook::Broken::shards);
}

TEST(ActeeLook, MistakesAreLocatedErrors) {
  // line 10 is the look; columns count from 1.
  std::string e = error_of("look: {colour: \"#12345\"}\n");
  EXPECT_NE(e.find("bead.yaml:10:16"), std::string::npos) << e;
  EXPECT_NE(e.find("#rrggbb"), std::string::npos) << e;
  EXPECT_NE(e.find("'#12345'"), std::string::npos) << e;
  // Unquoted, the # starts a comment: the colour is missing, and the message says why.
  e = error_of("look:\n  colour: #123456\n");
  EXPECT_NE(e.find("bead.yaml:11:"), std::string::npos) << e;
  EXPECT_NE(e.find("quoted"), std::string::npos) << e;
  e = error_of("look: {colour: \"#12g456\"}\n");
  EXPECT_NE(e.find("#rrggbb"), std::string::npos) << e;
  e = error_of("look: {color: \"#123456\"}\n");
  EXPECT_NE(e.find("bead.yaml:10:8"), std::string::npos) << e;
  EXPECT_NE(e.find("colour"), std::string::npos) << e;  // did you mean
  e = error_of("look: {colour: \"#123456\", broken: halfs}\n");
  EXPECT_NE(e.find("bead.yaml:10:35"), std::string::npos) << e;
  EXPECT_NE(e.find("one of halves, crushed, shards"), std::string::npos) << e;
  e = error_of("look: {inside: \"#123456\"}\n");
  EXPECT_NE(e.find("colour"), std::string::npos) << e;
  // A broken look on an actee that never breaks.
  const std::string soft =
      test::replace_once(kActee, "breaks: true", "breaks: false") + "look: {colour: \"#123456\", broken: shards}\n";
  e = test::thrown<DataError>([&] { read_actee(load_yaml_string(soft, "soft.yaml")); });
  EXPECT_NE(e.find("soft.yaml:10:35"), std::string::npos) << e;
  EXPECT_NE(e.find("never breaks"), std::string::npos) << e;
}

// Every shipped actee has a look of its own: no two share a colour, and
// one that never breaks has no broken look.
TEST(ActeeLook, EveryShippedActeeHasItsOwnColour) {
  std::set<ActeeLook::Srgb> colours;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kSource + "/actees")) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const std::string text = [&] {
      std::ifstream in(entry.path());
      return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    EXPECT_NE(text.find("\nlook: "), std::string::npos) << entry.path();
    const ActeeSpec a = load_actee(entry.path().string());
    EXPECT_TRUE(colours.insert(a.look.colour).second) << entry.path() << " shares its colour";
  }
  EXPECT_GE(files, 9);
}

// ---------------------------------------------------------------- pixels

render::RenderOptions plain() {
  render::RenderOptions o;
  o.width = 200;
  o.height = 150;
  o.hand = o.contacts = o.forces = false;
  return o;
}

// Chromaticity: the colour with its brightness divided out.
Eigen::Vector3d chroma(double r, double g, double b) {
  const Eigen::Vector3d v(r, g, b);
  return v / std::max(v.sum(), 1e-9);
}
Eigen::Vector3d chroma(const ActeeLook::Srgb& c) { return chroma(c[0], c[1], c[2]); }

// The mean colour of a 5 x 5 patch at the actee's projected centre.
Eigen::Vector3d centre_colour(const render::Image& img, const render::Camera& cam, const State& s) {
  const Eigen::Vector2d p = render::project(cam, img.width, img.height, s.actee_pose.translation());
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int dy = -2; dy <= 2; ++dy) {
    for (int dx = -2; dx <= 2; ++dx) {
      const render::Rgb c = img.at(static_cast<int>(p.x()) + dx, static_cast<int>(p.y()) + dy);
      sum += Eigen::Vector3d(c.r, c.g, c.b);
    }
  }
  return sum / 25;
}

// The egg (tongs) and the sponge (tongs) at rest: the pixel at each
// actee's centre has its own file's colour (its chromaticity nearer its
// own than the other's), so the two are told apart in the picture.
TEST(ActeeLook, FileColourAppearsInThePixels) {
  const CompiledSession egg = load_session(kSource + "/sessions/paper-tongs.yaml");
  const CompiledSession sponge = load_session(kSource + "/sessions/sponge-tongs.yaml");
  ASSERT_NE(egg.model.actee_look.colour, sponge.model.actee_look.colour);
  render::Renderer r;
  for (const CompiledSession* s : {&egg, &sponge}) {
    const CompiledSession* other = s == &egg ? &sponge : &egg;
    const std::unique_ptr<State> st = state_at(*s, 0.2);
    const render::Camera cam = render::frame_scene(s->model, render::scene_box(s->model, *st), 200.0 / 150);
    const render::Image img = r.render(s->model, *st, cam, plain());
    const Eigen::Vector3d c = centre_colour(img, cam, *st);
    const Eigen::Vector3d seen = chroma(c.x(), c.y(), c.z());
    const double own = (seen - chroma(s->model.actee_look.colour)).norm();
    const double theirs = (seen - chroma(other->model.actee_look.colour)).norm();
    EXPECT_LT(own, 0.05) << s->model.actee_name << " seen " << c.transpose();
    EXPECT_LT(own * 3, theirs) << s->model.actee_name;
    EXPECT_EQ(render::actee_colour(s->model), (render::Rgb{s->model.actee_look.colour[0], s->model.actee_look.colour[1],
                                                           s->model.actee_look.colour[2]}));
  }
}

// Broken, the egg is drawn crushed with its yolk (its file's inside)
// showing, and not as the walnut's halves: the three looks give three
// pictures, and only those with the inside colour show it.
TEST(ActeeLook, BrokenLookComesFromTheFile) {
  const CompiledSession s = load_session(kSource + "/sessions/paper-tongs.yaml");
  const std::unique_ptr<State> st = state_at(s, 5.5);
  ASSERT_EQ(st->condition, ActeeCondition::broken);
  const render::Camera cam = render::frame_scene(s.model, render::scene_box(s.model, *st), 200.0 / 150);
  render::Renderer r;
  // Pixels near the yolk's chromaticity (#f4b41a: strongly yellow, little blue).
  auto yolk_pixels = [&](const render::Image& img) {
    int n = 0;
    const Eigen::Vector3d yolk = chroma(s.model.actee_look.inside);
    for (int y = 0; y < img.height; ++y) {
      for (int x = 0; x < img.width; ++x) {
        const render::Rgb c = img.at(x, y);
        if (c.r + c.g + c.b > 150 && (chroma(c.r, c.g, c.b) - yolk).norm() < 0.04) ++n;
      }
    }
    return n;
  };
  Model m = s.model;
  ASSERT_EQ(m.actee_look.broken, ActeeLook::Broken::crushed);
  const render::Image crushed = r.render(m, *st, cam, plain());
  m.actee_look.broken = ActeeLook::Broken::halves;
  const render::Image halves = r.render(m, *st, cam, plain());
  m.actee_look.broken = ActeeLook::Broken::shards;
  const render::Image shards = r.render(m, *st, cam, plain());
  EXPECT_NE(crushed.rgb, halves.rgb);
  EXPECT_NE(crushed.rgb, shards.rgb);
  EXPECT_NE(halves.rgb, shards.rgb);
  EXPECT_GT(yolk_pixels(crushed), 20);
  // With a grey inside, nothing of the yolk's colour is left.
  m.actee_look.broken = ActeeLook::Broken::crushed;
  m.actee_look.inside = {128, 128, 128};
  EXPECT_EQ(yolk_pixels(r.render(m, *st, cam, plain())), 0);
}

}  // namespace
}  // namespace afford
