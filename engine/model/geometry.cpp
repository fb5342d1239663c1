#include "geometry.h"

#include "gjk.h"

#include <Eigen/Eigenvalues>

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/sphere_capsule.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/sphere_cylinder.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/sphere_sphere.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace afford {

namespace {

using Eigen::Vector3d;

// ---------------------------------------------------------------- convex hull

struct HullFace {
  std::array<int, 3> v;  // counter-clockwise seen from outside
  Vector3d normal;       // unit, outward
  double offset;         // normal . x on the face's plane
  bool dead = false;
};

HullFace make_face(const std::vector<Vector3d>& p, int a, int b, int c) {
  Vector3d n = (p[b] - p[a]).cross(p[c] - p[a]);
  const double len = n.norm();
  if (len > 0) n /= len;
  return HullFace{{a, b, c}, n, n.dot(p[a])};
}

// Incremental hull, O(n^2): the shapes are written by hand (a few hundred
// points at most) and compiled once, so plain beats clever here. Returns
// triangles; a point on a face or an edge of the final hull may remain a
// corner of some (flat) triangles if it came before the points that cover it.
std::vector<HullFace> hull_triangles(const std::vector<Vector3d>& p, const SourceLoc& loc) {
  const int n = static_cast<int>(p.size());
  const std::string expected = "at least 4 vertices that span a volume";
  if (n < 4) fail(loc, expected, std::to_string(n) + (n == 1 ? " vertex" : " vertices"));
  for (const Vector3d& x : p)
    if (!x.allFinite()) fail(loc, "finite vertex coordinates", "a non-finite vertex");

  // Tolerances relative to the size of the point set, so that mm and m agree.
  Eigen::AlignedBox3d box;
  for (const Vector3d& x : p) box.extend(x);
  const double eps = 1e-9 * std::max(box.diagonal().norm(), 1e-300);

  // A first tetrahedron from extreme points; each failure names the degeneracy.
  int i0 = 0;
  for (int i = 1; i < n; ++i)
    if (p[i].x() < p[i0].x()) i0 = i;
  auto farthest = [&](auto&& measure) {
    int best = -1;
    double best_d = eps;
    for (int i = 0; i < n; ++i) {
      const double d = measure(p[i]);
      if (d > best_d) {
        best = i;
        best_d = d;
      }
    }
    return best;
  };
  const int i1 = farthest([&](const Vector3d& x) { return (x - p[i0]).norm(); });
  if (i1 < 0) fail(loc, expected, "one point repeated");
  const Vector3d axis = (p[i1] - p[i0]).normalized();
  const int i2 = farthest([&](const Vector3d& x) { return (x - p[i0]).cross(axis).norm(); });
  if (i2 < 0) fail(loc, expected, "collinear vertices");
  const Vector3d plane = (p[i1] - p[i0]).cross(p[i2] - p[i0]).normalized();
  const int i3 = farthest([&](const Vector3d& x) { return std::abs((x - p[i0]).dot(plane)); });
  if (i3 < 0) fail(loc, expected, "coplanar vertices");

  // Each face of the tetrahedron turned so that the fourth corner is behind it.
  std::vector<HullFace> faces;
  const std::array<int, 4> t{i0, i1, i2, i3};
  for (int k = 0; k < 4; ++k) {
    const int a = t[(k + 1) % 4], b = t[(k + 2) % 4], c = t[(k + 3) % 4];
    HullFace f = make_face(p, a, b, c);
    faces.push_back(f.normal.dot(p[t[k]]) > f.offset ? make_face(p, a, c, b) : f);
  }

  std::vector<std::pair<int, int>> edges, horizon;
  for (int i = 0; i < n; ++i) {
    if (i == i0 || i == i1 || i == i2 || i == i3) continue;
    // The faces that see the point go; the loop of their boundary edges (the
    // horizon) is coned to the point. A point within eps of the hull is inside.
    edges.clear();
    for (HullFace& f : faces) {
      if (f.dead || f.normal.dot(p[i]) - f.offset <= eps) continue;
      f.dead = true;
      edges.emplace_back(f.v[0], f.v[1]);
      edges.emplace_back(f.v[1], f.v[2]);
      edges.emplace_back(f.v[2], f.v[0]);
    }
    horizon.clear();
    for (const auto& [a, b] : edges)
      if (std::find(edges.begin(), edges.end(), std::pair{b, a}) == edges.end())
        horizon.emplace_back(a, b);
    for (const auto& [a, b] : horizon) faces.push_back(make_face(p, a, b, i));
    std::erase_if(faces, [](const HullFace& f) { return f.dead; });
  }
  return faces;
}

}  // namespace

ConvexHull convex_hull(const std::vector<Vector3d>& input, const SourceLoc& loc) {
  std::vector<Vector3d> p = input;
  std::vector<HullFace> faces = hull_triangles(p, loc);

  // A true corner meets faces whose normals span 3D; a point inside a face
  // (one normal) or on an edge (two) is dropped and the hull built again.
  std::vector<Eigen::Matrix3d> spread(p.size(), Eigen::Matrix3d::Zero());
  std::vector<bool> used(p.size(), false);
  for (const HullFace& f : faces) {
    for (int v : f.v) {
      spread[v] += f.normal * f.normal.transpose();
      used[v] = true;
    }
  }
  std::vector<Vector3d> corners;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!used[i]) continue;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(spread[i], Eigen::EigenvaluesOnly);
    if (eig.eigenvalues().minCoeff() > 1e-12) corners.push_back(p[i]);
  }
  if (corners.size() < p.size()) {
    p = std::move(corners);
    faces = hull_triangles(p, loc);
  }

  // Keep only the vertices the faces use, renumbered in input order.
  ConvexHull hull;
  std::vector<int> index(p.size(), -1);
  for (const HullFace& f : faces)
    for (int v : f.v) index[v] = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (index[i] < 0) continue;
    index[i] = static_cast<int>(hull.vertices.size());
    hull.vertices.push_back(p[i]);
  }
  for (const HullFace& f : faces) hull.triangles.push_back({index[f.v[0]], index[f.v[1]], index[f.v[2]]});
  return hull;
}

