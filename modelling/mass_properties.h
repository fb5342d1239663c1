// Volume, surface, centre and inertia of a solid bounded by a mesh (paper
// Sec. 3.2 step 2: O_v and O_g). A closed, oriented mesh gives them exactly
// (the divergence theorem over the triangles); an open or broken one is
// filled as voxels, as the paper does with its range data, at a voxel size
// the result says.
#pragma once

#include <Eigen/Core>
#include <string>

#include "triangle_mesh.h"

namespace afford::modelling {

struct MassProperties {
  double volume = 0;   // m^3
  double surface = 0;  // m^2
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // m, of the volume
  // Second moment of the volume about the centroid, m^5: multiplied by a
  // density (kg/m^3) it is the inertia tensor, kg*m^2.
  Eigen::Matrix3d inertia_per_density = Eigen::Matrix3d::Zero();
  bool exact = false;      // from the closed surface; false: from voxels
  bool turned_out = false; // exact, but the triangles faced inward (taken as the solid they bound)
  double voxel_size = 0;   // m, when not exact
  std::string open_because;  // when not exact: why the mesh is not closed
};

// Voxels along the mesh's longest side when it is not closed.
inline constexpr int kVoxelsAlongLongest = 160;

MassProperties mass_properties(const TriangleMesh& mesh);

// The inertia tensor about `point` (m) of a body of `mass` (kg) with these
// properties, kg*m^2 (the parallel axis theorem).
Eigen::Matrix3d inertia_about(const MassProperties& p, double mass, const Eigen::Vector3d& point);

}  // namespace afford::modelling
