// One point of a grid as a session the engine runs like any other: the
// hand grasps the tool at the thumb's distance, closes the jaws on the
// actee, squeezes until it pushes with the point's effort, holds, then
// lifts the tool (paper Sec. 2.2's "all possible simulations").
#pragma once

#include <string>

#include "squeeze.h"
#include "model.h"
#include "script.h"

namespace afford {

// The generated script's timing, s: closing, squeezing to the effort,
// holding, lifting, resting at the end. Long enough for a function model's
// `for` of a few hundred ms to be met in each phase.
struct PointTiming {
  double close = 0.3;    // the fingers bring the jaws to the actee
  double squeeze = 1.0;  // the push rises to the effort
  double hold = 1.0;     // the effort is kept
  double lift = 1.0;     // the hand lifts the tool
  double rest = 0.3;     // the hand keeps still at the end
};

// s, the whole script.
inline double point_duration(const PointTiming& t) { return t.close + t.squeeze + t.hold + t.lift + t.rest; }

inline constexpr double kLiftHeight = 0.08;  // m, how far the hand lifts the tool, world +z (a carry needs more than 5 cm)

// Where the generated hand grips and how hard it pushes.
struct PointDrive {
  double thumb = 0;   // m, signed distance of the thumb (and the index) along the arms
  int grasp = -1;     // grasp type of the model's taxonomy; -1: none (a model without one)
  double effort = 0;  // N, the push at the thumb the squeeze aims at
};

// The lever at rest with the actee (engine/model/squeeze.h's lever_at_start),
// found once per model (an FCL bisection) and shared by every point on it;
// the squeeze for a point's effort is squeeze.h's squeeze_for_effort.
// The script of one grid point, compiled against the model (which must
// have its agent): the hand above the tool in the tool's frame, palm toward
// -z of the tool, the thumb on the moving arm and the index on the fixed
// arm at drive.thumb. Throws DataError when the grip does not fit the tool.
Script point_script(const Model& m, const ForcedLever& jaws, const PointDrive& drive, const PointTiming& timing = {});

}  // namespace afford
