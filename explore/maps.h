// The picture a user looks at first: per actee, the outcome of every point
// over placement (across) and effort (up, the actee's own axis), one panel
// per thumb position and grasp type, the thresholds drawn as black lines at
// the efforts where the outcome turns, efforts beyond a grasp's cap hatched.
// Grasp types whose panels are alike everywhere share one row, labelled
// with all of them (alike_grasps). As SVG and PNG from one layout
// (render/canvas.h).
#pragma once

#include <string>
#include <vector>

#include "canvas.h"
#include "results.h"

namespace afford {

// Draws actee `actee`'s map on a canvas of map_size(g) pixels.
void draw_map(render::Canvas& c, const GridInfo& g, const ExploreResult& r, int actee);
void map_size(const GridInfo& g, const ExploreResult& r, int actee, int* width, int* height);

// Writes DIR/ACTEE.svg and DIR/ACTEE.png for every actee that fits; returns the paths.
std::vector<std::string> write_maps(const std::string& dir, const GridInfo& g, const ExploreResult& r);

}  // namespace afford
