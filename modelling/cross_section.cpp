#include "cross_section.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>

namespace afford::modelling {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr int kCoarseSamples = 300;     // boundary points, to pick candidates among many directions
constexpr int kFineSamples = 1000;      // to refine and to score
constexpr double kEqualMoments = 1e-2;  // relative: moments this close: search every direction
constexpr int kMaxLines = 16;           // a regular polygon of 16 sides has 16 lines

// A cut edge of the mesh, named by its two vertices (the lower first).
using EdgeKey = std::uint64_t;
EdgeKey edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return lo << 32 | hi;
}
std::string edge_name(EdgeKey k) {
  return "edge " + std::to_string(k >> 32) + "-" + std::to_string(k & 0xffffffffu);
}

// A segment of the section, running with the solid on its left seen from
// the plane's normal (from the cut of one edge of its triangle to the other).
struct Segment {
  EdgeKey from = 0, to = 0;
};

// The two cut edges of a triangle whose vertices lie on both sides. With
// the triangle counter-clockwise from outside, the lone vertex i above the
// plane and j, k after it, the solid lies left of the run from the cut of
// i-j to the cut of k-i; with the lone vertex below, the other way.
Segment segment_of(const std::array<int, 3>& t, const std::array<bool, 3>& above) {
  int lone = 0;
  for (int i = 0; i < 3; ++i) {
    if (above[i] != above[(i + 1) % 3] && above[i] != above[(i + 2) % 3]) lone = i;
  }
  const int i = t[lone], j = t[(lone + 1) % 3], k = t[(lone + 2) % 3];
  if (above[lone]) return {edge_key(i, j), edge_key(k, i)};
  return {edge_key(k, i), edge_key(i, j)};
}

double distance_to_segment(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
  const Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Scores a line through the centre by the RMS distance of the reflected
// boundary points from the boundary.
class LineScorer {
 public:
  LineScorer(const std::vector<std::vector<Vector2d>>& loops, const Vector2d& centre, double perimeter, int samples)
      : centre_(centre) {
    for (const auto& loop : loops) {
      for (size_t i = 0; i < loop.size(); ++i) edges_.emplace_back(loop[i], loop[(i + 1) % loop.size()]);
    }
    // Points evenly spread along the boundary by length, the k-th at (k + 1/2) / samples of it.
    double walked = 0;
    int k = 0;
    for (const auto& [a, b] : edges_) {
      const double len = (b - a).norm();
      while (k < samples && (k + 0.5) / samples * perimeter <= walked + len) {
        const double t = len > 0 ? ((k + 0.5) / samples * perimeter - walked) / len : 0;
        samples_.push_back(a + t * (b - a));
        ++k;
      }
      walked += len;
    }
  }
  double operator()(const Vector2d& direction) const {
    double sum = 0;
    for (const Vector2d& p : samples_) {
      const Vector2d q = p - centre_;
      const Vector2d mirrored = centre_ + 2 * q.dot(direction) * direction - q;
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& [a, b] : edges_) nearest = std::min(nearest, distance_to_segment(mirrored, a, b));
      sum += nearest * nearest;
    }
    return samples_.empty() ? 0 : std::sqrt(sum / static_cast<double>(samples_.size()));
  }

 private:
  Vector2d centre_;
  std::vector<std::pair<Vector2d, Vector2d>> edges_;
  std::vector<Vector2d> samples_;
};

Vector2d at_angle(double phi) { return {std::cos(phi), std::sin(phi)}; }

// The angle in [lo, hi] where the score is least, by golden-section search.
double golden_minimum(const LineScorer& score, double lo, double hi) {
  const double r = (std::sqrt(5.0) - 1) / 2;
  double a = hi - r * (hi - lo), b = lo + r * (hi - lo);
  double fa = score(at_angle(a)), fb = score(at_angle(b));
  for (int i = 0; i < 30; ++i) {  // the bracket shrinks to 0.618^30 of 2 deg: below 1e-7 rad
    if (fa <= fb) {
      hi = b, b = a, fb = fa;
      a = hi - r * (hi - lo), fa = score(at_angle(a));
    } else {
      lo = a, a = b, fa = fb;
      b = lo + r * (hi - lo), fb = score(at_angle(b));
    }
  }
  return fa <= fb ? a : b;
}

