// Geometry and contact queries on configurations whose answers are known in
// closed form. Lengths in m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fcl/geometry/shape/convex.h>

#include "errors.h"
#include "geometry.h"
#include "shape_specs.h"

namespace afford {
namespace {
using test::box;
using test::ellipsoid;
using test::at;

using Eigen::Isometry3d;
using Eigen::Vector3d;

// Pairs without a closed form go through our GJK (within 1e-12 m, checked
// in test_gjk.cpp), overlaps through FCL's libccd; sphere-sphere,
// sphere-box and the like are closed form.
constexpr double kGjk = 1e-6;
constexpr double kExact = 1e-9;

ShapeSpec sphere(double r) {
  ShapeSpec s;
  s.kind = ShapeKind::sphere;
  s.radius = r;
  return s;
}
ShapeSpec capsule(double r, double length) {
  ShapeSpec s;
  s.kind = ShapeKind::capsule;
  s.radius = r;
  s.length = length;
  return s;
}
ShapeSpec cylinder(double r, double length) {
  ShapeSpec s = capsule(r, length);
  s.kind = ShapeKind::cylinder;
  return s;
}
ShapeSpec convex(std::vector<Vector3d> points) {
  ShapeSpec s;
  s.kind = ShapeKind::convex;
  s.vertices = std::move(points);
  s.loc = {"x.yaml", 3, 7};
  return s;
}

std::vector<Vector3d> cube_corners(double half) {
  std::vector<Vector3d> v;
  for (int i = 0; i < 8; ++i)
    v.emplace_back(i & 1 ? half : -half, i & 2 ? half : -half, i & 4 ? half : -half);
  return v;
}

// Fibonacci points: near-uniform on the sphere of radius r.
std::vector<Vector3d> sphere_points(int n, double r) {
  std::vector<Vector3d> v;
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double y = 1 - 2 * (i + 0.5) / n;
    const double ring = std::sqrt(1 - y * y);
    const double phi = golden * i;
    v.emplace_back(r * ring * std::cos(phi), r * y, r * ring * std::sin(phi));
  }
  return v;
}

void expect_vec(const Vector3d& actual, const Vector3d& expected, double tol) {
  EXPECT_NEAR(actual.x(), expected.x(), tol) << actual.transpose();
  EXPECT_NEAR(actual.y(), expected.y(), tol) << actual.transpose();
  EXPECT_NEAR(actual.z(), expected.z(), tol) << actual.transpose();
}

// ---------------------------------------------------------------- distances

TEST(Contacts, SphereSphereDistance) {
  const Geometry a = Geometry::compile(sphere(0.5));
  const Geometry b = Geometry::compile(sphere(0.25));
  const Vector3d n = Vector3d(1, 1, 0).normalized();
  const Vector3d cb = 2 * n + Vector3d(1, 2, 3);
  ContactQuery q;
  EXPECT_NEAR(q.distance(a, at(1, 2, 3), b, at(cb.x(), cb.y(), cb.z())), 1.25, kExact);

  ContactPoint c;
  EXPECT_FALSE(q.contact(a, at(1, 2, 3), b, at(cb.x(), cb.y(), cb.z()), 1.0, &c));
  ASSERT_TRUE(q.contact(a, at(1, 2, 3), b, at(cb.x(), cb.y(), cb.z()), 1.25 + 1e-6, &c));
  EXPECT_NEAR(c.distance, 1.25, kExact);
  expect_vec(c.normal, n, kExact);
  // Midpoint of the nearest points: 0.5 m and 1.75 m along n from a's centre.
  expect_vec(c.point, Vector3d(1, 2, 3) + 1.125 * n, kExact);
}

TEST(Contacts, SphereBoxDistance) {
  const Geometry b = Geometry::compile(box(0.2, 0.4, 0.6));
  const Geometry s = Geometry::compile(sphere(0.1));
  ContactQuery q;
  // Face: 0.5 - 0.1 (half x) - 0.1 (radius).
  EXPECT_NEAR(q.distance(b, at(0, 0, 0), s, at(0.5, 0, 0)), 0.3, kExact);
  // Edge: nearest box point (0.1, 0.2, 0), 0.5 from the centre.
  EXPECT_NEAR(q.distance(b, at(0, 0, 0), s, at(0.4, 0.6, 0)), 0.4, kExact);
  // The box turned a quarter about z shows its 0.4 m side along x.
  EXPECT_NEAR(q.distance(b, at(0, 0, 0, std::numbers::pi / 2), s, at(0.5, 0, 0)), 0.2, kExact);
  // Order does not matter; overlap is 0.
  EXPECT_NEAR(q.distance(s, at(0.5, 0, 0), b, at(0, 0, 0)), 0.3, kExact);
  EXPECT_EQ(q.distance(b, at(0, 0, 0), s, at(0.15, 0, 0)), 0.0);
}

TEST(Contacts, BoxBoxWithinTolerance) {
  const Geometry a = Geometry::compile(box(1, 1, 1));
  ContactQuery q;
  ContactPoint c;
  // A 0.5 mm gap: in contact at 1 mm tolerance, not at 0.1 mm.
  EXPECT_FALSE(q.contact(a, at(0, 0, 0), a, at(1.0005, 0.2, 0), 1e-4, &c));
  ASSERT_TRUE(q.contact(a, at(0, 0, 0), a, at(1.0005, 0.2, 0), 1e-3, &c));
  EXPECT_NEAR(c.distance, 5e-4, kGjk);
  expect_vec(c.normal, Vector3d::UnitX(), 1e-6);
  EXPECT_NEAR(c.point.x(), 0.50025, kGjk);
  EXPECT_NEAR(q.distance(a, at(0, 0, 0), a, at(1.0005, 0.2, 0)), 5e-4, kGjk);
}

TEST(Contacts, BoxBoxFaceOnFaceIsTheMiddleOfThePatch) {
  const Geometry a = Geometry::compile(box(1, 1, 1));
  ContactQuery q;
  ContactPoint c;
  // Touching exactly; the shared patch spans y in [-0.3, 0.5], z in [-0.5, 0.5].
  ASSERT_TRUE(q.contact(a, at(0, 0, 0), a, at(1.0, 0.2, 0), 1e-3, &c));
  EXPECT_LE(c.distance, 0.0);
  EXPECT_GT(c.distance, -1e-9);
  expect_vec(c.normal, Vector3d::UnitX(), 1e-9);
  expect_vec(c.point, Vector3d(0.5, 0.1, 0), 1e-9);
  // Pressed 1 cm in: depth 0.01, point in the middle of the overlap.
  ASSERT_TRUE(q.contact(a, at(0, 0, 0), a, at(0.99, 0.2, 0), 0, &c));
  EXPECT_NEAR(c.distance, -0.01, 1e-9);
  expect_vec(c.normal, Vector3d::UnitX(), 1e-9);
  expect_vec(c.point, Vector3d(0.495, 0.1, 0), 1e-9);
}

// ---------------------------------------------------------------- overlap

TEST(Contacts, OverlappingSphereBox) {
  const Geometry s = Geometry::compile(sphere(0.5));
  const Geometry b = Geometry::compile(box(1, 1, 1));
  ContactQuery q;
  ContactPoint c;
  // Sphere reaches x = 0.5, box starts at 0.3: 0.2 deep, middle at 0.4.
  ASSERT_TRUE(q.contact(s, at(0, 0, 0), b, at(0.8, 0, 0), 0, &c));
  EXPECT_NEAR(c.distance, -0.2, kExact);
  expect_vec(c.normal, Vector3d::UnitX(), kExact);  // from a (sphere) to b (box)
  expect_vec(c.point, Vector3d(0.4, 0, 0), kExact);
  // Swapped: the normal turns round, the rest stays.
  ASSERT_TRUE(q.contact(b, at(0.8, 0, 0), s, at(0, 0, 0), 0, &c));
  EXPECT_NEAR(c.distance, -0.2, kExact);
  expect_vec(c.normal, -Vector3d::UnitX(), kExact);
  expect_vec(c.point, Vector3d(0.4, 0, 0), kExact);
  EXPECT_EQ(q.distance(s, at(0, 0, 0), b, at(0.8, 0, 0)), 0.0);

  // A turned box: its face normal is the world direction of its local x.
  const Isometry3d pb = at(0, 0, 0, 0.3) * at(0.8, 0, 0);
  ASSERT_TRUE(q.contact(s, at(0, 0, 0), b, pb, 0, &c));
  EXPECT_NEAR(c.distance, -0.2, kExact);
  expect_vec(c.normal, pb.linear() * Vector3d::UnitX(), kExact);
}

// A capsule lying along a box face, and an ellipsoid pressed into it: depth
// and normal exact, the point in the middle of the overlap along the normal.
TEST(Contacts, CurvedShapesPressedIntoABox) {
  const Geometry slab = Geometry::compile(box(2, 2, 2));
  ContactQuery q;
  ContactPoint c;
  const Geometry cap = Geometry::compile(capsule(0.1, 1.0));
  // The box (a, below) reaches up to y = -0.08, the capsule (b) down to -0.1.
  ASSERT_TRUE(q.contact(slab, at(0.05, -1.08, 0), cap, at(0, 0, 0), 0, &c));
  EXPECT_NEAR(c.distance, -0.02, kGjk);
  expect_vec(c.normal, Vector3d::UnitY(), kGjk);
  EXPECT_NEAR(c.point.y(), -0.09, kGjk);
  EXPECT_LE(std::abs(c.point.x()), 0.5 + kGjk);  // somewhere along the line of contact

  const Geometry e = Geometry::compile(ellipsoid(0.3, 0.2, 0.1));
  ASSERT_TRUE(q.contact(e, at(0, 0, 0), slab, at(0.05, 1.15, 0.02), 0, &c));
  EXPECT_NEAR(c.distance, -0.05, kGjk);
  expect_vec(c.normal, Vector3d::UnitY(), kGjk);
  expect_vec(c.point, Vector3d(0, 0.175, 0), 1e-4);
}

TEST(Contacts, GapNormalFollowsTurnedShapes) {
  const Geometry cap = Geometry::compile(capsule(0.1, 1.0));
  const Geometry s = Geometry::compile(sphere(0.1));
  ContactQuery q;
  ContactPoint c;
  // The capsule turned 30 degrees about z; the sphere 0.2 m beyond its end.
  const Isometry3d pc = at(1, 2, 3, std::numbers::pi / 6);
  const Vector3d axis = pc.linear() * Vector3d::UnitX();
  const Vector3d cs = pc.translation() + 0.9 * axis;
  ASSERT_TRUE(q.contact(cap, pc, s, at(cs.x(), cs.y(), cs.z()), 0.25, &c));
  EXPECT_NEAR(c.distance, 0.2, kGjk);
  expect_vec(c.normal, axis, kGjk);
  expect_vec(c.point, pc.translation() + 0.7 * axis, kGjk);
  // Seen from the sphere, the normal turns round.
  ASSERT_TRUE(q.contact(s, at(cs.x(), cs.y(), cs.z()), cap, pc, 0.25, &c));
  expect_vec(c.normal, -axis, kGjk);
}

// Every pair of kinds, pressed together along a slanted direction: the
// normal points from a to b whatever the pair (FCL's convention, checked).
TEST(Contacts, OverlapNormalPointsFromAToB) {
  const std::vector<ShapeSpec> specs = {
      sphere(0.5),        box(1, 1, 1),
      capsule(0.4, 0.2),  cylinder(0.5, 1),
      ellipsoid(0.5, 0.4, 0.6), convex(sphere_points(60, 0.5)),
  };
  std::vector<Geometry> shapes;
  for (const ShapeSpec& s : specs) shapes.push_back(Geometry::compile(s));
  const Vector3d dir = Vector3d(1, 0.3, -0.2).normalized();
  ContactQuery q;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      const Vector3d cb = 0.8 * dir;
      ContactPoint c;
      ASSERT_TRUE(q.contact(shapes[i], at(0, 0, 0), shapes[j], at(cb.x(), cb.y(), cb.z()), 0, &c))
          << i << " " << j;
      EXPECT_LT(c.distance, 0) << i << " " << j;
      EXPECT_NEAR(c.normal.norm(), 1, 1e-9) << i << " " << j;
      EXPECT_GT(c.normal.dot(dir), 0.5) << i << " " << j << ": " << c.normal.transpose();
    }
  }
}

