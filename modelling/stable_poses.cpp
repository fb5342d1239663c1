#include "stable_poses.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "errors.h"
#include "geometry.h"

namespace afford::modelling {
namespace {

using Eigen::Vector3d;

// The hull of many vertices: first of those extreme along 600 spread
// directions (each a corner of the hull), then grown by the vertices still
// outside it, until none is. The engine's hull is O(n^2) (it is fed the
// corners, not the mesh); past kMostCorners (a finely tessellated smooth
// body, every vertex a corner) the hull stays as it is, and `outside` says
// how far the furthest vertex lies beyond it.
constexpr size_t kMostCorners = 4000;

struct MeshHull {
  ConvexHull hull;
  double outside = 0;  // m
};

MeshHull mesh_hull(const TriangleMesh& mesh) {
  const SourceLoc loc{mesh.file, 0, 0};
  constexpr int kDirections = 600;
  std::vector<char> taken(mesh.vertices.size(), 0);
  std::vector<Vector3d> points;
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (int i = 0; i < kDirections; ++i) {
    const double z = 1 - 2 * (i + 0.5) / kDirections, r = std::sqrt(1 - z * z);
    const Vector3d d(r * std::cos(golden * i), r * std::sin(golden * i), z);
    size_t best = 0;
    for (size_t v = 1; v < mesh.vertices.size(); ++v) {
      if (mesh.vertices[v].dot(d) > mesh.vertices[best].dot(d)) best = v;
    }
    if (!taken[best]) {
      taken[best] = 1;
      points.push_back(mesh.vertices[best]);
    }
  }
  const double size = (box_max(mesh) - box_min(mesh)).norm();
  while (true) {
    MeshHull out{convex_hull(points, loc), 0};
    std::vector<Vector3d> normal;
    std::vector<double> offset;
    for (const auto& t : out.hull.triangles) {
      const auto& h = out.hull.vertices;
      const Vector3d n = (h[t[1]] - h[t[0]]).cross(h[t[2]] - h[t[0]]).normalized();
      normal.push_back(n);
      offset.push_back(n.dot(h[t[0]]));
    }
    std::vector<size_t> beyond;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
      if (taken[v]) continue;
      double most = 0;
      for (size_t f = 0; f < normal.size(); ++f) most = std::max(most, normal[f].dot(mesh.vertices[v]) - offset[f]);
      if (most > 1e-9 * size) beyond.push_back(v);
      out.outside = std::max(out.outside, most);
    }
    if (beyond.empty() || points.size() + beyond.size() > kMostCorners) return out;
    for (size_t v : beyond) {
      taken[v] = 1;
      points.push_back(mesh.vertices[v]);
    }
  }
}

double segment_distance(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

}  // namespace

RestingPoses resting_poses(const TriangleMesh& mesh, const Vector3d& centre) {
  const MeshHull whole = mesh_hull(mesh);
  const ConvexHull& hull = whole.hull;
  RestingPoses poses;
  poses.hull_corners = static_cast<int>(hull.vertices.size());
  poses.hull_outside = whole.outside;
  std::vector<RestingFace>& out = poses.faces;
  const double size = (box_max(mesh) - box_min(mesh)).norm();
  // The hull's triangles grouped into faces: one plane, one normal.
  struct Tri {
    Vector3d normal;
    double offset;
    std::array<int, 3> v;
  };
  std::vector<Tri> tris;
  for (const auto& t : hull.triangles) {
    const Vector3d n = (hull.vertices[t[1]] - hull.vertices[t[0]]).cross(hull.vertices[t[2]] - hull.vertices[t[0]]).normalized();
    tris.push_back({n, n.dot(hull.vertices[t[0]]), t});
  }
  std::vector<char> grouped(tris.size(), 0);
  for (size_t i = 0; i < tris.size(); ++i) {
    if (grouped[i]) continue;
    std::vector<size_t> face;
    for (size_t j = i; j < tris.size(); ++j) {
      if (grouped[j] || tris[j].normal.dot(tris[i].normal) < 1 - 1e-9 ||
          std::abs(tris[j].offset - tris[i].offset) > 1e-9 * size) {
        continue;
      }
      grouped[j] = 1;
      face.push_back(j);
    }
    const Vector3d n = tris[i].normal;
    const Vector3d foot = centre - (n.dot(centre) - tris[i].offset) * n;
    // Inside the face: inside one of its triangles. Its margin: the
    // distance to its boundary, the edges no other of its triangles shares.
    bool inside = false;
    double area = 0;
    for (size_t k : face) {
      const auto& v = tris[k].v;
      const Vector3d &a = hull.vertices[v[0]], &b = hull.vertices[v[1]], &c = hull.vertices[v[2]];
      area += 0.5 * (b - a).cross(c - a).norm();
      const bool in = (b - a).cross(foot - a).dot(n) >= 0 && (c - b).cross(foot - b).dot(n) >= 0 &&
                      (a - c).cross(foot - c).dot(n) >= 0;
      inside = inside || in;
    }
    if (!inside) continue;
    double margin = std::numeric_limits<double>::infinity();
    for (size_t k : face) {
      for (int e = 0; e < 3; ++e) {
        const int a = tris[k].v[e], b = tris[k].v[(e + 1) % 3];
        bool shared = false;
        for (size_t l : face) {
          for (int g = 0; g < 3; ++g) shared = shared || (tris[l].v[g] == b && tris[l].v[(g + 1) % 3] == a);
        }
        if (!shared) margin = std::min(margin, segment_distance(foot, hull.vertices[a], hull.vertices[b]));
      }
    }
    if (margin <= 1e-12 * size) continue;  // on an edge: balanced, not resting
    out.push_back({n, tris[i].offset - n.dot(centre), margin, area});
  }
  std::stable_sort(out.begin(), out.end(), [](const RestingFace& a, const RestingFace& b) { return a.margin > b.margin; });
  return poses;
}

}  // namespace afford::modelling
