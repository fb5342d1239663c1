// The pictures' text and axes (issue 26, item 8): a frame's bars never
// cover the tool, the actee or the fingertips, every label fits its bar,
// and a chart's axes fit the data they show (limits worked by hand).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "axis_range.h"
#include "chart.h"
#include "frame_overlay.h"
#include "plot.h"
#include "run.h"
#include "scene.h"
#include "scripted_agent.h"
#include "session.h"
#include "session_render.h"
#include "text_fit.h"
#include "test_util.h"

namespace afford {
namespace {
using test::kSource;

using render::PixelBox;


const CompiledSession& session(const std::string& name) {
  static std::map<std::string, CompiledSession> loaded;
  auto it = loaded.find(name);
  if (it == loaded.end()) it = loaded.emplace(name, load_session(kSource + "/sessions/" + name + ".yaml")).first;
  return it->second;
}

// ---------------------------------------------------------------- text

TEST(RenderText, FitsOrIsShortenedWithDots) {
  // The font is 6 px a character at scale 1, less the last column: 5 characters are 29 px.
  EXPECT_EQ(render::fit_text("carry", 29, 1), "carry");
  EXPECT_EQ(render::fit_text("carry 2.78 s", 29, 1), "car..");  // 5 characters, 29 px
  EXPECT_EQ(render::fit_text("carry", 10, 1), "");              // not even ".." and one letter
  EXPECT_LE(render::text_width(render::fit_text("a long label in a legend", 100, 2), 2), 100);
}

TEST(RenderText, FlowsItemsIntoLinesThatFit) {
  // 11 characters a line at scale 1 (65 px): "pinch 1.20s" is 11, two items never share a line.
  const std::vector<std::string> items{"pinch 1.20s", "hold 1.51s", "carry 2.78s", "crash 5.00s"};
  const std::vector<std::string> all = render::flow({items}, 65, 1, "  ");
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[3], "crash 5.00s");
  // 24 characters (143 px): two items a line ("pinch 1.20s  hold 1.51s" is 23).
  const std::vector<std::string> two = render::flow({items}, 143, 1, "  ");
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0], "pinch 1.20s  hold 1.51s");
  EXPECT_EQ(two[1], "carry 2.78s  crash 5.00s");
  // One line allowed: the first item and the count of the other three
  // ("pinch 1.20s  +3 more" is 20 characters; with "hold 1.51s" it would be 32).
  const std::vector<std::string> one = render::flow({items}, 143, 1, "  ", 1);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], "pinch 1.20s  +3 more");
  // Each group starts a line.
  const std::vector<std::string> groups = render::flow({{"a", "b"}, {"c"}}, 500, 1, " ");
  EXPECT_EQ(groups, (std::vector<std::string>{"a b", "c"}));
}

// ---------------------------------------------------------------- frames

// The boxes of the bars lie in the frame, apart from the scene and from
// one another, and the scene keeps at least half of the height.
void expect_apart(const render::FrameLayout& l) {
  const PixelBox frame{0, 0, l.width, l.height};
  for (const PixelBox* b : {&l.info, &l.scene, &l.inferred, &l.legend}) {
    if (!b->empty()) {
      EXPECT_TRUE(frame.contains(*b)) << l.width << "x" << l.height;
    }
  }
  EXPECT_FALSE(l.info.intersects(l.scene));
  EXPECT_FALSE(l.legend.intersects(l.scene));
  EXPECT_FALSE(l.inferred.intersects(l.scene));
  EXPECT_FALSE(l.info.intersects(l.inferred));
  EXPECT_GE(l.scene.h * 2, l.height) << l.width << "x" << l.height;
}

// What issue 26 saw cut: "carry 2.78 s  c". Every function the tongs and
// the egg infer is in the bar, whole, at each size, and each line fits.
TEST(RenderFrame, InferredBarShowsEveryFunctionWhole) {
  const CompiledSession& s = session("paper-tongs");
  const std::vector<std::string> inferred{render::inferred_item("pinch", 1.2), render::inferred_item("hold", 1.513),
                                          render::inferred_item("carry", 2.781), render::inferred_item("crash", 4.997)};
  for (const auto& [w, h] : {std::pair{640, 480}, {320, 240}, {1280, 720}}) {
    const render::FramePlan plan = render::plan_frames(s, w, h);
    expect_apart(plan.layout);
    const std::vector<std::string> lines = render::inferred_text(plan.layout, inferred);
    std::string all;
    for (const std::string& l : lines) {
      EXPECT_LE(render::text_width(l, plan.layout.scale) + 12 * plan.layout.scale, w) << l;
      all += l + " | ";
    }
    for (const std::string& f : inferred) {
      EXPECT_NE(all.find(f), std::string::npos) << f << " in " << all << " at " << w;
    }
    EXPECT_EQ(all.find("more"), std::string::npos) << all;
  }
}