// A sphere (a fingertip) whose centre is inside the other shape is a deep
// overlap: reported at its centre, at least its radius deep, with a unit
// normal, and without a collision query.
TEST(Contacts, ConcentricSpheresStillGiveAUnitNormal) {
  const Geometry s = Geometry::compile(sphere(0.5));
  ContactQuery q;
  ContactPoint c;
  ASSERT_TRUE(q.contact(s, at(1, 1, 1), s, at(1, 1, 1), 0, &c));
  EXPECT_LE(c.distance, -0.5);
  EXPECT_NEAR(c.normal.norm(), 1.0, kExact);
  EXPECT_NEAR((c.point - Eigen::Vector3d(1, 1, 1)).norm(), 0, kExact);
}

// ---------------------------------------------------------------- x-axis shapes

TEST(Contacts, CapsuleLiesAlongX) {
  const Geometry cap = Geometry::compile(capsule(0.1, 1.0));
  const Geometry s = Geometry::compile(sphere(0.1));
  ContactQuery q;
  // Beyond the end: cap reaches x = 0.5 + 0.1.
  EXPECT_NEAR(q.distance(cap, at(0, 0, 0), s, at(1.0, 0, 0)), 0.3, kExact);
  // To the side: only the radius.
  EXPECT_NEAR(q.distance(cap, at(0, 0, 0), s, at(0, 1.0, 0)), 0.8, kExact);
  EXPECT_NEAR(q.distance(cap, at(0, 0, 0), s, at(0, 0, 1.0)), 0.8, kExact);
  // Turned a quarter about z, the capsule lies along y.
  EXPECT_NEAR(q.distance(cap, at(0, 0, 0, std::numbers::pi / 2), s, at(0, 1.0, 0)), 0.3, kExact);
  const Eigen::AlignedBox3d& lb = cap.local_box();
  expect_vec(lb.min(), Vector3d(-0.6, -0.1, -0.1), kExact);
  expect_vec(lb.max(), Vector3d(0.6, 0.1, 0.1), kExact);
}

