// The text of a session's frame, around its picture and never over it: a
// bar above the scene with the time, the angle, the forces and the actee's
// state (with the key to the markers and arrows beside it, when the frame
// is wide enough), and a bar below with the functions inferred so far. The
// bars' heights are fixed for a session (from the most lines its frames
// need), so that the scene keeps its place from frame to frame.
//
// Rules, so that no label is cut: text is flowed into lines by text_fit.h
// and measured with the font; the info bar takes at most a quarter of the
// frame's height and the inferred bar two lines ("+N more" for the rest);
// the key goes beside the info from 480 x 240 px, else in the bottom
// bar when the frame is at least 240 px high, else it is left out; the
// scene keeps at least half the height (on a small frame the inferred bar
// shrinks to one line, then goes).
#pragma once

#include <string>
#include <vector>

#include "image.h"
#include "model.h"
#include "state.h"

namespace afford::render {

// A rectangle of pixels: x right, y down from the top-left corner.
struct PixelBox {
  int x = 0, y = 0, w = 0, h = 0;
  bool empty() const { return w <= 0 || h <= 0; }
  bool intersects(const PixelBox& o) const {
    return !empty() && !o.empty() && x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
  }
  bool contains(const PixelBox& o) const { return o.x >= x && o.y >= y && o.x + o.w <= x + w && o.y + o.h <= y + h; }
};

struct FrameLayout {
  int width = 0, height = 0;               // px, the whole frame
  int scale = 1;                           // of the text (image.h's font)
  int line_height = 0;                     // px, a line of text at the scale
  size_t info_lines = 0;                   // lines the info bar holds
  size_t inferred_lines = 0;               // lines the inferred bar holds
  PixelBox info, scene, inferred, legend;  // legend empty: left out
};

// The text scale of a frame of width x height px (2 from 480 x 240), and
// the width left for the info's lines (the key beside it takes its part).
int overlay_scale(int width, int height);
int info_width(int width, int height);

// The info of a state in groups that each start a line: time and angle;
// the forces; the actee's state, its contacts and the grasp.
std::vector<std::vector<std::string>> info_groups(const Model& model, const State& state);
// The lines that info needs on a frame of width x height px, unlimited.
size_t info_lines_needed(const Model& model, const State& state, int width, int height);
// An inferred function as the bar shows it: "carry 2.78 s".
std::string inferred_item(const std::string& function, double t);

// The layout for a session whose frames need at most `info_lines` lines of
// info and `inferred` items (both capped by the rules above).
FrameLayout frame_layout(int width, int height, size_t info_lines, const std::vector<std::string>& inferred);

// The frame: the scene picture (layout.scene's size) in its place, the bars
// around it with the info, the key and the inferred functions so far.
Image compose_frame(const Image& scene, const FrameLayout& layout, const std::vector<std::vector<std::string>>& info,
                    const std::vector<std::string>& inferred);

// The lines each bar shows (what compose_frame draws; each fits its bar).
std::vector<std::string> info_text(const FrameLayout& layout, const std::vector<std::vector<std::string>>& info);
std::vector<std::string> inferred_text(const FrameLayout& layout, const std::vector<std::string>& inferred);

}  // namespace afford::render