namespace {

void check_size(const SourceLoc& loc, const char* what, double value) {
  if (!std::isfinite(value) || value < 0)
    fail(loc, std::string("a non-negative ") + what, std::to_string(value));
}

// World support of a placed shape: max over the shape of x . d, d unit, world.
double world_support(const Geometry& g, const Eigen::Isometry3d& pose, const Vector3d& d) {
  return g.support(pose.linear().transpose() * d) + pose.translation().dot(d);
}

}  // namespace

// ---------------------------------------------------------------- Geometry

Geometry Geometry::compile(const ShapeSpec& spec) {
  Geometry g;
  g.spec_ = spec;
  const SourceLoc& loc = spec.loc;
  switch (spec.kind) {
    case ShapeKind::sphere: {
      check_size(loc, "radius", spec.radius);
      g.fcl_ = std::make_shared<fcl::Sphered>(spec.radius);
      g.local_box_ = {Vector3d::Constant(-spec.radius), Vector3d::Constant(spec.radius)};
      break;
    }
    case ShapeKind::box: {
      for (int i = 0; i < 3; ++i) check_size(loc, "box size", spec.size[i]);
      g.fcl_ = std::make_shared<fcl::Boxd>(spec.size);
      g.local_box_ = {-0.5 * spec.size, 0.5 * spec.size};
      break;
    }
    case ShapeKind::capsule:
    case ShapeKind::cylinder: {
      check_size(loc, "radius", spec.radius);
      check_size(loc, "length", spec.length);
      if (spec.kind == ShapeKind::capsule)
        g.fcl_ = std::make_shared<fcl::Capsuled>(spec.radius, spec.length);
      else
        g.fcl_ = std::make_shared<fcl::Cylinderd>(spec.radius, spec.length);
      // Our axis is local x, FCL's is z: a quarter turn about y takes z to x.
      // Written out so that the zeros are exact.
      Eigen::Matrix3d turn;
      turn << 0, 0, 1,  //
          0, 1, 0,      //
          -1, 0, 0;
      g.fcl_offset_.linear() = turn;
      const double end = 0.5 * spec.length + (spec.kind == ShapeKind::capsule ? spec.radius : 0);
      const Vector3d half(end, spec.radius, spec.radius);
      g.local_box_ = {-half, half};
      break;
    }
    case ShapeKind::ellipsoid: {
      for (int i = 0; i < 3; ++i) check_size(loc, "semi-axis", spec.radii[i]);
      g.fcl_ = std::make_shared<fcl::Ellipsoidd>(spec.radii);
      g.local_box_ = {-spec.radii, spec.radii};
      break;
    }
    case ShapeKind::convex: {
      ConvexHull hull = convex_hull(spec.vertices, loc);
      g.hull_vertices_ = hull.vertices;
      std::vector<int> fcl_faces;  // FCL's encoding: 3, i0, i1, i2, 3, ...
      for (const auto& t : hull.triangles) fcl_faces.insert(fcl_faces.end(), {3, t[0], t[1], t[2]});
      g.local_box_.setEmpty();
      for (const Vector3d& v : hull.vertices) g.local_box_.extend(v);
      g.fcl_ = std::make_shared<fcl::Convexd>(
          std::make_shared<const std::vector<Vector3d>>(std::move(hull.vertices)), static_cast<int>(hull.triangles.size()),
          std::make_shared<const std::vector<int>>(std::move(fcl_faces)));
      break;
    }
  }
  g.fcl_->computeLocalAABB();
  return g;
}