TEST(Contacts, CylinderLiesAlongX) {
  const Geometry cyl = Geometry::compile(cylinder(0.1, 1.0));
  const Geometry s = Geometry::compile(sphere(0.1));
  ContactQuery q;
  // Beyond the flat end at x = 0.5.
  EXPECT_NEAR(q.distance(cyl, at(0, 0, 0), s, at(1.0, 0, 0)), 0.4, kGjk);
  EXPECT_NEAR(q.distance(cyl, at(0, 0, 0), s, at(0, 1.0, 0)), 0.8, kGjk);
  EXPECT_NEAR(q.distance(cyl, at(0, 0, 0), s, at(0.3, 0, 1.0)), 0.8, kGjk);
  // Past the rim: nearest point (0.5, 0.1, 0).
  EXPECT_NEAR(q.distance(cyl, at(0, 0, 0), s, at(0.8, 0.5, 0)), 0.5 - 0.1, kGjk);
  const Eigen::AlignedBox3d& lb = cyl.local_box();
  expect_vec(lb.min(), Vector3d(-0.5, -0.1, -0.1), kExact);
  expect_vec(lb.max(), Vector3d(0.5, 0.1, 0.1), kExact);
  // The FCL offset takes FCL's axis (z) to ours (x).
  expect_vec(cyl.fcl_offset().linear() * Vector3d::UnitZ(), Vector3d::UnitX(), 0);
}