// The area's integrals over the loops (shoelace sums): area, first and
// second moments about the plane's origin, in the plane's frame.
struct AreaMoments {
  double area = 0;
  Vector2d first = Vector2d::Zero();  // integral of x, y
  double xx = 0, yy = 0, xy = 0;      // integrals of x^2, y^2, x y
};

AreaMoments area_moments(const std::vector<std::vector<Vector2d>>& loops) {
  AreaMoments m;
  for (const auto& loop : loops) {
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vector2d& p = loop[i];
      const Vector2d& r = loop[(i + 1) % loop.size()];
      const double cross = p.x() * r.y() - r.x() * p.y();
      m.area += cross / 2;
      m.first += (p + r) * cross / 6;
      m.xx += (p.x() * p.x() + p.x() * r.x() + r.x() * r.x()) * cross / 12;
      m.yy += (p.y() * p.y() + p.y() * r.y() + r.y() * r.y()) * cross / 12;
      m.xy += (p.x() * r.y() + 2 * p.x() * p.y() + 2 * r.x() * r.y() + r.x() * p.y()) * cross / 24;
    }
  }
  return m;
}

}  // namespace

CrossSection cross_section(const TriangleMesh& mesh, const Vector3d& normal, const Vector3d& point, double tolerance) {
  CrossSection out;
  out.normal = normal.normalized();
  out.point = point;
  out.tolerance = tolerance;
  const Vector3d& n = out.normal;

  std::vector<double> height(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) height[i] = (mesh.vertices[i] - point).dot(n);
  auto cut = [&](EdgeKey k) {
    const auto a = static_cast<size_t>(k >> 32), b = static_cast<size_t>(k & 0xffffffffu);
    return Vector3d(mesh.vertices[a] + (mesh.vertices[b] - mesh.vertices[a]) * (height[a] / (height[a] - height[b])));
  };

  // The segments, each found again by the edge it starts from.
  std::vector<Segment> segments;
  std::map<EdgeKey, int> starting;
  for (const auto& t : mesh.triangles) {
    const std::array<bool, 3> above{height[t[0]] >= 0, height[t[1]] >= 0, height[t[2]] >= 0};
    if (above[0] == above[1] && above[1] == above[2]) continue;
    const Segment s = segment_of(t, above);
    if (!starting.emplace(s.from, static_cast<int>(segments.size())).second) {
      out.why_not = edge_name(s.from) + " is cut by more than two triangles, or two that run it the same way";
      return out;
    }
    segments.push_back(s);
  }
  if (segments.empty()) {
    out.why_not = "the plane does not cut the mesh";
    return out;
  }

  // Joined into loops, each from its lowest-numbered segment (the same every run).
  std::vector<bool> used(segments.size(), false);
  for (size_t first = 0; first < segments.size(); ++first) {
    if (used[first]) continue;
    std::vector<Vector3d> loop;
    size_t at = first;
    while (!used[at]) {
      used[at] = true;
      loop.push_back(cut(segments[at].from));
      const auto next = starting.find(segments[at].to);
      if (next == starting.end()) {
        out.why_not = "the cut through " + edge_name(segments[at].to) + " does not close (the mesh is open there)";
        out.loops.clear();
        return out;
      }
      at = static_cast<size_t>(next->second);
    }
    out.loops.push_back(std::move(loop));
  }

  // The plane's frame: u, v with u x v = n, u from the world axis most across n.
  int across = 0;
  n.cwiseAbs().minCoeff(&across);
  const Vector3d u = (Vector3d::Unit(across) - n[across] * n).normalized();
  const Vector3d v = n.cross(u);
  std::vector<std::vector<Vector2d>> flat;
  Vector2d lo = Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& loop : out.loops) {
    auto& f = flat.emplace_back();
    for (const Vector3d& p : loop) {
      f.emplace_back((p - point).dot(u), (p - point).dot(v));
      lo = lo.cwiseMin(f.back());
      hi = hi.cwiseMax(f.back());
    }
    for (size_t i = 0; i < loop.size(); ++i) out.perimeter += (loop[(i + 1) % loop.size()] - loop[i]).norm();
  }
  AreaMoments m = area_moments(flat);
  if (m.area < 0) {  // the mesh's triangles face inward: the same solid, every loop turned
    m.area = -m.area, m.first = -m.first, m.xx = -m.xx, m.yy = -m.yy, m.xy = -m.xy;
  }
  if (!(m.area > 0)) {
    out.why_not = "the section has no area (the plane only touches the mesh)";
    out.loops.clear();
    return out;
  }
  out.closed = true;
  out.area = m.area;
  const Vector2d c = m.first / m.area;
  out.centre = point + c.x() * u + c.y() * v;

  // The candidate lines: the principal axes of the area about its centre.
  Eigen::Matrix2d spread;
  spread << m.xx - m.area * c.x() * c.x(), m.xy - m.area * c.x() * c.y(), m.xy - m.area * c.x() * c.y(),
      m.yy - m.area * c.y() * c.y();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(spread);
  const double diagonal = (hi - lo).norm();
  const LineScorer fine(flat, c, out.perimeter, kFineSamples);
  out.best.score = std::numeric_limits<double>::infinity();
  auto add = [&](const Vector2d& d) {
    SectionLine line;
    line.direction = (d.x() * u + d.y() * v).normalized();
    int k = 0;  // one sign for a line: its largest component positive
    line.direction.cwiseAbs().maxCoeff(&k);
    if (line.direction[k] < 0) line.direction = -line.direction;
    for (const SectionLine& l : out.lines) {
      if (std::abs(l.direction.dot(line.direction)) > std::cos(1e-4)) return;
    }
    line.score = fine(d);
    line.relative = line.score / diagonal;
    if (line.score < out.best.score) out.best = line;
    if (line.relative <= tolerance) out.lines.push_back(line);
  };
  const Eigen::Vector2d moment = eig.eigenvalues();
  if (std::abs(moment[1] - moment[0]) > kEqualMoments * std::abs(moment[1])) {
    add(eig.eigenvectors().col(0));
    add(eig.eigenvectors().col(1));
  } else {
    // Equal moments (a square, a disc): every direction a degree apart,
    // each one scoring lower than both neighbours refined within them.
    const LineScorer coarse(flat, c, out.perimeter, kCoarseSamples);
    constexpr int kCount = 180;
    const double step = std::numbers::pi / kCount;
    std::vector<double> s(kCount);
    for (int k = 0; k < kCount; ++k) s[k] = coarse(at_angle(k * step));
    std::vector<std::pair<double, int>> minima;
    for (int k = 0; k < kCount; ++k) {
      if (s[k] <= s[(k + 1) % kCount] && s[k] < s[(k + kCount - 1) % kCount] && s[k] <= 10 * tolerance * diagonal) {
        minima.emplace_back(s[k], k);
      }
    }
    std::stable_sort(minima.begin(), minima.end());
    for (size_t i = 0; i < minima.size() && static_cast<int>(i) < kMaxLines; ++i) {
      const double phi = minima[i].second * step;
      add(at_angle(golden_minimum(fine, phi - step, phi + step)));
    }
    if (!std::isfinite(out.best.score)) add(eig.eigenvectors().col(0));
  }
  std::stable_sort(out.lines.begin(), out.lines.end(),
                   [](const SectionLine& a, const SectionLine& b) { return a.score < b.score; });
  return out;
}

}  // namespace afford::modelling
