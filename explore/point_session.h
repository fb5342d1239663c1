// One point of a grid as a session the engine runs like any other: the
// hand grasps the tool at the thumb's distance, closes the jaws on the
// actee, squeezes until it pushes with the point's effort, holds, then
// lifts the tool (paper Sec. 2.2's "all possible simulations").
#pragma once

#include <string>

#include "forced_lever.h"
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

// The lever of a model at rest with its actee (or none) between the jaws:
// where they touch it, as the forced balance needs it. Found once per model
// (an FCL bisection), shared by every point on it.
struct JawsAtRest {
  ForcedLever lever;         // effort_distance is set per point
  double contact_angle = 0;  // rad, where the jaws touch the actee (lever.actee)
};
JawsAtRest jaws_at_rest(const Model& m);

// The thumb's advance past the rest angle (m) at which the hand, an
// impedance of stiffness force_gain behind the arm, pushes with `effort`
// newtons at `thumb` once the lever has come to rest against the spring and
// the actee (the model's own forced balance, friction included, the actee
// intact). Beyond the hand's limit the push stays at the limit.
double squeeze_for_effort(const Model& m, const JawsAtRest& jaws, double thumb_m, double effort_n);

// The script of one grid point, compiled against the model (which must
// have its agent): the hand above the tool in the tool's frame, palm toward
// -z of the tool, the thumb on the moving arm and the index on the fixed
// arm at drive.thumb. Throws DataError when the grip does not fit the tool.
Script point_script(const Model& m, const JawsAtRest& jaws, const PointDrive& drive, const PointTiming& timing = {});

}  // namespace afford
