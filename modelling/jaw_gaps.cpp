#include "jaw_gaps.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "outline.h"

namespace afford::modelling {

using Eigen::Vector2d;


JawGaps jaw_gaps(const TriangleMesh& moving, const LeverGeometry& lever) {
  JawGaps out;
  const Outline moving_outline = outline_of(moving);
  for (int i = 0; i < kJawGapAngles; ++i) {
    out.angles.push_back(lever.theta_min + (lever.theta_max - lever.theta_min) * i / (kJawGapAngles - 1));
  }
  // Where an actee rests on the fixed jaw's face (y = 0, object frame): a
  // gap from there changes no faster than the distance along the arm, as
  // the object file's loader checks.
  std::vector<Vector2d> face;
  for (int k = 0; k < kJawGapDistances; ++k) {
    const double r = lever.application.from + (lever.application.to - lever.application.from) * k / (kJawGapDistances - 1);
    out.distances.push_back(r);
    face.emplace_back(r, 0.0);
  }
  for (const double theta : out.angles) {
    // The moving part turned by theta is the point turned back by theta.
    const Eigen::Rotation2Dd back(-theta);
    auto& row = out.gap.emplace_back();
    for (const Vector2d& p : face) row.push_back(distance_to(moving_outline, back * p));
  }
  out.wedge_from = std::abs(lever.application.from) * std::sin(lever.theta_max);
  out.wedge_to = std::abs(lever.application.to) * std::sin(lever.theta_max);
  return out;
}

}  // namespace afford::modelling
