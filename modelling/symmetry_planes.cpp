#include "symmetry_planes.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "surface_distance.h"

namespace afford::modelling {
namespace {

using Eigen::Vector3d;

constexpr int kCoarsePlaneSamples = 300;    // to pick candidates among many directions
constexpr int kFinePlaneSamples = 1500;     // to refine and to score
constexpr double kEqualPlaneMoments = 1e-2;  // relative: moments this close may share a plane of axes: search it
constexpr double kSameNormal = 1e-4;    // rad: two planes closer than this are one

class Scorer {
 public:
  Scorer(const TriangleMesh& mesh, const Vector3d& centre, int samples)
      : surface_(mesh), centre_(centre), samples_(surface_samples(mesh, samples)) {}
  Vector3d mirror(const Vector3d& p, const Vector3d& normal) const {
    return p - 2 * (p - centre_).dot(normal) * normal;
  }
  double operator()(const Vector3d& normal) const {
    double sum = 0;
    for (const Vector3d& p : samples_) {
      const double d = surface_(mirror(p, normal));
      sum += d * d;
    }
    return std::sqrt(sum / static_cast<double>(samples_.size()));
  }
  // One step of an iterative closest point fit of the plane: each surface
  // point's partner is the surface point nearest its mirror image; the
  // normal that best explains the pairs is the principal direction of
  // their differences (a point and its partner differ along the normal).
  Vector3d refit(const Vector3d& normal) const {
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
    for (const Vector3d& p : samples_) {
      const Vector3d d = p - surface_.nearest(mirror(p, normal));
      spread += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(spread);
    Vector3d n = eig.eigenvectors().col(2);
    return n.dot(normal) < 0 ? Vector3d(-n) : n;
  }

 private:
  SurfaceDistance surface_;
  Vector3d centre_;
  std::vector<Vector3d> samples_;
};

// Refits until the normal turns by less than 1e-12 rad (at most 40 times),
// keeping the best normal seen.
Vector3d refine(const Scorer& score, Vector3d n) {
  double best = score(n);
  for (int i = 0; i < 40; ++i) {
    const Vector3d m = score.refit(n);
    const double s = score(m);
    const bool settled = (m - n).norm() < 1e-12;
    if (s >= best) break;
    best = s;
    n = m;
    if (settled) break;
  }
  return n;
}

// The directions to try. Each principal axis whose moment stands alone is
// one; over two equal moments, every direction of their plane (a degree
// apart); over three, directions spread over a half sphere.
struct Candidates {
  Eigen::Matrix3d axis;          // the principal axes, as columns
  std::vector<Vector3d> spread;  // the directions of equal moments
  int lone = -1;                 // over two equal moments: the axis across them
  bool ball = false;             // three equal moments
};

Candidates candidate_normals(const MassProperties& p) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(p.inertia_per_density);
  const Vector3d moment = eig.eigenvalues();
  Candidates c;
  c.axis = eig.eigenvectors();
  const double scale = moment.cwiseAbs().maxCoeff();
  auto equal = [&](int i, int j) { return std::abs(moment[i] - moment[j]) <= kEqualPlaneMoments * scale; };
  if (equal(0, 1) && equal(1, 2)) {
    c.ball = true;
    constexpr int kCount = 600;  // Fibonacci points on the upper half sphere, about 6 deg apart
    const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
    for (int i = 0; i < kCount; ++i) {
      const double z = 1 - (i + 0.5) / kCount, r = std::sqrt(1 - z * z);
      c.spread.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    }
    return c;
  }
  for (int lone = 0; lone < 3; ++lone) {
    const int a = (lone + 1) % 3, b = (lone + 2) % 3;
    if (!equal(a, b)) continue;
    c.lone = lone;
    for (int k = 0; k < 180; ++k) {
      const double phi = std::numbers::pi * k / 180;
      c.spread.push_back(std::cos(phi) * c.axis.col(a) + std::sin(phi) * c.axis.col(b));
    }
  }
  return c;
}

}  // namespace

Symmetry symmetry_planes(const TriangleMesh& mesh, const MassProperties& p, double tolerance) {
  const double diagonal = (box_max(mesh) - box_min(mesh)).norm();
  const Candidates c = candidate_normals(p);
  const Scorer fine(mesh, p.centroid, kFinePlaneSamples);
  Symmetry out;
  out.tolerance = tolerance;
  out.best.score = std::numeric_limits<double>::infinity();

  // Refined (or taken as it is), kept when within the tolerance and not a
  // plane already kept; returns the normal it settled on.
  auto add = [&](Vector3d n, bool refined) -> Vector3d {
    if (refined) n = refine(fine, n);
    int k = 0;  // one sign for a plane: its largest component positive
    n.cwiseAbs().maxCoeff(&k);
    if (n[k] < 0) n = -n;
    for (const SymmetryPlane& q : out.planes) {
      if (std::abs(q.normal.dot(n)) > std::cos(kSameNormal)) return n;
    }
    SymmetryPlane plane;
    plane.normal = n;
    plane.point = p.centroid;
    plane.score = fine(n);
    plane.relative = plane.score / diagonal;
    if (plane.score < out.best.score) out.best = plane;
    if (plane.relative <= tolerance) out.planes.push_back(plane);
    return n;
  };

  // The principal axes: exact for a closed mesh, refined for voxels.
  const bool refine_principal = !p.exact;
  if (c.spread.empty()) {
    for (int k = 0; k < 3; ++k) add(c.axis.col(k), refine_principal);
  } else {
    const Scorer coarse(mesh, p.centroid, kCoarsePlaneSamples);
    std::vector<std::pair<double, Vector3d>> scored;
    int within = 0;
    for (const Vector3d& n : c.spread) {
      const double s = coarse(n);
      within += s <= tolerance * diagonal;
      scored.emplace_back(s, n);
    }
    if (within >= 0.9 * static_cast<double>(c.spread.size())) {
      // A ball or a body of revolution: every such plane is one.
      out.every_plane = c.ball;
      out.every_plane_through_axis = !c.ball;
      if (!c.ball) out.axis = c.axis.col(c.lone);
      for (int k = 0; k < 3; ++k) add(c.axis.col(k), false);
    } else {
      // Refined from each direction that scores better than its
      // neighbours (those within 1.5 spacings of the spread), best first,
      // unless it lies near a plane found already; at most 48 (a cube has
      // 9 planes, an icosahedron 15).
      const double spacing = c.ball ? 0.105 : std::numbers::pi / 180;  // rad between spread directions
      const double near = std::cos(1.5 * spacing);
      std::vector<std::pair<double, Vector3d>> minima;
      for (const auto& [s, n] : scored) {
        if (s > 10 * tolerance * diagonal) continue;
        bool lowest = true;
        for (const auto& [t, m] : scored) lowest = lowest && !(std::abs(m.dot(n)) > near && t < s);
        if (lowest) minima.emplace_back(s, n);
      }
      std::stable_sort(minima.begin(), minima.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      int refined = 0;
      for (const auto& [s, n] : minima) {
        if (refined >= 48) break;
        bool found = false;
        for (const SymmetryPlane& q : out.planes) found = found || std::abs(q.normal.dot(n)) > near;
        if (found) continue;
        add(n, true);
        ++refined;
      }
      if (c.lone >= 0) add(c.axis.col(c.lone), refine_principal);
    }
  }
  if (!std::isfinite(out.best.score)) {  // no direction came near: the principal axes, for the best
    for (int k = 0; k < 3; ++k) add(c.axis.col(k), false);
  }
  std::stable_sort(out.planes.begin(), out.planes.end(),
                   [](const SymmetryPlane& a, const SymmetryPlane& b) { return a.score < b.score; });
  return out;
}

}  // namespace afford::modelling
