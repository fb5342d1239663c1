// The lever of a two-part tool found from its shape (paper Sec. 3.2 step 4
// and Fig. 2): the object frame (objects/README.md: the fulcrum at the
// origin, the pivot axis +z, the fixed arm along +x with its gripping face
// in y = 0), the opening angle the joint's limits give, and where the jaws
// (application) and the handle (emphasis) lie along the arm.
//
// The jaws are found from the gap between the two parts' facing surfaces:
// every point of the moving part turns about the hinge by the same angle as
// the tool closes, so the angular gap between the parts at each distance
// along the arm says where they meet first; the jaws are the stretch where
// that gap is smallest. The handle is the other end from the jaws about the
// pivot (type 1: both parts reach across the pivot) or, for parts on one
// side of the pivot, the stretch beyond the jaws (type 2, jaws near the
// pivot) or between the pivot and the jaws (type 3).
//
// What the shape cannot say: where two plain bars lie face on face all
// along (the shipped nutcracker and tongs, boxes) the gap is the same
// everywhere and no stretch is the jaws: an error asks for the regions.
// Where it can, it gives the whole stretch where the jaws meet (from 10 %
// of the reach, where angles start to say something, to the jaws' tip) and
// a handle's share by the rules above, not the narrower regions a designer
// writes by hand inside them (the shipped pliers: 13.8..42 mm and
// -140..-70 mm found, 5..40 mm and -130..-60 mm written).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "spec.h"
#include "urdf_tool.h"

namespace afford::modelling {

// The angular gap between the parts' facing surfaces over one stretch of
// the arm, with the tool closed (theta = 0).
struct GapBin {
  double from = 0, to = 0;  // m, signed distance along the arm
  double angle = 0;         // rad, >= 0; 0 where the parts meet first
};

struct LeverGeometry {
  // From the tool's frame (the fixed link's) to the object frame, and to the
  // moving arm's own frame (the moving part as it lies at joint 0).
  Eigen::Isometry3d fixed_to_object = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d moving_to_arm = Eigen::Isometry3d::Identity();
  double theta_at_zero = 0;  // rad, the opening at joint 0
  int joint_sign = 1;        // +1: a positive joint angle opens the tool
  double theta_min = 0, theta_max = 0;  // rad
  bool closes_on_contact = false;  // theta_min is where the parts meet, not the lower limit
  RangeSpec arm, emphasis, application;  // m, along the arm
  bool emphasis_found = false, application_found = false;  // from the shape (true) or given
  LeverPattern pattern = LeverPattern::type2;
  std::vector<GapBin> gap;  // along the arm, where both parts are
};

// Regions given instead of found (m, along the arm of the object frame).
struct RegionsGiven {
  std::optional<RangeSpec> emphasis, application;
};

// Half a degree: a stretch whose gap is within this of the smallest closes
// with it (the jaws); a type 1 tool whose two ends' gaps are this close has
// its jaws on the shorter end.
inline constexpr double kJawGapTolerance = 0.5 * 3.14159265358979323846 / 180;  // rad

// DataError at the tool's file when the two parts never lie side by side
// along the arm, when the joint's range never opens them, when the joint
// has no limits, or when the jaws cannot be told from the handle (a gap the
// same all along the arm) and the regions are not given.
LeverGeometry lever_geometry(const UrdfTool& tool, const RegionsGiven& given = {});

}  // namespace afford::modelling
