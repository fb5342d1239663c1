#include "maps.h"

#include <algorithm>
#include <filesystem>

#include "files.h"
#include "png.h"
#include "reports.h"
#include "units.h"

namespace afford {
namespace {

using render::Anchor;
using render::Rgb;

constexpr Rgb kInk{40, 44, 52}, kAxisInk{120, 126, 138}, kThreshold{0, 0, 0};
constexpr Rgb kNone{228, 230, 235};  // no function inferred
// One colour per function, in file order (cycled past eight).
constexpr Rgb kPalette[] = {{102, 166, 30}, {27, 158, 119}, {117, 112, 179}, {217, 95, 2},
                            {231, 41, 138}, {230, 171, 2}, {166, 118, 29}, {31, 120, 180}};

constexpr int kPanel = 180;  // px, a panel's plot square
constexpr int kLeft = 70, kTop = 110, kGapX = 80, kGapY = 80, kRight = 20, kBottom = 10, kMinWidth = 720;

// An actee's name as a file name: letters, digits, '-', '_' and '.' kept,
// anything else (a '/' above all) made '_'.
std::string file_stem(const std::string& name) {
  std::string stem = name;
  for (char& ch : stem) {
    const bool plain = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '-' ||
                       ch == '_' || ch == '.';
    if (!plain) ch = '_';
  }
  return stem.empty() || stem[0] == '.' ? "_" + stem : stem;
}

Rgb colour(int outcome) {
  return outcome < 0 ? kNone : kPalette[static_cast<size_t>(outcome) % (sizeof kPalette / sizeof kPalette[0])];
}

}  // namespace

void map_size(const GridInfo& g, int* width, int* height) {
  const int columns = static_cast<int>(g.thumbs.size()), rows = static_cast<int>(g.grasps.size());
  // At least wide enough for the legend.
  *width = std::max(kMinWidth, kLeft + columns * kPanel + (columns - 1) * kGapX + kRight);
  *height = kTop + rows * (kPanel + kGapY) + kBottom;
}

void draw_map(render::Canvas& c, const GridInfo& g, const ExploreResult& r, int actee) {
  const GridActee& a = g.actees[static_cast<size_t>(actee)];
  int width = 0, height = 0;
  map_size(g, &width, &height);
  c.rect(0, 0, width, height, {255, 255, 255});
  c.text(kLeft, 16, a.name + " in the " + g.object, kInk);
  c.text(kLeft, 36, "how each point ends, by placement (across) and effort (up)", kAxisInk);
  // The legend: every outcome, in file order, then none.
  double lx = kLeft;
  for (int o = 0; o <= static_cast<int>(g.functions.size()); ++o) {
    const int outcome = o < static_cast<int>(g.functions.size()) ? o : -1;
    const std::string name = outcome_name(g, outcome);
    c.rect(lx, 56, 14, 14, colour(outcome));
    c.text(lx + 18, 63, name, kInk);
    lx += 18 + c.text_width(name) + 16;
  }
  c.line(lx, 63, lx + 20, 63, kThreshold, 2);
  c.text(lx + 24, 63, "threshold", kInk);

  // Effort i is the row centred on efforts[i] (evenly spaced); y(F) places any effort on that scale.
  const double rows = static_cast<double>(g.efforts.size());
  const double step = g.efforts.size() > 1 ? g.efforts[1] - g.efforts[0] : g.efforts[0];
  const double bottom_effort = g.efforts.front() - 0.5 * step;  // N, at the panel's bottom edge
  const double cell_w = static_cast<double>(kPanel) / static_cast<double>(a.placements.size());
  const double cell_h = static_cast<double>(kPanel) / rows;
  auto y_of = [&](double y0, double effort) { return y0 + kPanel - (effort - bottom_effort) / (step * rows) * kPanel; };
  for (const SeriesResult& s : r.series) {
    if (s.key.actee != actee) continue;
    const double x0 = kLeft + s.key.thumb * (kPanel + kGapX);
    const double y0 = kTop + s.key.grasp * (kPanel + kGapY);
    const double x = x0 + s.key.placement * cell_w;
    for (size_t i = 0; i < s.points.size(); ++i) {
      c.rect(x, y0 + kPanel - (static_cast<double>(i) + 1) * cell_h, cell_w, cell_h, colour(outcome(s.points[i])));
    }
    for (const Threshold& t : s.thresholds) {
      const double y = y_of(y0, t.effort);
      c.line(x, y, x + cell_w, y, kThreshold, 2);
    }
    if (s.key.placement != 0) continue;
    // The panel's frame and labels, once per panel.
    const std::string grasp = g.grasps[static_cast<size_t>(s.key.grasp)];
    c.text(x0, y0 - (grasp == "-" ? 12 : 30),
           "thumb at " + format_quantity(g.thumbs[static_cast<size_t>(s.key.thumb)], dim::length), kInk);
    if (grasp != "-") c.text(x0, y0 - 12, grasp, kInk);
    c.line(x0, y0 + kPanel, x0 + kPanel, y0 + kPanel, kAxisInk, 1);
    c.line(x0, y0, x0, y0 + kPanel, kAxisInk, 1);
    c.text(x0 - 4, y_of(y0, g.efforts.back()), format_quantity(g.efforts.back(), dim::force), kAxisInk, Anchor::end);
    if (g.efforts.size() > 1) {
      c.text(x0 - 4, y_of(y0, g.efforts.front()), format_quantity(g.efforts.front(), dim::force), kAxisInk, Anchor::end);
    }
    c.text(x0, y0 + kPanel + 12, format_quantity(a.placements.front(), dim::length), kAxisInk, Anchor::start);
    c.text(x0 + kPanel, y0 + kPanel + 12, format_quantity(a.placements.back(), dim::length), kAxisInk, Anchor::end);
  }
}

std::vector<std::string> write_maps(const std::string& dir, const GridInfo& g, const ExploreResult& r) {
  std::vector<std::string> written;
  std::filesystem::create_directories(dir);
  int width = 0, height = 0;
  map_size(g, &width, &height);
  for (size_t a = 0; a < g.actees.size(); ++a) {
    if (!g.actees[a].fits) continue;
    // Two actees of one name (from two folders): the later ones get their place in the list.
    std::string name = file_stem(g.actees[a].name);
    const auto same = [&](const GridActee& b) { return b.name == g.actees[a].name; };
    if (std::any_of(g.actees.begin(), g.actees.begin() + static_cast<long>(a), same)) name += "-" + std::to_string(a + 1);
    const std::string stem = (std::filesystem::path(dir) / name).string();
    render::SvgCanvas svg(width, height);
    draw_map(svg, g, r, static_cast<int>(a));
    write_file_checked(stem + ".svg", svg.finish());
    render::Image img(width, height);
    render::RasterCanvas raster(&img);
    draw_map(raster, g, r, static_cast<int>(a));
    render::write_png(stem + ".png", img);
    written.push_back(stem + ".svg");
    written.push_back(stem + ".png");
  }
  return written;
}

}  // namespace afford
