#include "jaw_gaps.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "outline.h"

namespace afford::modelling {

using Eigen::Vector2d;


JawGaps jaw_gaps(const TriangleMesh& fixed, const TriangleMesh& moving, const LeverGeometry& lever) {
  JawGaps out;
  const Outline fixed_outline = outline_of(fixed);
  const Outline moving_outline = outline_of(moving);
  for (int i = 0; i < kJawGapAngles; ++i) {
    out.angles.push_back(lever.theta_min + (lever.theta_max - lever.theta_min) * i / (kJawGapAngles - 1));
  }
  std::vector<Vector2d> face;  // the fixed jaw's face, object frame
  for (int k = 0; k < kJawGapDistances; ++k) {
    const double r = lever.application.from + (lever.application.to - lever.application.from) * k / (kJawGapDistances - 1);
    out.distances.push_back(r);
    const double top = edge_at(fixed_outline, r, +1);
    face.emplace_back(r, std::isnan(top) ? 0.0 : top);  // no fixed part there: the face's plane, y = 0
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
