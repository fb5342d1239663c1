#include "frame_overlay.h"

#include <algorithm>
#include <cstdio>
#include <numbers>

#include "palette.h"
#include "text_fit.h"

namespace afford::render {
namespace {

constexpr Rgb kBar{28, 32, 42}, kInferredInk{255, 220, 120};
constexpr const char* kInfoSep = "   ";
constexpr const char* kInferredSep = "  ";

// The key to the markers and arrows (scene.cpp's palette), at scale 1: small,
// it is read once.
struct Key {
  Rgb c;
  const char* text;
};
constexpr Key kKeys[] = {{{250, 158, 13}, "effort"},
                         {{217, 26, 26}, "jaw force"},
                         {{38, 204, 77}, "jaw contact"},
                         {{26, 166, 242}, "finger contact"}};
constexpr int kKeyLine = kGlyphHeight + 5;  // px
constexpr int kSwatch = 7, kKeyText = 11;   // px: the swatch, and the text's start after it

int key_width(const Key& k) { return kKeyText + text_width(k.text, 1); }

int key_column_width() {
  int w = 0;
  for (const Key& k : kKeys) w = std::max(w, key_width(k));
  return w + 10;  // 5 px each side
}

int key_column_height() { return static_cast<int>(std::size(kKeys)) * kKeyLine + 6; }

// Beside the info on a frame wide and high enough for it (the column is 54 px).
bool key_beside(int width, int height) { return width >= 480 && height >= 240; }

int margin(int scale) { return 6 * scale; }
int pad(int scale) { return 3 * scale; }

// Where each key goes: in a column (beside the info) or flowed in rows
// `width` px wide from (x, y); the rows used.
int place_keys(bool column, int x, int y, int width, std::vector<std::pair<int, int>>* at) {
  int cx = x, cy = y, rows = 1;
  for (const Key& k : kKeys) {
    if (column) {
      if (at) at->push_back({cx, cy});
      cy += kKeyLine;
      continue;
    }
    if (cx > x && cx + key_width(k) > x + width) cx = x, cy += kKeyLine, ++rows;
    if (at) at->push_back({cx, cy});
    cx += key_width(k) + 14;
  }
  return column ? static_cast<int>(std::size(kKeys)) : rows;
}

}  // namespace

int overlay_scale(int width, int height) { return width >= 480 && height >= 240 ? 2 : 1; }

int info_width(int width, int height) {
  const int s = overlay_scale(width, height);
  return width - 2 * margin(s) - (key_beside(width, height) ? key_column_width() + margin(s) : 0);
}

std::vector<std::vector<std::string>> info_groups(const Model& m, const State& s) {
  std::vector<std::vector<std::string>> g;
  g.push_back({printf_number("t %.3f s", s.t), printf_number("angle %.1f deg", s.theta * 180 / std::numbers::pi)});
  g.push_back({printf_number("effort %.1f N", s.effort_force)});
  if (m.has_actee) g.back().push_back(printf_number("actee %.1f", s.actee_force) + printf_number(" / %.0f N", m.actee_limit));
  std::vector<std::string> state;
  if (m.has_actee) {
    state.push_back(m.actee_name + ": " + condition_name(s.condition));
    state.push_back("contacts " + std::to_string(s.object_actee.count));
  }
  state.push_back(s.grasped ? "grasped" : "not grasped");
  g.push_back(std::move(state));
  return g;
}

size_t info_lines_needed(const Model& m, const State& s, int width, int height) {
  return flow(info_groups(m, s), info_width(width, height), overlay_scale(width, height), kInfoSep).size();
}

std::string inferred_item(const std::string& function, double t) { return function + printf_number(" %.2f s", t); }

std::vector<std::string> info_text(const FrameLayout& l, const std::vector<std::vector<std::string>>& info) {
  return flow(info, info_width(l.width, l.height), l.scale, kInfoSep, l.info_lines);
}

std::vector<std::string> inferred_text(const FrameLayout& l, const std::vector<std::string>& inferred) {
  std::vector<std::string> items{"inferred:"};
  items.insert(items.end(), inferred.begin(), inferred.end());
  return flow({items}, l.width - 2 * margin(l.scale), l.scale, kInferredSep, l.inferred_lines);
}

FrameLayout frame_layout(int width, int height, size_t info_lines, const std::vector<std::string>& inferred) {
  FrameLayout l;
  l.width = width;
  l.height = height;
  l.scale = overlay_scale(width, height);
  l.line_height = (kGlyphHeight + 4) * l.scale;
  const int p = pad(l.scale), m = margin(l.scale);
  // At most a quarter of the height for the info, two lines for the inferred.
  const size_t cap = static_cast<size_t>(std::max(1, (height / 4 - 2 * p) / l.line_height));
  l.info_lines = std::clamp<size_t>(info_lines, 1, cap);
  int top = static_cast<int>(l.info_lines) * l.line_height + 2 * p;
  const bool beside = key_beside(width, height);
  if (beside) {
    top = std::max(top, key_column_height());
    l.legend = {width - key_column_width() - m / 2, (top - key_column_height()) / 2, key_column_width(),
                key_column_height()};
  }
  l.info = {0, 0, width, top};
  if (!inferred.empty()) {
    l.inferred_lines = 2;  // at most; as many as the session's whole list needs
    l.inferred_lines = inferred_text(l, inferred).size();
  }
  int key_rows_h = 0;
  if (!beside && height >= 240) key_rows_h = place_keys(false, m, 0, width - 2 * m, nullptr) * kKeyLine + 4;
  auto bottom = [&] {
    return (l.inferred_lines > 0 ? static_cast<int>(l.inferred_lines) * l.line_height + 2 * p : 0) + key_rows_h;
  };
  // The scene keeps at least half the height: on a small frame the
  // inferred bar shrinks to one line, then goes.
  if (top + bottom() > height / 2 && l.inferred_lines > 1) l.inferred_lines = 1;
  if (top + bottom() > height / 2) l.inferred_lines = 0;
  l.inferred = {0, height - bottom(), width, bottom()};
  if (key_rows_h > 0) l.legend = {0, height - bottom(), width, key_rows_h};
  l.scene = {0, top, width, height - top - bottom()};
  return l;
}

Image compose_frame(const Image& scene, const FrameLayout& l, const std::vector<std::vector<std::string>>& info,
                    const std::vector<std::string>& inferred) {
  Image out(l.width, l.height, kBar);
  blit(out, scene, l.scene.x, l.scene.y);
  const int p = pad(l.scale), m = margin(l.scale);
  const std::vector<std::string> lines = info_text(l, info);
  const int info_h = static_cast<int>(lines.size()) * l.line_height;
  for (size_t i = 0; i < lines.size(); ++i) {
    const int y = (l.info.h - info_h) / 2 + static_cast<int>(i) * l.line_height + l.scale;
    draw_text(out, m, y, lines[i], kWhite, l.scale);
  }
  if (!l.legend.empty()) {
    const bool column = key_beside(l.width, l.height);
    std::vector<std::pair<int, int>> at;
    if (column) {
      place_keys(true, l.legend.x + 5, l.legend.y + 4, l.legend.w, &at);
    } else {
      place_keys(false, m, l.legend.y + 3, l.width - 2 * m, &at);
    }
    for (size_t i = 0; i < at.size(); ++i) {
      fill_rect(out, at[i].first, at[i].second, kSwatch, kSwatch, kKeys[i].c);
      draw_text(out, at[i].first + kKeyText, at[i].second, kKeys[i].text, kWhite, 1);
    }
  }
  if (l.inferred_lines > 0) {
    const std::vector<std::string> bar = inferred_text(l, inferred);
    const int y0 = l.inferred.y + l.inferred.h - static_cast<int>(l.inferred_lines) * l.line_height - p;
    for (size_t i = 0; i < bar.size(); ++i) {
      draw_text(out, m, y0 + static_cast<int>(i) * l.line_height + l.scale, bar[i], kInferredInk, l.scale);
    }
  }
  return out;
}

}  // namespace afford::render
