#include "gjk.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>

namespace afford {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;

// Closer than this to the origin, m, the simplex counts as touching it.
constexpr double kTouching = 1e-15;
// On curved shapes GJK converges linearly (about 20 iterations to 1e-12 m
// for a flat jaw on a nut); this many means it is cycling on round-off.
// Stopping there without a separating plane counts as touching.
constexpr int kMaxIterations = 64;

// A corner of the Minkowski difference a - b, with the points it came from.
struct Corner {
  Vector3d w = Vector3d::Zero(), a = Vector3d::Zero(), b = Vector3d::Zero();
};

Corner corner(const Geometry& a, const Isometry3d& pa, const Geometry& b, const Isometry3d& pb,
              const Vector3d& d) {
  // Farthest along d on a, farthest along -d on b.
  Corner c;
  c.a = pa * a.support_point(pa.linear().transpose() * d);
  c.b = pb * b.support_point(pb.linear().transpose() * -d);
  c.w = c.a - c.b;
  return c;
}

// Up to four corners and the weights of the point nearest the origin.
struct Simplex {
  std::array<Corner, 4> c;
  std::array<double, 4> weight{};
  int size = 0;

  Vector3d nearest = Vector3d::Zero();  // the point nearest the origin

  // Keeps the listed corners (increasing indices) with their weights; the
  // nearest point is their weighted sum.
  void keep(std::initializer_list<int> which, std::initializer_list<double> weights) {
    int n = 0;
    auto w = weights.begin();
    nearest.setZero();
    for (int i : which) {
      if (i != n) c[static_cast<size_t>(n)] = c[static_cast<size_t>(i)];  // i >= n: in place
      weight[static_cast<size_t>(n)] = *w++;
      nearest += weight[static_cast<size_t>(n)] * c[static_cast<size_t>(n)].w;
      ++n;
    }
    size = n;
  }
};

void nearest_on_segment(Simplex& s) {
  const Vector3d& a = s.c[0].w;
  const Vector3d ab = s.c[1].w - a;
  const double t = -a.dot(ab), length2 = ab.squaredNorm();
  if (t <= 0) return s.keep({0}, {1.0});
  if (t >= length2) return s.keep({1}, {1.0});
  s.keep({0, 1}, {1 - t / length2, t / length2});
}

// Ericson's closest point on a triangle to a point p, with p the origin.
void nearest_on_triangle(Simplex& s) {
  const Vector3d &a = s.c[0].w, &b = s.c[1].w, &c = s.c[2].w;
  const Vector3d ab = b - a, ac = c - a;
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0 && d2 <= 0) return s.keep({0}, {1.0});
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0 && d4 <= d3) return s.keep({1}, {1.0});
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return s.keep({0, 1}, {1 - v, v});
  }
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0 && d5 <= d6) return s.keep({2}, {1.0});
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return s.keep({0, 2}, {1 - w, w});
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return s.keep({1, 2}, {1 - w, w});
  }
  const double denom = 1 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  s.keep({0, 1, 2}, {1 - v - w, v, w});
  // Inside the face: the foot of the normal, which keeps its accuracy when
  // the origin is a nanometre from a face centimetres wide (the weighted
  // sum loses it to cancellation).
  const Vector3d n = ab.cross(ac);
  s.nearest = n * (n.dot(a) / n.squaredNorm());
}

// The nearest point on the faces of a tetrahedron that face the origin;
// false when none does (the origin is inside).
bool nearest_on_tetrahedron(Simplex& s) {
  static constexpr std::array<std::array<int, 4>, 4> kFaces{{{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}}};
  // A flat tetrahedron (the new corner in the plane of the others, as when
  // GJK closes in on a face) encloses nothing, and its sides' signs are
  // round-off: every face is a candidate then.
  const Vector3d ab = s.c[1].w - s.c[0].w, ac = s.c[2].w - s.c[0].w, ad = s.c[3].w - s.c[0].w;
  const double size = std::max({ab.norm(), ac.norm(), ad.norm()});
  const bool flat = std::abs(ab.cross(ac).dot(ad)) <= 1e-9 * size * size * size;
  Simplex best;
  double best_d2 = 0;
  bool outside_any = false;
  for (const auto& f : kFaces) {
    const Vector3d& a = s.c[static_cast<size_t>(f[0])].w;
    const Vector3d n = (s.c[static_cast<size_t>(f[1])].w - a).cross(s.c[static_cast<size_t>(f[2])].w - a);
    const double origin_side = -a.dot(n), other_side = (s.c[static_cast<size_t>(f[3])].w - a).dot(n);
    if (!flat && origin_side * other_side > 0) continue;  // the origin is on the inner side of this face
    Simplex face;
    face.c = {s.c[static_cast<size_t>(f[0])], s.c[static_cast<size_t>(f[1])], s.c[static_cast<size_t>(f[2])]};
    face.size = 3;
    nearest_on_triangle(face);
    const double d2 = face.nearest.squaredNorm();
    if (!outside_any || d2 < best_d2) {
      best = face;
      best_d2 = d2;
      outside_any = true;
    }
  }
  if (outside_any) s = best;
  return outside_any;
}

// Reduces the simplex to the corners that carry its point nearest the
// origin; false when it encloses the origin.
bool reduce(Simplex& s) {
  switch (s.size) {
    case 1:
      s.keep({0}, {1.0});
      return true;
    case 2:
      nearest_on_segment(s);
      return true;
    case 3:
      nearest_on_triangle(s);
      return true;
    default:
      return nearest_on_tetrahedron(s);
  }
}

}  // namespace

GjkResult gjk_distance(const Geometry& a, const Isometry3d& pose_a, const Geometry& b, const Isometry3d& pose_b,
                       const Vector3d& start) {
  GjkResult r;
  Simplex s;
  // Any direction would do; the nearer the answer, the fewer iterations.
  Vector3d first = start.squaredNorm() > 0 ? start : Vector3d(pose_b.translation() - pose_a.translation());
  if (!(first.squaredNorm() > 0)) first = Vector3d::UnitX();
  s.c[0] = corner(a, pose_a, b, pose_b, first);
  s.size = 1;
  s.weight[0] = 1;
  Vector3d v = s.c[0].w;
  bool apart = false;  // a plane is known to separate the shapes
  for (int i = 0; i < kMaxIterations; ++i) {
    const double v2 = v.squaredNorm();
    if (v2 <= kTouching * kTouching) break;
    const Corner w = corner(a, pose_a, b, pose_b, -v);
    // |v| bounds the distance from above, v.w / |v| from below.
    apart = v.dot(w.w) > 0;
    if (v2 - v.dot(w.w) <= kGjkDistanceTolerance * std::sqrt(v2)) break;
    Simplex next = s;
    next.c[static_cast<size_t>(next.size++)] = w;
    if (!reduce(next)) {
      apart = false;
      break;
    }
    const Vector3d next_v = next.nearest;
    if (next_v.squaredNorm() >= v2) break;  // no progress: round-off; keep the last
    s = next;
    v = next_v;
  }
  // Without a separating plane (the simplex encloses the origin, or came
  // within round-off of it), they touch or overlap.
  if (!apart) {
    r.overlap = true;
    return r;
  }
  r.on_a = Vector3d::Zero();
  r.on_b = Vector3d::Zero();
  for (int i = 0; i < s.size; ++i) {
    r.on_a += s.weight[static_cast<size_t>(i)] * s.c[static_cast<size_t>(i)].a;
    r.on_b += s.weight[static_cast<size_t>(i)] * s.c[static_cast<size_t>(i)].b;
  }
  r.distance = v.norm();
  return r;
}

}  // namespace afford
