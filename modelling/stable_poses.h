// How a rigid object rests on a level plane (paper Sec. 3.2 step 3, the
// stable pose): on a face of its convex hull whose plane the centre of
// gravity stands over. The most stable is the one whose foot of the
// centre lies furthest inside the face (the largest margin: the smallest
// tip it survives), and the paper's pose for functioning is a resting face
// that keeps the plane of symmetry parallel to gravity.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "triangle_mesh.h"

namespace afford::modelling {

struct RestingFace {
  Eigen::Vector3d down = -Eigen::Vector3d::UnitZ();  // unit, mesh frame: gravity when resting on the face
  double height = 0;  // m, of the centre above the face
  double margin = 0;  // m, from the centre's foot to the face's nearest edge
  double area = 0;    // m^2, of the face
};

struct RestingPoses {
  std::vector<RestingFace> faces;  // the most stable (largest margin) first
  int hull_corners = 0;
  // m: how far the furthest vertex lies outside the hull the faces come
  // from; 0 unless a smooth body's thousands of corners were cut short.
  double hull_outside = 0;
};

// The faces the object can rest on with its centre at `centre`. DataError
// at the mesh's file when its points span no volume.
RestingPoses resting_poses(const TriangleMesh& mesh, const Eigen::Vector3d& centre);

}  // namespace afford::modelling