// Every line of the info fits beside the key, at every size, for every
// state of the session.
TEST(RenderFrame, InfoLinesFitTheirBar) {
  const CompiledSession& s = session("paper-tongs");
  for (const auto& [w, h] : {std::pair{640, 480}, {160, 120}, {320, 240}}) {
    const render::FramePlan plan = render::plan_frames(s, w, h);
    expect_apart(plan.layout);
    std::unique_ptr<State> st = make_state(s.model);
    ScriptedAgent agent(s.script);
    Sample sample;
    for (std::int64_t k = 1; static_cast<double>(k) * s.model.timestep <= agent.duration(); k += 250) {
      for (std::int64_t j = 0; j < 250; ++j) {
        const double t = static_cast<double>(st->frame + 1) * s.model.timestep;
        agent.sample_at(t, &sample);
        sample.t = t;
        step(s.model, *st, sample);
      }
      const std::vector<std::string> lines = render::info_text(plan.layout, render::info_groups(s.model, *st));
      EXPECT_LE(lines.size(), plan.layout.info_lines);
      for (const std::string& l : lines) {
        EXPECT_LE(render::text_width(l, plan.layout.scale), render::info_width(w, h)) << l << " at " << w;
      }
    }
  }
}

// The projected box of what the frame must show (every part of the tool,
// the actee and the fingertips) over the session lies in the scene, so no
// bar covers it: the frame of issue 26 had the info box over the hand and
// the key over a jaw.
TEST(RenderFrame, BarsDoNotCoverTheToolActeeOrFingertips) {
  for (const char* name : {"paper-tongs", "paper-nutcracker", "sponge-tongs"}) {
    const CompiledSession& s = session(name);
    const render::FramePlan plan = render::plan_frames(s, 640, 480);
    const render::FrameLayout& l = plan.layout;
    std::unique_ptr<State> st = make_state(s.model);
    ScriptedAgent agent(s.script);
    Sample sample;
    Eigen::AlignedBox2d seen;
    auto add = [&](const Eigen::Vector3d& p) {
      const Eigen::Vector2d q = render::project(plan.camera, l.scene.w, l.scene.h, p);
      seen.extend(Eigen::Vector2d(q.x() + l.scene.x, q.y() + l.scene.y));
    };
    const double end = agent.duration();
    for (std::int64_t k = 1; static_cast<double>(k) * s.model.timestep <= end; ++k) {
      const double t = static_cast<double>(k) * s.model.timestep;
      agent.sample_at(t, &sample);
      sample.t = t;
      step(s.model, *st, sample);
      if (k % 100 != 0) continue;
      const Eigen::AlignedBox3d box = render::scene_box(s.model, *st);
      for (int c = 0; c < 8; ++c) add(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
      if (st->grasped) {
        for (int f = 0; f < kFingers; ++f) add(st->fingertip[static_cast<size_t>(f)]);
      }
    }
    const PixelBox drawn{static_cast<int>(std::floor(seen.min().x())), static_cast<int>(std::floor(seen.min().y())),
                         static_cast<int>(std::ceil(seen.sizes().x())), static_cast<int>(std::ceil(seen.sizes().y()))};
    EXPECT_TRUE(l.scene.contains(drawn)) << name << ": drawn " << drawn.x << "," << drawn.y << " " << drawn.w << "x"
                                         << drawn.h << " scene y " << l.scene.y << " h " << l.scene.h;
    for (const PixelBox* bar : {&l.info, &l.legend, &l.inferred}) {
      EXPECT_FALSE(bar->intersects(drawn)) << name;
    }
  }
}

// The smallest frames `afford render --size` takes keep half their height
// for the scene: the inferred bar gives way first.
TEST(RenderFrame, SmallFramesKeepHalfForTheScene) {
  const std::vector<std::string> inferred{"pinch 1.20 s", "hold 1.51 s", "carry 2.78 s", "crash 5.00 s"};
  for (const auto& [w, h] : {std::pair{64, 48}, {96, 72}, {160, 120}, {3840, 48}, {480, 100}, {3840, 2160}}) {
    const render::FrameLayout l = render::frame_layout(w, h, 9, inferred);
    expect_apart(l);
    EXPECT_GE(l.info_lines, 1u);
  }
  // 64 x 48 at scale 1: a line is 11 px, the info 17 px (one line and 3 px
  // above and below); the inferred bar (17 px) would leave the scene 14 px.
  const render::FrameLayout tiny = render::frame_layout(64, 48, 9, inferred);
  EXPECT_EQ(tiny.info.h, 17);
  EXPECT_EQ(tiny.inferred_lines, 0u);
  EXPECT_EQ(tiny.scene.h, 31);
}

// The frame is the scene's picture in its place, the bars around it.
TEST(RenderFrame, SceneIsCopiedBetweenTheBars) {
  const render::FrameLayout l = render::frame_layout(320, 240, 3, {"pinch 1.20 s"});
  render::Image scene(l.scene.w, l.scene.h, {10, 200, 30});
  const render::Image frame = render::compose_frame(scene, l, {{"t 0.000 s"}}, {"pinch 1.20 s"});
  ASSERT_EQ(frame.width, 320);
  ASSERT_EQ(frame.height, 240);
  for (int y = 0; y < 240; ++y) {
    const bool in_scene = y >= l.scene.y && y < l.scene.y + l.scene.h;
    EXPECT_EQ(frame.at(160, y) == (render::Rgb{10, 200, 30}), in_scene) << "row " << y;
  }
}

// ---------------------------------------------------------------- axes

TEST(RenderAxis, MacadamiaLoopStartsAtZeroNotMinus1000) {
  // The loop's forces: 0 to 3400 N. With a 4 % margin (136 N) the low end
  // would be -136 N, and rounded to the 1000 N step, -1000 N (issue 26).
  // A force that does not go below zero starts at zero; the top stays at
  // 3400 + 136 = 3536 N, since 4000 N would add 464 N, more than 5 % of
  // the 3536 N span (176.8 N).
  const render::AxisRange r = render::axis_range(0, 3400, 6, 0.04);
  EXPECT_DOUBLE_EQ(r.lo, 0);
  EXPECT_DOUBLE_EQ(r.hi, 3536);
  EXPECT_DOUBLE_EQ(r.step, 1000);  // 3536 / 6 = 589 -> the next of 1, 2, 5 x 10^n: 1000
  EXPECT_DOUBLE_EQ(r.first_tick(), 0);
}

TEST(RenderAxis, SmallNegativeNoiseAddsItsMarginNotAStep) {
  // -5 to 3400 N: span 3405, margin 136.2: -141.2 to 3536.2; step 1000
  // (3677.4 / 6 = 612.9); -1000 would add 858.8 N, 3677.4 * 5 % = 183.87.
  const render::AxisRange r = render::axis_range(-5, 3400, 6, 0.04);
  EXPECT_NEAR(r.lo, -141.2, 1e-9);
  EXPECT_NEAR(r.hi, 3536.2, 1e-9);
  EXPECT_DOUBLE_EQ(r.step, 1000);
  EXPECT_DOUBLE_EQ(r.first_tick(), 0);
}

TEST(RenderAxis, EndsRoundOutToATickWhenThatAddsLittle) {
  // Time 0 to 88.3 s, no margin: step 10 (8.83 -> 10); 90 adds 1.7 s, at
  // most 5 % of 88.3 (4.415).
  const render::AxisRange t = render::axis_range(0, 88.3, 10, 0);
  EXPECT_DOUBLE_EQ(t.lo, 0);
  EXPECT_DOUBLE_EQ(t.hi, 90);
  EXPECT_DOUBLE_EQ(t.step, 10);
  // A residual of -800 to 1050 N: margin 74, -874 to 1124; step 500
  // (1998 / 6 = 333); -1000 adds 126 and 1500 adds 376, both above 99.9.
  const render::AxisRange res = render::axis_range(-800, 1050, 6, 0.04);
  EXPECT_NEAR(res.lo, -874, 1e-9);
  EXPECT_NEAR(res.hi, 1124, 1e-9);
  EXPECT_DOUBLE_EQ(res.step, 500);
  EXPECT_DOUBLE_EQ(res.first_tick(), -500);
  // No data, and one value.
  EXPECT_DOUBLE_EQ(render::axis_range(1, 0, 6, 0.04).hi, 1);
  const render::AxisRange one = render::axis_range(2, 2, 6, 0);
  EXPECT_DOUBLE_EQ(one.lo, 1.5);
  EXPECT_DOUBLE_EQ(one.hi, 2.5);
}

// A chart's tick labels are those of its range: the loop of 0 to 3400 N
// has no "-1000" label, and its legend stays inside the picture however
// long a label is (the residual plot's "loading in contact" was cut).
// Every `<text x="X" ... text-anchor="ANCHOR">TEXT</text>` of an SVG, as
// (X, TEXT). (Scanned by hand: std::regex trips GCC 12's uninitialised
// warnings in the sanitised build.)
std::vector<std::pair<double, std::string>> svg_texts(const std::string& svg, const std::string& anchor) {
  std::vector<std::pair<double, std::string>> out;
  const std::string open = "<text x=\"", tail = "text-anchor=\"" + anchor + "\">";
  for (size_t at = svg.find(open); at != std::string::npos; at = svg.find(open, at + 1)) {
    const size_t end = svg.find('>', at);
    const size_t body = svg.find(tail, at);
    if (end == std::string::npos || body == std::string::npos || body + tail.size() != end + 1) continue;
    const size_t close = svg.find("</text>", end);
    if (close == std::string::npos) continue;
    out.emplace_back(std::stod(svg.substr(at + open.size())), svg.substr(end + 1, close - end - 1));
  }
  return out;
}

TEST(RenderChart, AxisFitsTheDataAndTheLegendStaysInside) {
  render::Chart ch;
  ch.title = "loop";
  ch.x_label = "plate displacement [mm]";
  ch.y_label = "force [N]";
  ch.curves.push_back({"measured", {110, 110, 118}, 1.5, {0, 1, 1.5, 3.5}, {0, 2000, 3400, 200}});
  ch.band_legend.push_back({"loading in contact", {240, 230, 250}});
  ch.band_legend.push_back({std::string(200, 'x'), {250, 222, 222}});
  const std::string svg = render::chart_svg(ch);
  EXPECT_EQ(svg.find(">-1000<"), std::string::npos);
  EXPECT_NE(svg.find(">3000<"), std::string::npos);
  EXPECT_NE(svg.find(">loading in contact<"), std::string::npos);
  // Every text ends inside the picture (the SVG's font: 7.8 px a character).
  const auto texts = svg_texts(svg, "start");
  EXPECT_FALSE(texts.empty());
  for (const auto& [x, text] : texts) {
    EXPECT_LE(x + 7.8 * static_cast<double>(text.size()), render::kChartWidth) << text;
  }
  // The raster: the rightmost columns are blank, no text runs off the edge.
  const render::Image png = render::chart_png(ch);
  for (int y = 0; y < png.height; ++y) {
    for (int x = png.width - 3; x < png.width; ++x) {
      EXPECT_EQ(png.at(x, y), (render::Rgb{255, 255, 255})) << x << "," << y;
    }
  }
}

// The timeline's lanes name the functions of the rules, any length: a long
// name widens the left margin and still starts inside the picture.
TEST(RenderChart, TimelineLaneNamesStayInside) {
  render::Timeline tl;
  tl.title = "t";
  tl.functions = {"pinch", "squeeze_until_the_shell_gives"};
  tl.samples = {{0, 0, 0, 0}, {1, 0.1, 10, 0}};
  tl.end_time = 1;
  const std::string svg = render::plot_svg(tl);
  int names = 0;
  for (const auto& [x, text] : svg_texts(svg, "end")) {
    EXPECT_GE(x - 7.8 * static_cast<double>(text.size()), 0) << text;
    names += text == "squeeze_until_the_shell_gives";
  }
  EXPECT_EQ(names, 1);
}

}  // namespace
}  // namespace afford