double Geometry::volume() const { return fcl_->computeVolume(); }

Vector3d Geometry::centroid() const {
  // Every shape but a hull is symmetric about its origin (a turn folded into
  // fcl_offset_ keeps it so).
  return spec_.kind == ShapeKind::convex ? Vector3d(fcl_->computeCOM()) : Vector3d::Zero();
}

double Geometry::support(const Vector3d& d) const {
  switch (spec_.kind) {
    case ShapeKind::sphere:
      return spec_.radius;
    case ShapeKind::box:
      return 0.5 * spec_.size.dot(d.cwiseAbs());
    case ShapeKind::capsule:
      return 0.5 * spec_.length * std::abs(d.x()) + spec_.radius;
    case ShapeKind::cylinder:
      return 0.5 * spec_.length * std::abs(d.x()) + spec_.radius * std::hypot(d.y(), d.z());
    case ShapeKind::ellipsoid:
      // Maximum of x . d on x = diag(r) u, |u| = 1, is |diag(r) d|.
      return spec_.radii.cwiseProduct(d).norm();
    case ShapeKind::convex: {
      double best = -std::numeric_limits<double>::infinity();
      for (const Vector3d& v : hull_vertices_) best = std::max(best, v.dot(d));
      return best;
    }
  }
  return 0;
}

