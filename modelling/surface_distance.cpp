#include "surface_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace afford::modelling {

using Eigen::Vector3d;

Vector3d closest_on_triangle(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  const Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

SurfaceDistance::SurfaceDistance(const TriangleMesh& mesh) : mesh_(mesh) {
  const Vector3d lo = box_min(mesh), hi = box_max(mesh);
  // About 4 triangles per cell on a surface: cells of the mean triangle's size.
  const double extent = (hi - lo).maxCoeff();
  const double per_side = std::cbrt(static_cast<double>(mesh.triangles.size()) / 4) + 1;
  cell_ = std::max(extent / std::min(per_side * 4, 128.0), extent * 1e-6);
  origin_ = lo - Vector3d::Constant(cell_);
  for (int k = 0; k < 3; ++k) n_[k] = static_cast<int>(std::ceil((hi[k] - lo[k]) / cell_)) + 3;
  cells_.resize(static_cast<size_t>(n_.x()) * n_.y() * n_.z());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    Vector3d tlo = mesh.vertices[mesh.triangles[t][0]], thi = tlo;
    for (int k = 1; k < 3; ++k) {
      tlo = tlo.cwiseMin(mesh.vertices[mesh.triangles[t][k]]);
      thi = thi.cwiseMax(mesh.vertices[mesh.triangles[t][k]]);
    }
    const Eigen::Vector3i a = ((tlo - origin_) / cell_).array().floor().cast<int>();
    const Eigen::Vector3i b = ((thi - origin_) / cell_).array().floor().cast<int>();
    for (int z = a.z(); z <= b.z(); ++z)
      for (int y = a.y(); y <= b.y(); ++y)
        for (int x = a.x(); x <= b.x(); ++x) cells_[index(x, y, z)].push_back(static_cast<int>(t));
  }
}

size_t SurfaceDistance::index(int x, int y, int z) const {
  return (static_cast<size_t>(z) * n_.y() + y) * n_.x() + x;
}

Vector3d SurfaceDistance::nearest(const Vector3d& p) const {
  // Shells of cells around p's cell, until the nearest found is nearer
  // than anything a further shell could hold.
  const Eigen::Vector3i c = ((p - origin_) / cell_).array().floor().cast<int>();
  double best = std::numeric_limits<double>::infinity();
  Vector3d point = p;
  int most = 0;  // the shell that reaches the grid's furthest cell
  for (int k = 0; k < 3; ++k) most = std::max({most, std::abs(c[k]), std::abs(n_[k] - 1 - c[k])});
  for (int r = 0; r <= most; ++r) {
    if (best < (r - 1) * cell_) break;
    for (int z = c.z() - r; z <= c.z() + r; ++z) {
      if (z < 0 || z >= n_.z()) continue;
      for (int y = c.y() - r; y <= c.y() + r; ++y) {
        if (y < 0 || y >= n_.y()) continue;
        for (int x = c.x() - r; x <= c.x() + r; ++x) {
          if (x < 0 || x >= n_.x()) continue;
          if (std::max({std::abs(x - c.x()), std::abs(y - c.y()), std::abs(z - c.z())}) != r) continue;
          for (int t : cells_[index(x, y, z)]) {
            const auto& tri = mesh_.triangles[static_cast<size_t>(t)];
            const Vector3d q = closest_on_triangle(p, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]],
                                                   mesh_.vertices[tri[2]]);
            const double d = (q - p).norm();
            if (d < best) {
              best = d;
              point = q;
            }
          }
        }
      }
    }
  }
  return point;
}

namespace {

double halton(int index, int base) {
  double f = 1, r = 0;
  for (int i = index; i > 0; i /= base) {
    f /= base;
    r += f * (i % base);
  }
  return r;
}

}  // namespace

std::vector<Vector3d> surface_samples(const TriangleMesh& mesh, int count) {
  std::vector<double> cumulative(mesh.triangles.size());
  double total = 0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vector3d& a = mesh.vertices[tri[0]];
    total += 0.5 * (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a).norm();
    cumulative[t] = total;
  }
  std::vector<Vector3d> out;
  out.reserve(static_cast<size_t>(count));
  for (int k = 0; k < count; ++k) {
    const double at = (k + 0.5) / count * total;
    const size_t t = static_cast<size_t>(std::lower_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin());
    const auto& tri = mesh.triangles[std::min(t, mesh.triangles.size() - 1)];
    double u = halton(k + 1, 2), v = halton(k + 1, 3);
    if (u + v > 1) {
      u = 1 - u;
      v = 1 - v;
    }
    const Vector3d& a = mesh.vertices[tri[0]];
    out.push_back(a + u * (mesh.vertices[tri[1]] - a) + v * (mesh.vertices[tri[2]] - a));
  }
  return out;
}

}  // namespace afford::modelling
