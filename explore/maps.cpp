#include "maps.h"

#include <algorithm>
#include <filesystem>

#include "files.h"
#include "image.h"
#include "png.h"
#include "reports.h"
#include "units.h"

namespace afford {
namespace {

using render::Anchor;
using render::Rgb;

constexpr Rgb kInk{40, 44, 52}, kAxisInk{120, 126, 138}, kThreshold{0, 0, 0};
constexpr Rgb kNone{228, 230, 235};  // no function inferred
constexpr Rgb kBeyond{255, 255, 255}, kBeyondInk{150, 154, 162};  // beyond the grasp's cap: hatched, not an outcome
// One colour per function, in file order (cycled past eight).
constexpr Rgb kPalette[] = {{102, 166, 30}, {27, 158, 119}, {117, 112, 179}, {217, 95, 2},
                            {231, 41, 138}, {230, 171, 2}, {166, 118, 29}, {31, 120, 180}};

constexpr int kPanel = 180;  // px, a panel's plot square
constexpr int kLeft = 70, kTop = 140, kGapX = 80, kGapY = 80, kRight = 20, kBottom = 10, kMinWidth = 800;
constexpr int kAxisLabels = 20;  // px below the last row, for its placements
constexpr const char* kSubtitle = "the strongest function reached while the effort was applied";

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

// A cell beyond the grasp's cap: hatched, as no outcome of its own.
void hatch(render::Canvas& c, double x, double y, double w, double h) {
  c.rect(x, y, w, h, kBeyond);
  constexpr double kSpacing = 6;  // px
  for (double d = kSpacing; d < w + h; d += kSpacing) {
    // From the left or the bottom edge up and to the right, clipped to the cell.
    const double x0 = x + std::max(0.0, d - h), y0 = y + h - std::min(d, h);
    const double x1 = x + std::min(d, w), y1 = y + h - std::max(0.0, d - w);
    c.line(x0, y0, x1, y1, kBeyondInk, 1);
  }
}

// A row's grasps, as many as fit in `room` px: "a, b (alike)", "every
// grasp type (alike)", or "a, b and 3 more (alike, summary.txt)".
std::string row_label(const render::Canvas& c, const GridInfo& g, const std::vector<int>& group, double room) {
  if (group.size() == 1) return g.grasps[static_cast<size_t>(group.front())];
  if (group.size() == g.grasps.size()) return "every grasp type (alike)";
  std::string names;
  for (size_t i = 0; i < group.size(); ++i) {
    const std::string more = names + (names.empty() ? "" : ", ") + g.grasps[static_cast<size_t>(group[i])];
    const std::string rest = " and " + std::to_string(group.size() - i - 1) + " more (alike, summary.txt)";
    if (i + 1 < group.size() && c.text_width(more + rest) > room) {
      return names + " and " + std::to_string(group.size() - i) + " more (alike, summary.txt)";
    }
    names = more;
  }
  return names + " (alike)";
}

}  // namespace

void map_size(const GridInfo& g, const ExploreResult& r, int actee, int* width, int* height) {
  const int columns = static_cast<int>(g.thumbs.size());
  const int rows = static_cast<int>(alike_grasps(g, r, actee).size());
  // At least wide enough for the legend and the subtitle (in the raster's
  // font, the wider of the two canvases').
  *width = std::max({kMinWidth, kLeft + columns * kPanel + (columns - 1) * kGapX + kRight,
                     kLeft + render::text_width(kSubtitle, 2) + kRight});
  *height = kTop + rows * (kPanel + kGapY) - kGapY + kAxisLabels + kBottom;
}

void draw_map(render::Canvas& c, const GridInfo& g, const ExploreResult& r, int actee) {
  const GridActee& a = g.actees[static_cast<size_t>(actee)];
  int width = 0, height = 0;
  map_size(g, r, actee, &width, &height);
  // One row per group of grasps alike everywhere, labelled with all of them.
  const std::vector<std::vector<int>> groups = alike_grasps(g, r, actee);
  std::vector<int> row_of(g.grasps.size(), 0);
  for (size_t row = 0; row < groups.size(); ++row) {
    for (int k : groups[row]) row_of[static_cast<size_t>(k)] = static_cast<int>(row);
  }
  c.rect(0, 0, width, height, {255, 255, 255});
  c.text(kLeft, 16, a.name + " in the " + g.object, kInk);
  c.text(kLeft, 36, kSubtitle, kAxisInk);
  // The legend: none, then every outcome from the weakest to the strongest.
  double lx = kLeft;
  for (int outcome : outcomes_by_strength(g)) {
    const std::string name = outcome_name(g, outcome);
    c.rect(lx, 56, 14, 14, colour(outcome));
    c.text(lx + 18, 63, name, kInk);
    lx += 18 + c.text_width(name) + 16;
  }
  // Below the outcomes, so that a long list of functions does not push it off the picture.
  c.line(kLeft, 85, kLeft + 20, 85, kThreshold, 2);
  c.text(kLeft + 24, 85, "threshold", kInk);
  lx = kLeft + 24 + c.text_width("threshold") + 16;
  hatch(c, lx, 78, 14, 14);
  c.text(lx + 18, 85, "beyond the grasp's cap: pushed at the cap", kInk);

  // Effort i is the row centred on efforts[i] (evenly spaced); y(F) places any effort on that scale.
  const std::vector<double>& efforts = a.efforts;
  const double rows = static_cast<double>(efforts.size());
  const double step = efforts.size() > 1 ? efforts[1] - efforts[0] : efforts[0];
  const double bottom_effort = efforts.front() - 0.5 * step;  // N, at the panel's bottom edge
  const double cell_w = static_cast<double>(kPanel) / static_cast<double>(a.placements.size());
  auto y_of = [&](double y0, double effort) { return y0 + kPanel - (effort - bottom_effort) / (step * rows) * kPanel; };
  // The cells and thresholds first, then the panels' frames and labels over them.
  for (int pass = 0; pass < 2; ++pass) {
    for (const SeriesResult& s : r.series) {
      if (s.key.actee != actee) continue;
      const int row = row_of[static_cast<size_t>(s.key.grasp)];
      if (groups[static_cast<size_t>(row)].front() != s.key.grasp) continue;  // drawn with the first of its row
      const double x0 = kLeft + s.key.thumb * (kPanel + kGapX);
      const double y0 = kTop + row * (kPanel + kGapY);
      const double x = x0 + s.key.placement * cell_w;
      const double cap = g.grasp_limit[static_cast<size_t>(s.key.grasp)];
      if (pass == 0) {
        for (size_t i = 0; i < s.points.size(); ++i) {
          // The cell's part below the grasp's cap in its outcome (above the
          // cap the point is the cap's run), the part above hatched.
          const double lo = efforts[i] - 0.5 * step, hi = efforts[i] + 0.5 * step;  // N
          const double split = std::clamp(cap, lo, hi);
          if (split > lo) c.rect(x, y_of(y0, split), cell_w, y_of(y0, lo) - y_of(y0, split), colour(outcome(s.points[i])));
          if (split < hi) hatch(c, x, y_of(y0, hi), cell_w, y_of(y0, split) - y_of(y0, hi));
        }
        for (const Threshold& t : s.thresholds) c.line(x, y_of(y0, t.effort), x + cell_w, y_of(y0, t.effort), kThreshold, 2);
        continue;
      }
      if (s.key.placement != 0) continue;
      // The panel's frame and labels, once per panel; the row's grasps above its first.
      const std::string grasp = g.grasps[static_cast<size_t>(s.key.grasp)];
      c.text(x0, y0 - (grasp == "-" ? 12 : 30),
             "thumb at " + format_quantity(g.thumbs[static_cast<size_t>(s.key.thumb)], dim::length), kInk);
      if (grasp != "-" && s.key.thumb == 0) {
        c.text(x0, y0 - 12, row_label(c, g, groups[static_cast<size_t>(row)], width - kRight - x0), kInk);
      }
      c.line(x0, y0 + kPanel, x0 + kPanel, y0 + kPanel, kAxisInk, 1);
      c.line(x0, y0, x0, y0 + kPanel, kAxisInk, 1);
      c.text(x0 - 4, y_of(y0, efforts.back()), format_quantity(efforts.back(), dim::force), kAxisInk, Anchor::end);
      if (efforts.size() > 1) {
        c.text(x0 - 4, y_of(y0, efforts.front()), format_quantity(efforts.front(), dim::force), kAxisInk, Anchor::end);
      }
      if (cap < efforts.back()) {  // where the grasp's cap cuts the axis
        c.line(x0, y_of(y0, cap), x0 + kPanel, y_of(y0, cap), kBeyondInk, 1, 4);
        c.text(x0 - 4, y_of(y0, cap), format_quantity(cap, dim::force), kAxisInk, Anchor::end);
      }
      c.text(x0, y0 + kPanel + 12, format_quantity(a.placements.front(), dim::length), kAxisInk, Anchor::start);
      c.text(x0 + kPanel, y0 + kPanel + 12, format_quantity(a.placements.back(), dim::length), kAxisInk, Anchor::end);
    }
  }
}

std::vector<std::string> write_maps(const std::string& dir, const GridInfo& g, const ExploreResult& r) {
  std::vector<std::string> written;
  std::filesystem::create_directories(dir);
  for (size_t a = 0; a < g.actees.size(); ++a) {
    if (!g.actees[a].fits) continue;
    int width = 0, height = 0;
    map_size(g, r, static_cast<int>(a), &width, &height);
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
