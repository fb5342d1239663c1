// The distance between two placed convex shapes by GJK (Gilbert, Johnson
// and Keerthi, 1988) on their support functions, with the closest point of
// each simplex found from its Voronoi regions (Ericson, Real-Time Collision
// Detection, 5.1.5 and 5.1.6). Ours rather than FCL's: it allocates nothing,
// stops at a stated distance tolerance, starts from a direction the caller
// knows (a warm start), and skips the traversal fcl::distance sets up.
#pragma once

#include <Eigen/Geometry>

#include "geometry.h"

namespace afford {

// Where GJK stops, m: the upper bound of the distance (the simplex's point
// nearest the origin) is within this of its lower bound (the support plane's).
inline constexpr double kGjkDistanceTolerance = 1e-12;

struct GjkResult {
  bool overlap = false;  // the shapes touch or overlap; then nothing below is meaningful
  double distance = 0;   // m, within kGjkDistanceTolerance above the true distance
  Eigen::Vector3d on_a = Eigen::Vector3d::Zero();  // m, world: the nearest points
  Eigen::Vector3d on_b = Eigen::Vector3d::Zero();
};

// `start`: a direction from a towards b to begin from; near the final one
// (the last answer for a pair that moved a little) it saves iterations.
// Zero: the line between the origins.
GjkResult gjk_distance(const Geometry& a, const Eigen::Isometry3d& pose_a, const Geometry& b,
                       const Eigen::Isometry3d& pose_b, const Eigen::Vector3d& start = Eigen::Vector3d::Zero());

}  // namespace afford
