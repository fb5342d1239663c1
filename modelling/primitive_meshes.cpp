#include "primitive_meshes.h"

#include <cmath>
#include <numbers>

namespace afford::modelling {

using Eigen::Vector3d;

TriangleMesh box_mesh(const Vector3d& size) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) {
    m.vertices.push_back(0.5 * size.cwiseProduct(Vector3d(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)));
  }
  // Each face's corners counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

TriangleMesh ellipsoid_mesh(const Vector3d& radii, int rings, int slices) {
  TriangleMesh m;
  m.vertices.emplace_back(0, 0, radii.z());
  for (int i = 1; i < rings; ++i) {
    const double polar = std::numbers::pi * i / rings;
    for (int j = 0; j < slices; ++j) {
      const double az = 2 * std::numbers::pi * j / slices;
      m.vertices.push_back(
          radii.cwiseProduct(Vector3d(std::sin(polar) * std::cos(az), std::sin(polar) * std::sin(az), std::cos(polar))));
    }
  }
  m.vertices.emplace_back(0, 0, -radii.z());
  const int south = static_cast<int>(m.vertices.size()) - 1;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * slices + (j % slices); };
  for (int j = 0; j < slices; ++j) m.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < rings; ++i) {
    for (int j = 0; j < slices; ++j) {
      m.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  }
  for (int j = 0; j < slices; ++j) m.triangles.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
  return m;
}

TriangleMesh sphere_mesh(double radius, int rings, int slices) {
  return ellipsoid_mesh(Vector3d::Constant(radius), rings, slices);
}

TriangleMesh cylinder_mesh(double radius, double length, int slices) {
  TriangleMesh m;
  m.vertices.emplace_back(0, 0, -0.5 * length);
  m.vertices.emplace_back(0, 0, 0.5 * length);
  for (int j = 0; j < slices; ++j) {
    const double az = 2 * std::numbers::pi * j / slices;
    m.vertices.emplace_back(radius * std::cos(az), radius * std::sin(az), -0.5 * length);
    m.vertices.emplace_back(radius * std::cos(az), radius * std::sin(az), 0.5 * length);
  }
  auto low = [&](int j) { return 2 + 2 * (j % slices); };
  auto high = [&](int j) { return 3 + 2 * (j % slices); };
  for (int j = 0; j < slices; ++j) {
    m.triangles.push_back({0, low(j + 1), low(j)});
    m.triangles.push_back({1, high(j), high(j + 1)});
    m.triangles.push_back({low(j), low(j + 1), high(j + 1)});
    m.triangles.push_back({low(j), high(j + 1), high(j)});
  }
  return m;
}

TriangleMesh capsule_mesh(double radius, double length, int rings, int slices) {
  // The northern half lifted and the southern lowered by half the length:
  // the band across the equator becomes the cylinder.
  TriangleMesh m = sphere_mesh(radius, rings | 1, slices);
  for (Vector3d& v : m.vertices) v.z() += v.z() > 0 ? 0.5 * length : -0.5 * length;
  return m;
}

void append(TriangleMesh& a, const TriangleMesh& b, const Eigen::Isometry3d& pose) {
  const int offset = static_cast<int>(a.vertices.size());
  for (const Vector3d& v : b.vertices) a.vertices.push_back(pose * v);
  for (const auto& t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

}  // namespace afford::modelling