Vector3d Geometry::support_point(const Vector3d& d) const {
  const double norm = d.norm();
  const Vector3d u = norm > 0 ? Vector3d(d / norm) : Vector3d::UnitX();
  const double end = 0.5 * spec_.length * (d.x() >= 0 ? 1 : -1);  // capsule and cylinder
  switch (spec_.kind) {
    case ShapeKind::sphere:
      return spec_.radius * u;
    case ShapeKind::box:
      return 0.5 * Vector3d(d.x() >= 0 ? spec_.size.x() : -spec_.size.x(), d.y() >= 0 ? spec_.size.y() : -spec_.size.y(),
                            d.z() >= 0 ? spec_.size.z() : -spec_.size.z());
    case ShapeKind::capsule:
      return Vector3d(end, 0, 0) + spec_.radius * u;
    case ShapeKind::cylinder: {
      const double across = std::hypot(d.y(), d.z());
      if (!(across > 0)) return Vector3d(end, 0, 0);
      return Vector3d(end, spec_.radius * d.y() / across, spec_.radius * d.z() / across);
    }
    case ShapeKind::ellipsoid: {
      // x = diag(r) u' with u' = diag(r) d / |diag(r) d| (see support()).
      const Vector3d scaled = spec_.radii.cwiseProduct(d);
      const double len = scaled.norm();
      return len > 0 ? Vector3d(spec_.radii.cwiseProduct(scaled) / len) : Vector3d::Zero();
    }
    case ShapeKind::convex: {
      const Vector3d* best = &hull_vertices_.front();
      for (const Vector3d& v : hull_vertices_)
        if (v.dot(d) > best->dot(d)) best = &v;
      return *best;
    }
  }
  return Vector3d::Zero();
}

// ---------------------------------------------------------------- ContactQuery

