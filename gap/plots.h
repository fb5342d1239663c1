// The diagnosis as pictures (`afford gap --out DIR`): the residual over
// time with the phases shaded, and the force-angle (or force-displacement)
// loop, measured against nominal and against the effects fitted on the
// other traces. Each as SVG and PNG from one layout.
#pragma once

#include <string>
#include <vector>

#include "chart.h"
#include "diagnose.h"

namespace afford {

render::Chart residual_chart(const Diagnosis& d);
render::Chart loop_chart(const Diagnosis& d);

// Writes residual.svg, residual.png, loop.svg and loop.png into dir (made
// if missing); returns their paths. A failed write throws with the path.
std::vector<std::string> write_gap_plots(const Diagnosis& d, const std::string& dir);

}  // namespace afford