TEST(Contacts, EllipsoidSupportAndBox) {
  const Geometry e = Geometry::compile(ellipsoid(0.3, 0.2, 0.1));
  expect_vec(e.local_box().min(), Vector3d(-0.3, -0.2, -0.1), 0);
  expect_vec(e.local_box().max(), Vector3d(0.3, 0.2, 0.1), 0);
  EXPECT_NEAR(e.support(Vector3d::UnitX()), 0.3, kExact);
  EXPECT_NEAR(e.support(-Vector3d::UnitZ()), 0.1, kExact);
  // |diag(r) d| for d = (1, 1, 0)/sqrt 2.
  EXPECT_NEAR(e.support(Vector3d(1, 1, 0).normalized()), std::sqrt(0.13 / 2), kExact);
  const Geometry s = Geometry::compile(sphere(0.1));
  ContactQuery q;
  EXPECT_NEAR(q.distance(e, at(0, 0, 0), s, at(1, 0, 0)), 0.6, kGjk);
  EXPECT_NEAR(q.distance(e, at(0, 0, 0), s, at(0, 0, 1)), 0.8, kGjk);
}

// ---------------------------------------------------------------- convex hulls

// The hull's faces close up (each edge met once each way) and face outward.
void expect_closed_outward_hull(const Geometry& g) {
  const auto& cv = dynamic_cast<const fcl::Convexd&>(g.fcl());
  const std::vector<Vector3d>& v = cv.getVertices();
  const std::vector<int>& f = cv.getFaces();
  Vector3d inside = Vector3d::Zero();
  for (const Vector3d& x : v) inside += x;
  inside /= static_cast<double>(v.size());
  std::map<std::pair<int, int>, int> edges;
  std::size_t k = 0;
  for (int face = 0; face < cv.getFaceCount(); ++face) {
    ASSERT_EQ(f[k], 3);
    const int a = f[k + 1], b = f[k + 2], c = f[k + 3];
    const Vector3d n = (v[b] - v[a]).cross(v[c] - v[a]);
    EXPECT_GT(n.dot(v[a] - inside), 0) << "face " << face << " faces inward";
    ++edges[{a, b}];
    ++edges[{b, c}];
    ++edges[{c, a}];
    k += 4;
  }
  EXPECT_EQ(k, f.size());
  for (const auto& [e, count] : edges) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(edges.count({e.second, e.first}), 1u);
  }
  // Euler: a closed triangulated surface has F = 2V - 4.
  EXPECT_EQ(cv.getFaceCount(), 2 * static_cast<int>(v.size()) - 4);
}

