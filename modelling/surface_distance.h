// The distance from points to a mesh's surface, through a uniform grid of
// the triangles, and points spread evenly over the surface: what the
// symmetry search scores a reflection with.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "triangle_mesh.h"

namespace afford::modelling {

class SurfaceDistance {
 public:
  explicit SurfaceDistance(const TriangleMesh& mesh);
  // m, from p to the nearest point of any triangle.
  double operator()(const Eigen::Vector3d& p) const { return (nearest(p) - p).norm(); }
  // The nearest point of the surface to p, m.
  Eigen::Vector3d nearest(const Eigen::Vector3d& p) const;

 private:
  const TriangleMesh& mesh_;
  Eigen::Vector3d origin_;
  double cell_ = 0;  // m
  Eigen::Vector3i n_;
  std::vector<std::vector<int>> cells_;  // triangle indices whose boxes touch each cell
  size_t index(int x, int y, int z) const;
};

// The point of the triangle (a, b, c) nearest to p (Ericson, Real-Time
// Collision Detection, 5.1.5: by the Voronoi regions of its corners and
// edges).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c);

// `count` points spread over the surface by area, the same every run: the
// k-th picks its triangle by the cumulative area at (k + 1/2) / count and
// its place on it from a Halton pair (bases 2 and 3).
std::vector<Eigen::Vector3d> surface_samples(const TriangleMesh& mesh, int count);

}  // namespace afford::modelling
