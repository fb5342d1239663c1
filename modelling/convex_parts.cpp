#include "convex_parts.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "errors.h"
#include "geometry.h"
#include "mass_properties.h"

namespace afford::modelling {
namespace {

using Eigen::Vector3d;

// Directions the corners are taken in: the box's 26 and 100 spread over the
// sphere (a Fibonacci spiral), the same every run. A box keeps its 8
// corners; a curved surface becomes a polytope of at most 126 corners,
// what the engine's hull is built for.
const std::vector<Vector3d>& directions() {
  static const std::vector<Vector3d> kDirections = [] {
    std::vector<Vector3d> d;
    for (int x = -1; x <= 1; ++x) {
      for (int y = -1; y <= 1; ++y) {
        for (int z = -1; z <= 1; ++z) {
          if (x != 0 || y != 0 || z != 0) d.push_back(Vector3d(x, y, z).normalized());
        }
      }
    }
    const int n = 100;
    const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
      const double z = 1 - (i + 0.5) * 2.0 / n, r = std::sqrt(1 - z * z);
      d.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    }
    return d;
  }();
  return kDirections;
}

// The points furthest along each direction, each once, in direction order.
std::vector<Vector3d> extreme_points(const std::vector<Vector3d>& points) {
  std::vector<int> chosen;
  for (const Vector3d& d : directions()) {
    int best = 0;
    for (int i = 1; i < static_cast<int>(points.size()); ++i) {
      if (points[i].dot(d) > points[best].dot(d)) best = i;
    }
    if (std::find(chosen.begin(), chosen.end(), best) == chosen.end()) chosen.push_back(best);
  }
  std::vector<Vector3d> out;
  for (int i : chosen) out.push_back(points[i]);
  return out;
}

double hull_volume(const ConvexHull& h) {
  double v = 0;
  for (const auto& t : h.triangles) v += h.vertices[t[0]].dot(h.vertices[t[1]].cross(h.vertices[t[2]])) / 6;
  return std::abs(v);
}

// The mesh's points with x in [a, b]: its vertices there and where its
// edges cross the two planes.
std::vector<Vector3d> slab_points(const TriangleMesh& m, double a, double b) {
  std::vector<Vector3d> out;
  for (const Vector3d& v : m.vertices) {
    if (v.x() >= a && v.x() <= b) out.push_back(v);
  }
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vector3d& p = m.vertices[t[k]];
      const Vector3d& q = m.vertices[t[(k + 1) % 3]];
      for (double c : {a, b}) {
        if ((p.x() - c) * (q.x() - c) < 0) out.push_back(p + (q - p) * ((c - p.x()) / (q.x() - p.x())));
      }
    }
  }
  return out;
}

std::string valid_name(const std::string& raw) {
  std::string s;
  for (char c : raw) s += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_';
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) s = "part_" + s;
  return s;
}

std::string unique(std::string name, std::vector<std::string>& taken) {
  const std::string base = name;
  for (int n = 2; std::find(taken.begin(), taken.end(), name) != taken.end(); ++n) name = base + "_" + std::to_string(n);
  taken.push_back(name);
  return name;
}

ConvexPart part_of(const std::vector<Vector3d>& points, const SourceLoc& loc) {
  const ConvexHull hull = convex_hull(extreme_points(points), loc);
  ConvexPart part;
  for (const Vector3d& v : hull.vertices) part.position += v;
  part.position /= static_cast<double>(hull.vertices.size());
  for (const Vector3d& v : hull.vertices) part.corners.push_back(v - part.position);
  part.volume = hull_volume(hull);
  return part;
}

}  // namespace

std::vector<ConvexPart> convex_parts(const std::vector<NamedMesh>& pieces, Arm arm, std::vector<std::string>& taken) {
  const std::string arm_name = arm == Arm::fixed ? "fixed" : "moving";
  std::vector<ConvexPart> out;
  int n = 0;
  for (const NamedMesh& piece : pieces) {
    ++n;
    const SourceLoc loc{piece.mesh.file, 0, 0};
    const std::string name = piece.name.empty() ? arm_name + "_part_" + std::to_string(n) : valid_name(piece.name);
    ConvexPart whole = part_of(piece.mesh.vertices, loc);
    const double volume = mass_properties(piece.mesh).volume;
    if (!(whole.volume > (1 + kHullExcess) * volume)) {
      whole.name = unique(name, taken);
      whole.arm = arm;
      out.push_back(std::move(whole));
      continue;
    }
    // The hull would fill what the element leaves open: slabs across x.
    const double lo = box_min(piece.mesh).x(), hi = box_max(piece.mesh).x();
    for (int k = 0; k < kSlabs; ++k) {
      const std::vector<Vector3d> pts = slab_points(piece.mesh, lo + (hi - lo) * k / kSlabs, lo + (hi - lo) * (k + 1) / kSlabs);
      if (pts.size() < 4) continue;
      ConvexPart slab;
      try {
        slab = part_of(pts, loc);
      } catch (const DataError&) {
        continue;  // a slab that spans no volume (a flat end): nothing to touch
      }
      slab.name = unique(name + "_" + std::to_string(k + 1), taken);
      slab.arm = arm;
      out.push_back(std::move(slab));
    }
  }
  return out;
}

}  // namespace afford::modelling