TEST(Contacts, HullOfACubeIsTheBox) {
  std::vector<Vector3d> pts = cube_corners(0.5);
  // Interior points, a face centre and an edge middle: none is a hull vertex.
  pts.insert(pts.begin() + 3, {Vector3d(0, 0, 0), Vector3d(0.1, 0.2, -0.3), Vector3d(0.5, 0, 0),
                               Vector3d(0.5, 0.5, 0)});
  const Geometry hull = Geometry::compile(convex(pts));
  const Geometry cube = Geometry::compile(box(1, 1, 1));
  const auto& cv = dynamic_cast<const fcl::Convexd&>(hull.fcl());
  EXPECT_EQ(cv.getVertices().size(), 8u);
  EXPECT_EQ(cv.getFaceCount(), 12);
  expect_closed_outward_hull(hull);
  expect_vec(hull.local_box().min(), Vector3d::Constant(-0.5), 0);
  expect_vec(hull.local_box().max(), Vector3d::Constant(0.5), 0);

  const Geometry s = Geometry::compile(sphere(0.1));
  ContactQuery q;
  for (const Isometry3d& ps : {at(1, 0.2, 0.1), at(0.9, 0.9, 0), at(-0.3, 0.1, -1.2)}) {
    const double expected = q.distance(cube, at(0, 0, 0, 0.4), s, ps);
    EXPECT_NEAR(q.distance(hull, at(0, 0, 0, 0.4), s, ps), expected, kGjk);
  }
  EXPECT_NEAR(q.distance(hull, at(0, 0, 0), s, at(1, 0.2, 0.1)), 0.4, kGjk);
}

TEST(Contacts, HullOfSpherePointsIsNearlyTheSphere) {
  const Geometry hull = Geometry::compile(convex(sphere_points(100, 1.0)));
  const auto& cv = dynamic_cast<const fcl::Convexd&>(hull.fcl());
  EXPECT_EQ(cv.getVertices().size(), 100u);  // every point is extreme
  expect_closed_outward_hull(hull);

  // Within the sagitta of the facets (about 2 cm for 100 points on 1 m).
  const Geometry ball = Geometry::compile(sphere(1.0));
  const Geometry probe = Geometry::compile(sphere(0.01));
  ContactQuery q;
  for (const Isometry3d& pp : {at(3, 0.5, 0.2), at(-0.1, -2.5, 0.7), at(0.3, 0.4, 4)}) {
    const double round = q.distance(ball, at(0, 0, 0), probe, pp);
    const double flat = q.distance(hull, at(0, 0, 0), probe, pp);
    EXPECT_GE(flat, round - kGjk);
    EXPECT_LE(flat, round + 0.03);
  }
  for (const Vector3d& d : {Vector3d(1, 0, 0), Vector3d(0.3, -0.5, 0.8).normalized()}) {
    EXPECT_LE(hull.support(d), 1.0 + kExact);
    EXPECT_GE(hull.support(d), 0.97);
  }
}