namespace {
// Below this gap, m, the nearest points are too close to give a direction.
constexpr double kTinyGap = 1e-9;
// Contacts this close in depth, m, count as one face: their points are averaged.
constexpr double kSameDepth = 1e-9;
constexpr std::size_t kMaxFclContacts = 4;  // box-box faces give four corners

// A box and a rounded shape (ellipsoid, capsule, cylinder), decided without
// GJK where one of the box's faces or edges settles it. A flat jaw on a nut
// is this case, where GJK converges only linearly (about 20 iterations), or
// slower still when touching. In the box's frame:
enum class BoxAnswer { apart, overlap, undecided };

struct PlacedRounded {
  const Geometry& shape;
  Vector3d centre;        // m, in the box's frame
  Eigen::Matrix3d axes;   // the shape's axes in the box's frame
  // The shape's point farthest along d (any length but zero), box frame.
  Vector3d farthest(const Vector3d& d) const { return centre + axes * shape.support_point(axes.transpose() * d); }
};

// Towards face i (side si) and beyond edge j's plane (side sj) of a box of
// half sizes `half`, the nearest feature of the box is the edge between
// them, if anything: the direction n turning in that plane from the face's
// normal to the edge's neighbour face's, where the separation along n is
// largest, gives the distance. The separation is concave in n while it is
// positive, so its slope has one root, found by false position (Illinois):
// there the shape's farthest point towards the box and the edge's point
// level with it are a pair whose distance the separation bounds from
// below; `apart` once the two agree within a tenth of GJK's tolerance and
// that point lies along the edge. `overlap` once the shape's farthest
// point lies inside the box. Otherwise (a corner nearest, or no answer
// before the bracket closes) undecided.
BoxAnswer edge_distance(const PlacedRounded& s, const Vector3d& half, int i, int j, double si, double sj,
                        double* distance, Vector3d* on_box, Vector3d* on_shape) {
  const int k = 3 - i - j;
  // n(u) = si (1 - u) e_i + sj u e_j for u in [0, 1]; w(u), in the plane and
  // across n, points towards growing u.
  auto probe = [&](double u, Vector3d* p, Vector3d* edge_point) {
    Vector3d n = Vector3d::Zero(), w = Vector3d::Zero();
    n[i] = si * (1 - u);
    n[j] = sj * u;
    w[i] = -si * u;
    w[j] = sj * (1 - u);
    *p = s.farthest(-n);
    *edge_point = *p;
    (*edge_point)[i] = si * half[i];
    (*edge_point)[j] = sj * half[j];
    const Vector3d gap = *p - *edge_point;
    return std::pair<double, double>{gap.dot(w), gap.dot(n) / n.norm()};  // slope, separation
  };
  Vector3d p, edge_point;
  double lo = 0, hi = 1;
  double slope_lo = probe(lo, &p, &edge_point).first, slope_hi = probe(hi, &p, &edge_point).first;
  if (!(slope_lo > 0 && slope_hi < 0)) return BoxAnswer::undecided;
  int stale = 0;  // which end stayed last (Illinois halves its slope)
  for (int iteration = 0; iteration < 60 && hi - lo > 1e-12; ++iteration) {
    const double u = (lo * slope_hi - hi * slope_lo) / (slope_hi - slope_lo);
    const auto [slope, separation] = probe(u, &p, &edge_point);
    const double apart = (p - edge_point).norm();
    if (separation > 0 && apart - separation < 0.1 * kGjkDistanceTolerance) {
      if (!(std::abs(p[k]) <= half[k])) return BoxAnswer::undecided;  // a corner is nearest
      *distance = apart;
      *on_box = edge_point;
      *on_shape = p;
      return BoxAnswer::apart;
    }
    if ((p.cwiseAbs() - half).maxCoeff() < 0) return BoxAnswer::overlap;
    if (slope > 0) {
      lo = u;
      slope_lo = slope;
      if (stale == 1) slope_hi *= 0.5;
      stale = 1;
    } else {
      hi = u;
      slope_hi = slope;
      if (stale == -1) slope_lo *= 0.5;
      stale = -1;
    }
  }
  return BoxAnswer::undecided;
}

// For the face of largest separation, the shape's point deepest towards
// the face's plane: when it lies over the face and beyond the plane, the
// distance is exactly the plane's (the box lies behind the plane, the
// shape beyond it, and the two points are that far apart); when it lies
// over the face and inside the box, they overlap. When it lies beyond one
// edge of the face, that edge may settle it (edge_distance). Otherwise GJK
// decides; the separation across that face, where above 0, is still a
// lower bound of the distance (in *distance).
BoxAnswer box_rounded_distance(const Geometry& box, const Eigen::Isometry3d& pbox, const Geometry& shape,
                               const Eigen::Isometry3d& ps, double* distance, Vector3d* on_box, Vector3d* on_shape) {
  const Vector3d half = 0.5 * box.spec().size;
  const PlacedRounded s{shape, pbox.linear().transpose() * (ps.translation() - pbox.translation()),
                        pbox.linear().transpose() * ps.linear()};
  double best = -std::numeric_limits<double>::infinity();
  int face = 0;
  for (int i = 0; i < 3; ++i) {
    // How far the shape's centre is beyond face i's plane, less its reach along that axis.
    const Vector3d along = s.axes.row(i).transpose();
    const double apart = std::abs(s.centre[i]) - half[i] - shape.support(along);
    if (apart > best) {
      best = apart;
      face = i;
    }
  }
  *distance = best;
  const double side = s.centre[face] > 0 ? 1.0 : -1.0;
  Vector3d towards_box = Vector3d::Zero();
  towards_box[face] = -side;
  const Vector3d deepest = s.farthest(towards_box);
  int beyond = -1, edges = 0;  // the face's edges the deepest point lies beyond
  for (int j = 0; j < 3; ++j) {
    if (j != face && !(std::abs(deepest[j]) < half[j])) {
      beyond = j;
      ++edges;
    }
  }
  if (edges == 1) {
    Vector3d near_box, near_shape;
    double d = 0;
    const BoxAnswer edge =
        edge_distance(s, half, face, beyond, side, deepest[beyond] > 0 ? 1.0 : -1.0, &d, &near_box, &near_shape);
    if (edge == BoxAnswer::apart) {
      *distance = d;
      *on_box = pbox * near_box;
      *on_shape = pbox * near_shape;
    }
    return edge;
  }
  if (edges > 0) return BoxAnswer::undecided;
  if (!(best > 0)) return best > -2 * half[face] ? BoxAnswer::overlap : BoxAnswer::undecided;
  Vector3d on_face = deepest;
  on_face[face] = side * half[face];
  *on_box = pbox * on_face;
  *on_shape = pbox * deepest;
  return BoxAnswer::apart;
}

bool rounded(const Geometry& g) {
  const ShapeKind k = g.spec().kind;
  return k == ShapeKind::ellipsoid || k == ShapeKind::capsule || k == ShapeKind::cylinder;
}

}  // namespace

