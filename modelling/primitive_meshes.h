// Closed triangle meshes of the primitives a URDF may give instead of a
// mesh, in their own frames (URDF's: a box centred, a cylinder along z).
#pragma once

#include "triangle_mesh.h"

namespace afford::modelling {

TriangleMesh box_mesh(const Eigen::Vector3d& size);                  // m
// rings x slices bands about the z axis: 2 * slices * (rings - 1) triangles.
TriangleMesh ellipsoid_mesh(const Eigen::Vector3d& radii, int rings, int slices);  // m
TriangleMesh sphere_mesh(double radius, int rings = 24, int slices = 48);  // m
TriangleMesh cylinder_mesh(double radius, double length, int slices = 48);  // m, along z
// A cylinder of `length` along z capped by half spheres: a sphere of an
// odd number of rings (no ring on the equator) pulled apart at the equator.
TriangleMesh capsule_mesh(double radius, double length, int rings = 25, int slices = 48);  // m

// `b` appended to `a`, its vertices moved by `pose` first.
void append(TriangleMesh& a, const TriangleMesh& b, const Eigen::Isometry3d& pose);

}  // namespace afford::modelling
