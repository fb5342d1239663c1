// Triangle meshes of the shapes (render-side tessellation), in the shape's
// local frame: boxes, spheres, ellipsoids, capsules and cylinders along x,
// convex hulls from the compiled geometry's faces. Every triangle is wound
// counter-clockwise seen from outside, with per-vertex normals; the
// tessellations are cut at the planes x = 0, y = 0 and z = 0 so that a
// shape splits cleanly into octants (the shards of a broken actee).
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "geometry.h"

namespace afford::render {

struct Mesh {
  std::vector<float> pos;  // m, xyz per vertex, three vertices per triangle
  std::vector<float> nrm;  // unit, xyz per vertex
  void clear() {
    pos.clear();
    nrm.clear();
  }
  int vertices() const { return static_cast<int>(pos.size() / 3); }
  // Adds a triangle, turned so that it faces along the normals' sum;
  // degenerate triangles are dropped.
  void tri(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Eigen::Vector3d& na,
           const Eigen::Vector3d& nb, const Eigen::Vector3d& nc);
};

void add_shape(Mesh& mesh, const afford::Geometry& geometry);
void add_box(Mesh& mesh, const Eigen::Vector3d& size, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero());
void add_ellipsoid(Mesh& mesh, const Eigen::Vector3d& radii, int slices = 32, int stacks = 16);
// A solid between two world points (a tube with flat ends) and an arrow
// (shaft and cone) from tail to head, radius the shaft's.
void add_tube(Mesh& mesh, const Eigen::Vector3d& from, const Eigen::Vector3d& to, double radius, int slices = 16);
void add_arrow(Mesh& mesh, const Eigen::Vector3d& tail, const Eigen::Vector3d& head, double radius);
// The mesh in octants pushed apart by `gap` (m) each along its signs.
void shatter(const Mesh& in, double gap, Mesh& out);
// The mesh cut in two at the plane through the origin across axis (0, 1
// or 2): each half moved `gap` (m) away from the cut and turned by `angle`
// (rad) about the origin so that its cut face turns toward `toward`
// (unit), as a nut opens: the shell's inside shows.
void split_open(const Mesh& in, int axis, const Eigen::Vector3d& toward, double angle, double gap, Mesh& out);

}  // namespace afford::render