// Many coplanar and collinear points: a 5x5x5 grid is still an 8-corner cube.
TEST(Contacts, HullOfAGridIsItsCorners) {
  std::vector<Vector3d> pts;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k) pts.emplace_back(0.01 * i, 0.02 * j - 0.03, 0.005 * k);
  const Geometry hull = Geometry::compile(convex(pts));
  const auto& cv = dynamic_cast<const fcl::Convexd&>(hull.fcl());
  EXPECT_EQ(cv.getVertices().size(), 8u);
  expect_closed_outward_hull(hull);
  expect_vec(hull.local_box().min(), Vector3d(0, -0.03, 0), 1e-15);
  expect_vec(hull.local_box().max(), Vector3d(0.04, 0.05, 0.02), 1e-15);
}

// Random points in a ball (a few hundred, as a hand-written shape might have).
TEST(Contacts, HullOfRandomPointsIsClosed) {
  std::vector<Vector3d> pts;
  unsigned state = 12345;
  auto uniform = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24) * 2 - 1;
  };
  while (pts.size() < 300) {
    const Vector3d x(uniform(), uniform(), uniform());
    if (x.norm() <= 1) pts.push_back(0.05 * x);
  }
  const Geometry hull = Geometry::compile(convex(pts));
  expect_closed_outward_hull(hull);
  // Every input point is inside: its projection on any direction is below the support.
  for (const Vector3d& d : {Vector3d(1, 0, 0), Vector3d(-0.2, 0.9, 0.4).normalized()}) {
    double best = -1;
    for (const Vector3d& x : pts) best = std::max(best, x.dot(d));
    EXPECT_NEAR(hull.support(d), best, 1e-15);
  }
}

TEST(Contacts, DegenerateHullsAreDataErrors) {
  const std::vector<std::pair<std::string, std::vector<Vector3d>>> cases = {
      {"three points", {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)}},
      {"duplicates", std::vector<Vector3d>(6, Vector3d(1, 2, 3))},
      {"collinear", {Vector3d(0, 0, 0), Vector3d(1, 1, 1), Vector3d(2, 2, 2), Vector3d(-1, -1, -1),
                     Vector3d(0.5, 0.5, 0.5)}},
      {"coplanar", {Vector3d(0, 0, 1), Vector3d(1, 0, 1), Vector3d(0, 1, 1), Vector3d(1, 1, 1),
                    Vector3d(0.3, 0.7, 1)}},
      {"none", {}},
  };
  for (const auto& [name, pts] : cases) {
    try {
      Geometry::compile(convex(pts));
      ADD_FAILURE() << name << ": no error";
    } catch (const DataError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("x.yaml:3:7"), std::string::npos) << name << ": " << what;
      EXPECT_NE(what.find("expected "), std::string::npos) << name << ": " << what;
      EXPECT_NE(what.find(", found "), std::string::npos) << name << ": " << what;
      EXPECT_EQ(e.loc().line, 3);
    }
  }
}

// ---------------------------------------------------------------- support

