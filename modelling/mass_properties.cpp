#include "mass_properties.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "errors.h"

namespace afford::modelling {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// The inertia tensor of a volume whose second moment (integral of x x^T)
// about a point is `second`: I = trace(C) E - C.
Matrix3d inertia_of(const Matrix3d& second) { return second.trace() * Matrix3d::Identity() - second; }

double surface_of(const TriangleMesh& mesh) {
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const Vector3d& a = mesh.vertices[t[0]];
    area += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  return area;
}

// Signed tetrahedra from a reference point inside the box (for rounding):
// each has volume a.(b x c)/6, centre (a+b+c)/4 and second moment
// V/20 (a a^T + b b^T + c c^T + s s^T), s = a + b + c.
MassProperties exact(const TriangleMesh& mesh) {
  const Vector3d ref = 0.5 * (box_min(mesh) + box_max(mesh));
  double volume = 0;
  Vector3d first = Vector3d::Zero();
  Matrix3d second = Matrix3d::Zero();
  for (const auto& t : mesh.triangles) {
    const Vector3d a = mesh.vertices[t[0]] - ref, b = mesh.vertices[t[1]] - ref, c = mesh.vertices[t[2]] - ref;
    const double v = a.dot(b.cross(c)) / 6;
    const Vector3d s = a + b + c;
    volume += v;
    first += v * s / 4;
    second += v / 20 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  MassProperties p;
  p.exact = true;
  if (volume < 0) {  // the triangles face inward: the same solid, every sign turned
    p.turned_out = true;
    volume = -volume;
    first = -first;
    second = -second;
  }
  p.volume = volume;
  const Vector3d centre = first / volume;
  p.centroid = ref + centre;
  p.inertia_per_density = inertia_of(second - volume * centre * centre.transpose());
  return p;
}

// The paper's voxel volume: voxels the surface passes through are half
// inside on average; those the outside cannot reach through free voxels
// are inside.
MassProperties voxels(const TriangleMesh& mesh, const std::string& why) {
  const Vector3d lo = box_min(mesh), hi = box_max(mesh);
  const double h = (hi - lo).maxCoeff() / kVoxelsAlongLongest;
  const Vector3d origin = lo - Vector3d::Constant(h);  // one free voxel around the box
  Eigen::Vector3i n;
  for (int k = 0; k < 3; ++k) n[k] = static_cast<int>(std::ceil((hi[k] - lo[k]) / h)) + 3;
  const size_t cells = static_cast<size_t>(n.x()) * n.y() * n.z();
  auto at = [&](int x, int y, int z) { return (static_cast<size_t>(z) * n.y() + y) * n.x() + x; };
  enum : std::uint8_t { kFree = 0, kSurface = 1, kOutside = 2 };
  std::vector<std::uint8_t> cell(cells, kFree);
  // The surface: points on each triangle no further apart than h/2.
  for (const auto& t : mesh.triangles) {
    const Vector3d &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int steps = std::max(1, static_cast<int>(std::ceil(2 * longest / h)));
    for (int i = 0; i <= steps; ++i) {
      for (int j = 0; i + j <= steps; ++j) {
        const Vector3d p = a + (b - a) * (static_cast<double>(i) / steps) + (c - a) * (static_cast<double>(j) / steps);
        const Eigen::Vector3i v = ((p - origin) / h).array().floor().cast<int>();
        cell[at(v.x(), v.y(), v.z())] = kSurface;
      }
    }
  }
  // The outside: a flood from the corner through free voxels, 6-connected.
  std::vector<size_t> stack{at(0, 0, 0)};
  cell[stack.back()] = kOutside;
  while (!stack.empty()) {
    const size_t i = stack.back();
    stack.pop_back();
    const int x = static_cast<int>(i % n.x()), y = static_cast<int>((i / n.x()) % n.y()),
              z = static_cast<int>(i / (static_cast<size_t>(n.x()) * n.y()));
    const int next[6][3] = {{x - 1, y, z}, {x + 1, y, z}, {x, y - 1, z}, {x, y + 1, z}, {x, y, z - 1}, {x, y, z + 1}};
    for (const auto& q : next) {
      if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= n.x() || q[1] >= n.y() || q[2] >= n.z()) continue;
      const size_t j = at(q[0], q[1], q[2]);
      if (cell[j] != kFree) continue;
      cell[j] = kOutside;
      stack.push_back(j);
    }
  }
  double volume = 0;
  Vector3d first = Vector3d::Zero();
  Matrix3d second = Matrix3d::Zero();
  const double v = h * h * h;
  for (int z = 0; z < n.z(); ++z) {
    for (int y = 0; y < n.y(); ++y) {
      for (int x = 0; x < n.x(); ++x) {
        const std::uint8_t c = cell[at(x, y, z)];
        if (c == kOutside) continue;
        const double w = (c == kSurface ? 0.5 : 1.0) * v;
        const Vector3d p = origin + h * Vector3d(x + 0.5, y + 0.5, z + 0.5) - lo;
        volume += w;
        first += w * p;
        second += w * (p * p.transpose() + Matrix3d::Identity() * (h * h / 12));  // a cube's own spread
      }
    }
  }
  MassProperties p;
  p.voxel_size = h;
  p.open_because = why;
  p.volume = volume;
  const Vector3d centre = first / volume;
  p.centroid = lo + centre;
  p.inertia_per_density = inertia_of(second - volume * centre * centre.transpose());
  return p;
}

}  // namespace

MassProperties mass_properties(const TriangleMesh& mesh) {
  const Closure c = closure(mesh);
  MassProperties p = c.closed ? exact(mesh) : voxels(mesh, c.why_not);
  p.surface = surface_of(mesh);
  // A closed surface that bounds nothing (all its triangles in one plane,
  // or pairs that cancel) has no centre to speak of.
  const double box = (box_max(mesh) - box_min(mesh)).norm();
  if (!(p.volume > 1e-12 * box * box * box)) {
    fail(SourceLoc{mesh.file, 0, 0}, "a mesh that bounds a volume", "a volume of " + std::to_string(p.volume) + " m^3");
  }
  return p;
}

Eigen::Matrix3d inertia_about(const MassProperties& p, double mass, const Eigen::Vector3d& point) {
  const double density = mass / p.volume;
  const Eigen::Vector3d d = p.centroid - point;
  return density * p.inertia_per_density + mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

}  // namespace afford::modelling
