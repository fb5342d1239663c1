// A tool's contact geometry as convex parts (the object format's `convex`
// shape): each collision element's convex hull, or, where the hull of an
// element would fill space the element does not (a curved jaw, a channel:
// the hull would close the gap between the jaws), the hulls of slabs cut
// across its length.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "spec.h"
#include "urdf_tool.h"

namespace afford::modelling {

struct ConvexPart {
  std::string name;
  Arm arm = Arm::fixed;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m, in the arm's frame: the corners' mean
  std::vector<Eigen::Vector3d> corners;                // m, about position
  double volume = 0;                                   // m^3, of the hull
};

// An element is cut into this many slabs along x when its hull exceeds its
// own volume by more than kHullExcess.
inline constexpr int kSlabs = 8;
inline constexpr double kHullExcess = 0.15;

// The parts of one arm; `pieces` are its elements in the arm's own frame.
// Names come from the elements (made valid, and unique among `taken`, to
// which they are added), else "<arm>_part_<n>". DataError at the element's
// file when an element spans no volume.
std::vector<ConvexPart> convex_parts(const std::vector<NamedMesh>& pieces, Arm arm, std::vector<std::string>& taken);

}  // namespace afford::modelling