TEST(Contacts, SupportOfEachKind) {
  const Vector3d x = Vector3d::UnitX(), y = Vector3d::UnitY();
  const Vector3d xy = Vector3d(1, 1, 0).normalized();
  const Vector3d xyz = Vector3d(1, 1, 1).normalized();
  const double r2 = std::sqrt(0.5), r3 = std::sqrt(1.0 / 3);

  const Geometry s = Geometry::compile(sphere(0.3));
  EXPECT_NEAR(s.support(xyz), 0.3, kExact);
  const Geometry b = Geometry::compile(box(0.2, 0.4, 0.6));
  EXPECT_NEAR(b.support(xyz), 0.6 * r3, kExact);
  EXPECT_NEAR(b.support(-y), 0.2, kExact);
  const Geometry cap = Geometry::compile(capsule(0.1, 1.0));
  EXPECT_NEAR(cap.support(x), 0.6, kExact);
  EXPECT_NEAR(cap.support(y), 0.1, kExact);
  EXPECT_NEAR(cap.support(xy), 0.5 * r2 + 0.1, kExact);
  const Geometry cyl = Geometry::compile(cylinder(0.1, 1.0));
  EXPECT_NEAR(cyl.support(-x), 0.5, kExact);
  EXPECT_NEAR(cyl.support(y), 0.1, kExact);
  EXPECT_NEAR(cyl.support(xy), 0.6 * r2, kExact);
  const Geometry e = Geometry::compile(ellipsoid(0.3, 0.2, 0.1));
  EXPECT_NEAR(e.support(xyz), std::sqrt(0.14) * r3, kExact);
  const Geometry hull = Geometry::compile(convex(cube_corners(0.5)));
  EXPECT_NEAR(hull.support(xyz), 1.5 * r3, kExact);
  EXPECT_NEAR(hull.support(x), 0.5, kExact);
}

// support(d) agrees with FCL's shape (offset included): the distance from the
// shape to a large slab whose face is the plane x . d = 2 m is 2 - support(d).
TEST(Contacts, SupportMatchesFclShape) {
  const std::vector<ShapeSpec> specs = {
      sphere(0.3),        box(0.2, 0.4, 0.6),        capsule(0.1, 1.0),
      cylinder(0.1, 1.0), ellipsoid(0.3, 0.2, 0.1), convex(sphere_points(40, 0.4)),
  };
  // Kept small: GJK's error grows with the size of the shapes.
  const Geometry slab = Geometry::compile(box(6, 6, 2));  // face at local z = -1
  ContactQuery q;
  for (const ShapeSpec& spec : specs) {
    const Geometry g = Geometry::compile(spec);
    for (const Vector3d& d : {Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(1, 2, 3).normalized(),
                              Vector3d(-0.7, 0.1, 0.2).normalized()}) {
      Isometry3d ps = Isometry3d::Identity();
      ps.linear() = Eigen::Quaterniond::FromTwoVectors(Vector3d::UnitZ(), d).toRotationMatrix();
      ps.translation() = 3 * d;
      EXPECT_NEAR(q.distance(g, at(0, 0, 0), slab, ps), 2 - g.support(d), kGjk)
          << static_cast<int>(spec.kind) << " along " << d.transpose();
    }
  }
}

// ---------------------------------------------------------------- boxes_apart

TEST(Contacts, BoxesApart) {
  const Geometry cube = Geometry::compile(box(1, 1, 1));
  // A 0.1 m gap along x.
  EXPECT_TRUE(boxes_apart(cube, at(0, 0, 0), cube, at(1.1, 0.3, 0), 0.05));
  EXPECT_FALSE(boxes_apart(cube, at(0, 0, 0), cube, at(1.1, 0.3, 0), 0.2));
  EXPECT_FALSE(boxes_apart(cube, at(0, 0, 0), cube, at(0.9, 0.3, 0), 0));
  // Turned 45 degrees, the cube reaches sqrt(2)/2 along x: gap 1.3 - 0.707 - 0.5.
  EXPECT_TRUE(boxes_apart(cube, at(0, 0, 0, std::numbers::pi / 4), cube, at(1.3, 0, 0), 0.05));
  EXPECT_FALSE(boxes_apart(cube, at(0, 0, 0, std::numbers::pi / 4), cube, at(1.3, 0, 0), 0.1));
  // A capsule's box is long along x: gap 0.75 - 0.6 - 0.1 along x, 0.3 along y.
  const Geometry cap = Geometry::compile(capsule(0.1, 1.0));
  const Geometry s = Geometry::compile(sphere(0.1));
  EXPECT_TRUE(boxes_apart(cap, at(0, 0, 0), s, at(0.75, 0, 0), 0.01));
  EXPECT_FALSE(boxes_apart(cap, at(0, 0, 0), s, at(0.75, 0, 0), 0.1));
  EXPECT_TRUE(boxes_apart(cap, at(0, 0, 0), s, at(0, 0.5, 0), 0.2));
  EXPECT_FALSE(boxes_apart(cap, at(0, 0, 0), s, at(0, 0.5, 0), 0.4));
}

}  // namespace
}  // namespace afford
