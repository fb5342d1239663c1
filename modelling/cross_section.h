// The cross-section of a solid on a plane and the section's own line of
// symmetry (paper Sec. 3.2: the cross-section on the best plane of
// symmetry). The plane cuts each triangle that straddles it in a segment;
// the segments, joined where they share a cut edge of the mesh, make closed
// polylines: outer boundaries counter-clockwise and holes clockwise seen
// from the plane's normal, so the area is the sum of their signed areas.
// A line of symmetry of a region of one density passes through its centre
// along a principal axis of its area's second moments, so the search tries
// those two and, where the two moments are equal (a square, a disc), every
// direction a degree apart; each is scored like the planes of symmetry: the
// root mean square distance of the reflected boundary from the boundary.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "symmetry_planes.h"
#include "triangle_mesh.h"

namespace afford::modelling {

struct SectionLine {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // unit, in the plane
  double score = 0;     // m, RMS distance of the reflected boundary from the boundary
  double relative = 0;  // score over the diagonal of the section's box in the plane
};

struct CrossSection {
  // The segments joined into closed polylines; false (and why) where the
  // mesh is open along the cut: then no area nor line is reported.
  bool closed = false;
  std::string why_not;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, the plane's
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // m, on the plane
  std::vector<std::vector<Eigen::Vector3d>> loops;    // m, each closed (last joins first)
  double area = 0;       // m^2
  double perimeter = 0;  // m, of all loops
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // m, the area's centre
  // Lines through `centre` within the tolerance, best first; `best` the
  // best tried whether or not within it.
  std::vector<SectionLine> lines;
  SectionLine best;
  double tolerance = 0;  // relative
};

// The section of `mesh` on the plane through `point` with unit `normal`. A
// vertex on the plane counts as above it, so every cut edge is cut once.
CrossSection cross_section(const TriangleMesh& mesh, const Eigen::Vector3d& normal, const Eigen::Vector3d& point,
                           double tolerance = kSymmetryTolerance);

}  // namespace afford::modelling