struct ContactQuery::Impl {
  // Separated shapes: a pair with a sphere is the distance from its centre,
  // in closed form for a box, sphere, capsule or cylinder (FCL's, called
  // directly: the traversal fcl::distance sets up around it cost twice the
  // closed form itself); a box and a rounded shape across one of the box's
  // faces or edges, in closed form too (box_rounded_distance); every other
  // pair is our GJK (gjk.h), which allocates nothing and stops within a
  // picometre.
  //
  // Overlaps go to FCL's collision via libccd (its default): its
  // penetration (MPR) gives sane normals and depths; FCL's own GJK/EPA
  // ("indep") returned negative depths and wrong normals for convex pairs
  // in 0.7.
  fcl::CollisionRequestd collision_request{kMaxFclContacts, true};
  fcl::CollisionResultd collision_result;
  // A sphere's centre as a shape of its own, for FCL's closed forms and GJK.
  fcl::Sphered point{0.0};
  Geometry point_geometry = Geometry::compile(ShapeSpec{});  // a sphere of radius 0
  // The nearest points of the last distance() (world, m).
  Vector3d near_a = Vector3d::Zero(), near_b = Vector3d::Zero();

  Impl() {
    // The contacts vector is private: fill and clear it once to keep capacity.
    for (std::size_t i = 0; i < 2 * kMaxFclContacts; ++i) collision_result.addContact({});
    collision_result.clear();
  }

  // The distance from a point (at) to b and b's nearest point; -1 when the
  // point is inside b (as in FCL's closed forms).
  double point_distance(const Eigen::Isometry3d& at, const Geometry& b, const Eigen::Isometry3d& pb,
                        Vector3d* on_b) {
    double d = -1;
    Vector3d on_point = Vector3d::Zero();
    *on_b = Vector3d::Zero();
    switch (b.spec().kind) {
      case ShapeKind::box: {
        // The point in the box's frame, clamped to it: the nearest point
        // (FCL's sphereBoxDistance does the same with more pose products).
        const Vector3d local = pb.linear().transpose() * (at.translation() - pb.translation());
        const Vector3d half = 0.5 * b.spec().size;
        const Vector3d clamped = local.cwiseMax(-half).cwiseMin(half);
        if (clamped == local) return -1;  // inside
        *on_b = pb * clamped;
        return (local - clamped).norm();
      }
      case ShapeKind::sphere:
        fcl::detail::sphereSphereDistance(point, at, static_cast<const fcl::Sphered&>(b.fcl()), pb, &d, &on_point,
                                          on_b);
        return d;
      case ShapeKind::capsule:
        fcl::detail::sphereCapsuleDistance(point, at, static_cast<const fcl::Capsuled&>(b.fcl()),
                                           pb * b.fcl_offset(), &d, &on_point, on_b);
        return d;
      case ShapeKind::cylinder:
        fcl::detail::sphereCylinderDistance(point, at, static_cast<const fcl::Cylinderd&>(b.fcl()),
                                            pb * b.fcl_offset(), &d, &on_point, on_b);
        return d;
      default: {
        const GjkResult g = gjk_distance(point_geometry, at, b, pb);
        if (g.overlap) return -1;
        *on_b = g.on_b;
        return g.distance;
      }
    }
  }

  // A sphere (s) and another shape: the distance from the centre less the radius.
  double sphere_distance(const Geometry& s, const Eigen::Isometry3d& ps, const Geometry& other,
                         const Eigen::Isometry3d& po, Vector3d* on_s, Vector3d* on_other) {
    const Vector3d centre = ps.translation();
    Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
    at.translation() = centre;
    const double from_centre = point_distance(at, other, po, on_other);
    const double radius = s.spec().radius;
    if (!(from_centre > radius)) return -1;
    *on_s = centre + (radius / from_centre) * (*on_other - centre);
    return from_centre - radius;
  }

