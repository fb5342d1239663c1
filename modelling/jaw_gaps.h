// The interaction space L_is from the real shape (paper Sec. 3.2 step 4):
// how far apart the jaws are at each distance from the pivot along the
// application region, at openings from theta_min to theta_max; an actee
// fits at a distance and opening where it is no larger than the gap there.
// The gap is measured in the plane the tool turns in (x-y of the object
// frame), as the actee between the jaws sees it: the moving part is taken
// as its outline seen along the pivot axis (scissors' blades pass each
// other in z, yet close the gap between them). At distance r it runs from
// the fixed jaw's face where an actee rests, (r, 0) (the object frame puts
// that face in y = 0), to the nearest point of the moving part's outline,
// turned by the opening.
//
// The object file holds the row at theta_max (`interaction_space`), which
// the engine (engine/model/derive.h) uses instead of the wedge of flat jaw faces
// through the pivot, |r| sin(theta_max) wide. `wedge_*` is that figure, so
// the report says how far the real shape departs from the wedge.
#pragma once

#include <vector>

#include "lever_geometry.h"
#include "triangle_mesh.h"

namespace afford::modelling {

struct JawGaps {
  std::vector<double> angles;     // rad, theta_min to theta_max, evenly
  std::vector<double> distances;  // m, signed, the application region's from to to, evenly
  std::vector<std::vector<double>> gap;  // m, [angle][distance]
  double wedge_from = 0, wedge_to = 0;   // m, |r| sin(theta_max) at the application's ends
  double gap_from() const { return gap.back().front(); }  // m, at theta_max, the application's from
  double gap_to() const { return gap.back().back(); }     // m, at theta_max, the application's to
};

inline constexpr int kJawGapAngles = 5;      // theta_min, three between, theta_max
inline constexpr int kJawGapDistances = 9;   // across the application region

// `moving` in the moving arm's frame (where it lies closed, so that opening
// theta turns it by theta about +z).
JawGaps jaw_gaps(const TriangleMesh& moving, const LeverGeometry& lever);

}  // namespace afford::modelling
