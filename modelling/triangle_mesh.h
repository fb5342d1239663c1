// A triangle mesh in metres, as `afford model` reads it from a file: the
// vertices and the triangles that index them, counter-clockwise seen from
// outside where the mesh is closed and oriented.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

namespace afford::modelling {

struct TriangleMesh {
  std::string file;                              // where it was read from, for messages
  std::vector<Eigen::Vector3d> vertices;         // m
  std::vector<std::array<int, 3>> triangles;     // indices into vertices
};

// How the mesh's surface is joined: closed (every edge shared by exactly
// two triangles that run it in opposite directions) or, where it is not,
// the first edge that says why.
struct Closure {
  bool closed = false;
  std::string why_not;  // empty when closed: "edge 12-40 has 1 triangle", ...
};
Closure closure(const TriangleMesh& mesh);

// The mesh's axis-aligned box, m.
Eigen::Vector3d box_min(const TriangleMesh& mesh);
Eigen::Vector3d box_max(const TriangleMesh& mesh);

}  // namespace afford::modelling