  // The distance between two placed shapes, their nearest points in
  // near_a and near_b; -1 when they overlap. A caller that only asks
  // whether they are more than `enough` apart may get a lower bound above
  // it instead, without the nearest points.
  double distance(const Geometry& a, const Eigen::Isometry3d& pa, const Geometry& b, const Eigen::Isometry3d& pb,
                  const Vector3d& start = Vector3d::Zero(),
                  double enough = std::numeric_limits<double>::infinity()) {
    if (a.spec().kind == ShapeKind::sphere) return sphere_distance(a, pa, b, pb, &near_a, &near_b);
    if (b.spec().kind == ShapeKind::sphere) return sphere_distance(b, pb, a, pa, &near_b, &near_a);
    BoxAnswer answer = BoxAnswer::undecided;
    double d = -std::numeric_limits<double>::infinity();
    if (a.spec().kind == ShapeKind::box && rounded(b)) answer = box_rounded_distance(a, pa, b, pb, &d, &near_a, &near_b);
    if (b.spec().kind == ShapeKind::box && rounded(a)) answer = box_rounded_distance(b, pb, a, pa, &d, &near_b, &near_a);
    if (answer == BoxAnswer::apart) return d;
    if (answer == BoxAnswer::overlap) return -1;
    if (d > enough) return d;
    const GjkResult g = gjk_distance(a, pa, b, pb, start);
    if (g.overlap) return -1;
    near_a = g.on_a;
    near_b = g.on_b;
    return g.distance;
  }
};

ContactQuery::ContactQuery() : impl_(std::make_unique<Impl>()) {}
ContactQuery::~ContactQuery() = default;

double ContactQuery::distance(const Geometry& a, const Eigen::Isometry3d& pose_a,
                              const Geometry& b, const Eigen::Isometry3d& pose_b) {
  // Unsigned: an overlap is reported as -1 inside.
  return std::max(0.0, impl_->distance(a, pose_a, b, pose_b));
}

bool ContactQuery::apart(const Geometry& a, const Eigen::Isometry3d& pose_a, const Geometry& b,
                         const Eigen::Isometry3d& pose_b, double margin) {
  return impl_->distance(a, pose_a, b, pose_b, Vector3d::Zero(), margin) > margin;
}

double ContactQuery::distance(const Geometry& a, const Eigen::Isometry3d& pose_a, const Geometry& b,
                              const Eigen::Isometry3d& pose_b, Vector3d* near_a, Vector3d* near_b,
                              const Vector3d& start) {
  const double d = impl_->distance(a, pose_a, b, pose_b, start);
  *near_a = impl_->near_a;
  *near_b = impl_->near_b;
  return std::max(0.0, d);
}

