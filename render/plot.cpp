#include "plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "axis_range.h"
#include "canvas.h"
#include "palette.h"

namespace afford::render {
namespace {

constexpr Rgb kAngle{52, 101, 164}, kEffort{230, 140, 10}, kActeeForce{200, 30, 30}, kLimit{120, 20, 20};
constexpr Rgb kReached{40, 150, 70}, kLost{200, 60, 40};

constexpr int kPlotLeft = 86, kRight = 200, kPlotTop = 58, kPanelA = 170, kPanelGap = 34, kPanelB = 230, kLane = 24;

void draw(Canvas& c, const Timeline& tl, int width, int height) {
  // The lanes' function names (from the rules, any length) stand left of
  // the panels: the margin grows to the longest, up to a third of the width.
  double names = 0;
  for (const std::string& f : tl.functions) names = std::max(names, c.text_width(f));
  const double x0 = std::clamp(names + 20, static_cast<double>(kPlotLeft), width / 3.0), x1 = width - kRight;
  const double t_end = std::max(tl.end_time, tl.samples.empty() ? 1.0 : tl.samples.back().t);
  auto X = [&](double t) { return x0 + t / std::max(t_end, 1e-9) * (x1 - x0); };
  const double rad2deg = 180 / std::numbers::pi;

  c.rect(0, 0, width, height, {255, 255, 255});
  const std::string title = tl.title + ": timeline" + (tl.has_actee ? " (actee " + tl.actee_name + ")" : std::string());
  c.text(12, 14, fit_to(c, title, width - 16), kInk);

  // Data ranges: the angle from its closed 0 deg, the forces from 0 N and
  // through the actee's limit (axis_range.h says how the ends are chosen).
  double a_lo = 0, a_hi = 0, f_lo = 0, f_hi = 0;
  for (const TimelineSample& s : tl.samples) {
    a_lo = std::min(a_lo, s.angle * rad2deg);
    a_hi = std::max(a_hi, s.angle * rad2deg);
    f_lo = std::min({f_lo, s.effort, s.actee});
    f_hi = std::max({f_hi, s.effort, s.actee});
  }
  if (tl.has_actee) f_hi = std::max(f_hi, tl.limit);
  const AxisRange a_range = axis_range(a_lo, std::max(a_hi, a_lo + 1), 5, 0.04);
  const AxisRange f_range = axis_range(f_lo, std::max(f_hi, f_lo + 1), 6, 0.04);
  const double a_step = a_range.step, f_step = f_range.step;
  const Axis angle{a_range.lo, a_range.hi, kPlotTop, kPlotTop + kPanelA};
  const Axis force{f_range.lo, f_range.hi, kPlotTop + kPanelA + kPanelGap, kPlotTop + kPanelA + kPanelGap + kPanelB};
  const double lanes_top = force.bottom + kPanelGap;
  const double lanes_bottom = lanes_top + kLane * static_cast<double>(tl.functions.size());
  const double t_step = tick_step(t_end, 10);

  // Panels with grids and tick labels.
  for (const auto& [axis, step, unit] : {std::tuple{angle, a_step, "angle [deg]"}, std::tuple{force, f_step, "force [N]"}}) {
    c.rect(x0, axis.top, x1 - x0, axis.bottom - axis.top, kPanel);
    for (double v = std::ceil(axis.lo / step - 1e-9) * step; v <= axis.hi + step * 1e-6; v += step) {
      const double y = axis.y(v);
      c.line(x0, y, x1, y, kGrid, 1);
      c.line(x0 - 5, y, x0, y, kAxisInk, 1);
      c.text(x0 - 8, y, tick_label(v, step), kInk, Anchor::end);
    }
    for (double t = 0; t <= t_end + t_step * 1e-6; t += t_step) c.line(X(t), axis.top, X(t), axis.bottom, kGrid, 1);
    c.line(x0, axis.top, x0, axis.bottom, kAxisInk, 1);
    c.line(x0, axis.bottom, x1, axis.bottom, kAxisInk, 1);
    c.text(x0, axis.top - 12, unit, kInk);  // over the panel: clear of the tick labels left of it
  }
  // Time axis under the lanes.
  const double t_axis = lanes_bottom + 6;
  c.line(x0, t_axis, x1, t_axis, kAxisInk, 1);
  for (double t = 0; t <= t_end + t_step * 1e-6; t += t_step) {
    c.line(X(t), t_axis, X(t), t_axis + 5, kAxisInk, 1);
    c.text(X(t), t_axis + 16, tick_label(t, t_step), kInk, Anchor::middle);
  }
  c.text((x0 + x1) / 2, t_axis + 36, "time [s]", kInk, Anchor::middle);

  // Inferred functions: a line through both panels and the lanes.
  for (const TimelineMark& m : tl.marks) {
    if (m.kind == EventKind::inferred) c.line(X(m.t), angle.top, X(m.t), lanes_bottom, function_colour(m.function), 1.5, 5);
  }

  // The curves.
  auto curve = [&](const Axis& axis, auto value, Rgb col, double stroke) {
    std::vector<Pt> pts;
    double last_x = -1e9;
    for (size_t i = 0; i < tl.samples.size(); ++i) {
      const double x = X(tl.samples[i].t);
      // One point per half pixel is as much as the eye sees.
      if (x - last_x < 0.5 && i + 1 < tl.samples.size()) continue;
      pts.push_back({x, axis.y(value(tl.samples[i]))});
      last_x = x;
    }
    c.polyline(pts, col, stroke);
  };
  curve(angle, [&](const TimelineSample& s) { return s.angle * rad2deg; }, kAngle, 2);
  if (tl.has_actee) c.line(x0, force.y(tl.limit), x1, force.y(tl.limit), kLimit, 1.5, 7);
  curve(force, [](const TimelineSample& s) { return s.effort; }, kEffort, 2);
  if (tl.has_actee) curve(force, [](const TimelineSample& s) { return s.actee; }, kActeeForce, 2);

  // The inferred functions' names over the curves, on white, each in the
  // first row where it overlaps no other name.
  std::vector<std::vector<std::pair<double, double>>> rows;
  for (const TimelineMark& m : tl.marks) {
    if (m.kind != EventKind::inferred) continue;
    const Rgb col = function_colour(m.function);
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s %.2f s", tl.functions[static_cast<size_t>(m.function)].c_str(), m.t);
    const double w = c.text_width(buf) + 8;
    const bool left = X(m.t) + 4 + w > x1;
    const double bx = left ? X(m.t) - 4 - w : X(m.t) + 4;
    size_t row = 0;
    for (; row < rows.size(); ++row) {
      bool clear = true;
      for (const auto& [a, b] : rows[row]) clear = clear && (bx + w < a || bx > b);
      if (clear) break;
    }
    if (row == rows.size()) rows.emplace_back();
    rows[row].push_back({bx, bx + w});
    const double y = angle.top + 16 + 22 * static_cast<double>(row % 6);
    c.rect(bx, y - 9, w, 18, {255, 255, 255});
    c.text(bx + 4, y, buf, col);
  }

  // Lanes: each function's nodes reached (up triangle) and lost (down).
  for (size_t f = 0; f < tl.functions.size(); ++f) {
    const double y = lanes_top + kLane * (static_cast<double>(f) + 0.5);
    if (f % 2 == 0) c.rect(x0, y - kLane / 2.0, x1 - x0, kLane, {246, 247, 250});
    c.text(x0 - 8, y, fit_to(c, tl.functions[f], x0 - 12), function_colour(static_cast<int>(f)), Anchor::end);
  }
  for (const TimelineMark& m : tl.marks) {
    const double y = lanes_top + kLane * (m.function + 0.5), x = X(m.t);
    if (m.kind == EventKind::node_reached) {
      c.polygon({{x - 5, y + 5}, {x + 5, y + 5}, {x, y - 5}}, kReached);
    } else if (m.kind == EventKind::node_lost) {
      c.polygon({{x - 5, y - 5}, {x + 5, y - 5}, {x, y + 5}}, kLost);
    } else {
      c.polygon({{x, y - 8}, {x + 8, y}, {x, y + 8}, {x - 8, y}}, function_colour(m.function));
    }
  }

  // Legend, right of the panels.
  double ly = angle.top + 8;
  const double lx = x1 + 16;
  auto entry = [&](Rgb col, const std::string& label, double dash) {
    c.line(lx, ly, lx + 26, ly, col, 2.5, dash);
    c.text(lx + 34, ly, label, kInk);
    ly += 22;
  };
  entry(kAngle, "angle", 0);
  entry(kEffort, "effort force", 0);
  if (tl.has_actee) {
    entry(kActeeForce, "actee force", 0);
    entry(kLimit, "actee limit", 7);
  }
  ly += 6;
  c.polygon({{lx + 8, ly + 5}, {lx + 18, ly + 5}, {lx + 13, ly - 5}}, kReached);
  c.text(lx + 34, ly, "node reached", kInk);
  ly += 22;
  c.polygon({{lx + 8, ly - 5}, {lx + 18, ly - 5}, {lx + 13, ly + 5}}, kLost);
  c.text(lx + 34, ly, "node lost", kInk);
  ly += 22;
  c.polygon({{lx + 13, ly - 7}, {lx + 20, ly}, {lx + 13, ly + 7}, {lx + 6, ly}}, kInk);
  c.text(lx + 34, ly, "inferred", kInk);
}

}  // namespace

Rgb function_colour(int function) {
  static constexpr Rgb kPalette[] = {{31, 119, 180}, {44, 160, 44}, {214, 39, 40}, {148, 103, 189},
                                     {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34},
                                     {23, 190, 207}};
  const int n = static_cast<int>(sizeof kPalette / sizeof kPalette[0]);
  return kPalette[((function % n) + n) % n];
}

void TimelineRecorder::on_start(const Model& model, const State&, const RuleSet& rules) {
  timeline_.has_actee = model.has_actee;
  timeline_.limit = model.actee_limit;
  timeline_.actee_name = model.actee_name;
  timeline_.functions.clear();
  for (int f = 0; f < function_count(rules); ++f) timeline_.functions.push_back(function_name(rules, f));
  timeline_.samples.clear();
  timeline_.samples.reserve(1 << 14);
  timeline_.marks.clear();
}

void TimelineRecorder::on_frame(const Model&, const State& s, const RuleSet& rules, const RuleState& rs) {
  timeline_.samples.push_back({s.t, s.theta, s.effort_force, s.actee_force});
  timeline_.end_time = s.t;
  for (const Event* e = events_begin(rs); e != events_end(rs); ++e) {
    const int nodes = node_count(rules, e->function);
    int node = e->kind == EventKind::inferred ? nodes - 1 : e->node;
    std::string text = node >= 0 && node < nodes ? node_text(rules, e->function, node) : std::string();
    timeline_.marks.push_back({e->t, e->kind, e->function, node, std::move(text)});
  }
}

int plot_height(const Timeline& tl) {
  return kPlotTop + kPanelA + kPanelGap + kPanelB + kPanelGap + kLane * static_cast<int>(tl.functions.size()) + 56;
}

std::string plot_svg(const Timeline& tl, int width) {
  SvgCanvas c(width, plot_height(tl));
  draw(c, tl, width, plot_height(tl));
  return c.finish();
}

Image plot_png(const Timeline& tl, int width) {
  Image img(width, plot_height(tl));
  RasterCanvas c(&img);
  draw(c, tl, width, plot_height(tl));
  return img;
}

}  // namespace afford::render
