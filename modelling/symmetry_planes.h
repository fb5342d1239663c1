// The planes of symmetry of a solid (paper Sec. 3.2 step 3: O_sp). A plane
// of symmetry of a body of one density passes through its centre and has a
// principal axis of its inertia as its normal (the reflection leaves the
// inertia tensor as it is), so the search tries the principal axes and,
// where two or three moments are equal (a cylinder, a cube, a sphere), the
// directions of their common axes. Each plane is scored by how far the
// reflected surface lies from the surface: the root mean square distance
// of reflected surface points from the mesh.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mass_properties.h"
#include "triangle_mesh.h"

namespace afford::modelling {

struct SymmetryPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // m, the centre of the volume
  double score = 0;     // m, RMS distance of the reflected surface from the surface
  double relative = 0;  // score over the box's diagonal
};

struct Symmetry {
  // Planes whose relative score is within the tolerance, best first; none
  // when the solid has no plane of symmetry.
  std::vector<SymmetryPlane> planes;
  SymmetryPlane best;  // the best plane tried, whether or not within the tolerance
  double tolerance = 0;  // relative
  // A body of revolution is symmetric about every plane through its axis,
  // a ball about every plane through its centre: then `planes` holds the
  // principal ones and these say so.
  bool every_plane_through_axis = false;
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();  // unit, when every_plane_through_axis
  bool every_plane = false;
};

// Default tolerance: 1 % of the box's diagonal (a scanned tool's noise and
// small asymmetries, a stamped mark, stay within it).
inline constexpr double kSymmetryTolerance = 0.01;

Symmetry symmetry_planes(const TriangleMesh& mesh, const MassProperties& p, double tolerance = kSymmetryTolerance);

}  // namespace afford::modelling