bool ContactQuery::contact(const Geometry& a, const Eigen::Isometry3d& pose_a, const Geometry& b,
                           const Eigen::Isometry3d& pose_b, double tolerance, ContactPoint* out) {
  Impl& q = *impl_;
  if (a.spec().kind == ShapeKind::sphere) {
    // Fingertips: the distance from the centre, less the radius.
    const Vector3d centre = pose_a.translation();
    Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
    at.translation() = centre;
    Vector3d on_b;
    const double from_centre = q.point_distance(at, b, pose_b, &on_b);
    if (from_centre > kTinyGap) {
      const double gap = from_centre - a.spec().radius;
      if (gap > tolerance) return false;
      out->normal = (on_b - centre) / from_centre;
      out->point = 0.5 * (centre + a.spec().radius * out->normal + on_b);  // middle of the gap or overlap
      out->distance = gap;
      return true;
    }
    // The centre is inside b: a finger pushed into a part it does not hold.
    // Reported at the centre, at least a radius deep, without a collision
    // query (libccd's would allocate, and the depth means nothing here).
    out->point = centre;
    out->normal = pose_b.translation() - centre;
    out->normal = out->normal.squaredNorm() > 0 ? Vector3d(out->normal.normalized()) : Vector3d::UnitX();
    out->distance = -a.spec().radius;
    return true;
  }
  const double gap = q.distance(a, pose_a, b, pose_b, Vector3d::Zero(), tolerance);
  if (gap > tolerance) return false;
  const Vector3d& near_a = q.near_a;
  const Vector3d& near_b = q.near_b;
  if (gap > kTinyGap) {
    out->point = 0.5 * (near_a + near_b);
    out->normal = (near_b - near_a).normalized();
    out->distance = gap;
    return true;
  }

  // Touching or overlapping: the deepest of FCL's contacts (normal from o1
  // to o2, depth >= 0). Contacts of equal depth (a face on a face) are
  // averaged so that the point is the middle of the patch, not a corner.
  q.collision_result.clear();
  fcl::collide(&a.fcl(), pose_a * a.fcl_offset(), &b.fcl(), pose_b * b.fcl_offset(),
               q.collision_request, q.collision_result);
  const fcl::CollisionResultd& result = q.collision_result;
  Vector3d normal = Vector3d::Zero();
  Vector3d point = gap >= 0 ? Vector3d(0.5 * (near_a + near_b))
                            : Vector3d(0.5 * (pose_a.translation() + pose_b.translation()));
  double depth = 0;  // none: touching exactly, which GJK may call either way
  if (result.numContacts() > 0) {
    depth = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < result.numContacts(); ++i)
      depth = std::max(depth, result.getContact(i).penetration_depth);
    Vector3d sum = Vector3d::Zero();
    int count = 0;
    for (std::size_t i = 0; i < result.numContacts(); ++i) {
      const fcl::Contactd& c = result.getContact(i);
      if (c.penetration_depth < depth - kSameDepth) continue;
      sum += c.pos;
      if (count == 0) normal = c.normal;
      ++count;
    }
    point = sum / static_cast<double>(count);
  }

  // libccd can return a zero normal (concentric spheres, some touching
  // pairs): fall back to the line between the origins, then to x.
  if (!(normal.squaredNorm() > 0.25)) {
    normal = pose_b.translation() - pose_a.translation();
    if (!(normal.squaredNorm() > 0)) normal = Vector3d::UnitX();
  }
  normal.normalize();
  // Guard the sign: from a to b is the direction along which b must move
  // less to clear a (how far a reaches along n past where b begins).
  double a_top = world_support(a, pose_a, normal);
  double b_bottom = -world_support(b, pose_b, -normal);
  if (world_support(a, pose_a, -normal) + world_support(b, pose_b, normal) < a_top - b_bottom) {
    normal = -normal;
    a_top = world_support(a, pose_a, normal);
    b_bottom = -world_support(b, pose_b, -normal);
  }
  // FCL's pairs disagree on where along the normal the point sits (on one
  // surface, or somewhere inside): put it in the middle of the overlap.
  point += (0.5 * (a_top + b_bottom) - point.dot(normal)) * normal;

  out->point = point;
  out->normal = normal;
  out->distance = std::min(0.0, -depth);
  return true;
}

// ---------------------------------------------------------------- boxes_apart

WorldBox world_box(const Geometry& g, const Eigen::Isometry3d& pose) {
  // A rotated box's world extent is |R| times its half sizes.
  const Eigen::AlignedBox3d& local = g.local_box();
  return {pose * local.center(), pose.linear().cwiseAbs() * (0.5 * local.sizes())};
}

bool boxes_apart(const Geometry& a, const Eigen::Isometry3d& pose_a, const Geometry& b,
                 const Eigen::Isometry3d& pose_b, double margin) {
  // Apart when more than margin apart along some world axis; then the
  // shapes inside are more than margin apart too.
  return boxes_apart(world_box(a, pose_a), world_box(b, pose_b), margin);
}

}  // namespace afford
