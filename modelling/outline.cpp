#include "outline.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace afford::modelling {
namespace {

using Eigen::Vector2d;

double cross(const Vector2d& a, const Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

double to_segment(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
  const Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

}  // namespace

Outline outline_of(const TriangleMesh& mesh) {
  Outline out;
  for (const auto& t : mesh.triangles) {
    out.push_back({mesh.vertices[t[0]].head<2>(), mesh.vertices[t[1]].head<2>(), mesh.vertices[t[2]].head<2>()});
  }
  return out;
}

double distance_to(const Outline& outline, const Vector2d& p) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& [a, b, c] : outline) {
    const double s0 = cross(b - a, p - a), s1 = cross(c - b, p - b), s2 = cross(a - c, p - c);
    if ((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) return 0;
    d = std::min({d, to_segment(p, a, b), to_segment(p, b, c), to_segment(p, c, a)});
  }
  return d;
}

double edge_at(const Outline& outline, double r, int side) {
  double best = std::numeric_limits<double>::quiet_NaN();
  auto take = [&](double y) {
    if (std::isnan(best) || side * y > side * best) best = y;
  };
  for (const auto& tri : outline) {
    for (int e = 0; e < 3; ++e) {
      const Vector2d& a = tri[e];
      const Vector2d& b = tri[(e + 1) % 3];
      if (a.x() == r) take(a.y());  // a corner on the line (a vertical edge: both its ends)
      if ((a.x() - r) * (b.x() - r) < 0) take(a.y() + (b.y() - a.y()) * (r - a.x()) / (b.x() - a.x()));
    }
  }
  return best;
}

}  // namespace afford::modelling
