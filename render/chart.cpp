#include "chart.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "axis_range.h"
#include "canvas.h"
#include "palette.h"

namespace afford::render {
namespace {

constexpr Rgb kMarker{150, 150, 160};
constexpr double kLeft = 86, kTop = 70, kBottom = 64;
constexpr double kKey = 34, kGap = 16;  // px: a legend entry's line or swatch with its space; panel to legend

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
};

// The labels of the legend, in order, each once.
std::vector<std::string> legend_labels(const Chart& ch) {
  std::vector<std::string> shown;
  for (const ChartCurve& cv : ch.curves) {
    if (!cv.label.empty() && std::find(shown.begin(), shown.end(), cv.label) == shown.end()) shown.push_back(cv.label);
  }
  for (const ChartLegendBand& b : ch.band_legend) shown.push_back(b.label);
  return shown;
}

void draw(Canvas& c, const Chart& ch, int width, int height) {
  // The legend's column is as wide as its longest label (measured in the
  // canvas's font), up to 40 % of the picture; longer labels are shortened.
  const std::vector<std::string> labels = legend_labels(ch);
  double label_w = 0;
  for (const std::string& l : labels) label_w = std::max(label_w, c.text_width(l));
  const double right = std::min(kGap + kKey + label_w + 12, 0.4 * width);
  const double label_room = right - kGap - kKey - 12;
  const double x0 = kLeft, x1 = width - right, top = kTop, bottom = height - kBottom;
  Range xr, yr;
  for (const ChartCurve& cv : ch.curves) {
    for (double v : cv.x) xr.add(v);
    for (double v : cv.y) yr.add(v);
  }
  if (ch.zero_line) yr.add(0);
  const AxisRange ya_r = axis_range(yr.lo, yr.hi, 6, 0.04), xa = axis_range(xr.lo, xr.hi, 10, 0);
  const double y_step = ya_r.step, x_step = xa.step;
  const Axis ya{ya_r.lo, ya_r.hi, top, bottom};
  const double xlo = xa.lo, xhi = xa.hi;
  auto X = [&](double v) { return x0 + (v - xlo) / (xhi - xlo) * (x1 - x0); };

  c.rect(0, 0, width, height, {255, 255, 255});
  c.text(12, 16, fit_to(c, ch.title, width - 16), kInk);
  c.rect(x0, top, x1 - x0, bottom - top, kPanel);
  for (const ChartBand& b : ch.bands) {
    const double a = std::clamp(X(b.x0), x0, x1), e = std::clamp(X(b.x1), x0, x1);
    if (e > a) c.rect(a, top, e - a, bottom - top, b.colour);
  }
  for (double v = ya_r.first_tick(); v <= ya.hi + y_step * 1e-6; v += y_step) {
    c.line(x0, ya.y(v), x1, ya.y(v), kGrid, 1);
    c.line(x0 - 5, ya.y(v), x0, ya.y(v), kAxisInk, 1);
    c.text(x0 - 8, ya.y(v), tick_label(v, y_step), kInk, Anchor::end);
  }
  for (double v = xa.first_tick(); v <= xhi + x_step * 1e-6; v += x_step) {
    c.line(X(v), top, X(v), bottom, kGrid, 1);
    c.line(X(v), bottom, X(v), bottom + 5, kAxisInk, 1);
    c.text(X(v), bottom + 16, tick_label(v, x_step), kInk, Anchor::middle);
  }
  c.line(x0, top, x0, bottom, kAxisInk, 1);
  c.line(x0, bottom, x1, bottom, kAxisInk, 1);
  c.text((x0 + x1) / 2, bottom + 40, ch.x_label, kInk, Anchor::middle);
  c.text(12, top - 20, ch.y_label, kInk);  // clear of the top tick's label
  if (ch.zero_line) c.line(x0, ya.y(0), x1, ya.y(0), kAxisInk, 1);
  for (const ChartMarker& m : ch.markers) {
    c.line(X(m.x), top, X(m.x), bottom, kMarker, 1, 4);
    c.rect(X(m.x) + 2, top + 2, c.text_width(m.label) + 4, 16, {255, 255, 255});
    c.text(X(m.x) + 4, top + 10, m.label, kMarker);
  }

  // The curves, a point wherever the pen has moved half a pixel: as much
  // as the eye sees, and a 10 s trace at 1 kHz stays a small SVG. A value
  // that is not finite ends a stretch.
  for (const ChartCurve& cv : ch.curves) {
    std::vector<Pt> pts;
    auto flush = [&] {
      if (pts.size() > 1) c.polyline(pts, cv.colour, cv.width);
      pts.clear();
    };
    const size_t n = std::min(cv.x.size(), cv.y.size());
    for (size_t i = 0; i < n; ++i) {
      if (!std::isfinite(cv.x[i]) || !std::isfinite(cv.y[i])) {
        flush();
        continue;
      }
      const Pt p{X(cv.x[i]), ya.y(cv.y[i])};
      const bool last = i + 1 == n || !std::isfinite(cv.y[i + 1]);
      if (!pts.empty() && !last && std::abs(p.x - pts.back().x) < 0.5 && std::abs(p.y - pts.back().y) < 0.5) continue;
      pts.push_back(p);
    }
    flush();
  }

  // Legend, right of the panel, inside the picture.
  double ly = top + 8;
  const double lx = x1 + kGap;
  std::vector<std::string> shown;
  for (const ChartCurve& cv : ch.curves) {
    if (cv.label.empty() || std::find(shown.begin(), shown.end(), cv.label) != shown.end()) continue;
    shown.push_back(cv.label);
    c.line(lx, ly, lx + 26, ly, cv.colour, 2.5);
    c.text(lx + kKey, ly, fit_to(c, cv.label, label_room), kInk);
    ly += 22;
  }
  if (!ch.band_legend.empty()) ly += 8;
  for (const ChartLegendBand& b : ch.band_legend) {
    c.rect(lx, ly - 8, 26, 16, b.colour);
    c.text(lx + kKey, ly, fit_to(c, b.label, label_room), kInk);
    ly += 22;
  }
}

}  // namespace

std::string chart_svg(const Chart& chart, int width, int height) {
  SvgCanvas c(width, height);
  draw(c, chart, width, height);
  return c.finish();
}

Image chart_png(const Chart& chart, int width, int height) {
  Image img(width, height);
  RasterCanvas c(&img);
  draw(c, chart, width, height);
  return img;
}

}  // namespace afford::render
