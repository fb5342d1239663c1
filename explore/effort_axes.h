// Each actee's effort axis where its outcome turns. A common 0-400 N axis
// squeezes a grape's turns (a few newtons) into a few pixels of its map and
// a few points of its table; so every series is first run on the common
// axis, the last turn of each found by bisection, and the actee's axis then
// runs from 0 N to a little above its last turn (grid_axis.h). Every shard
// runs this first part whole, so that all of them agree on the axes.
#pragma once

#include <cstddef>
#include <functional>

#include "explore.h"

namespace afford {

// Scales e.grid.actees[*].efforts (an actee without a turn keeps the
// common axis); a grid of one effort is left as it is. `progress(done,
// total)` counts the sessions. Same axes whatever the number of threads.
void fit_effort_axes(Explorer& e, int threads, const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace afford
