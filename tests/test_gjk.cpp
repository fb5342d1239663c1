// Our GJK (gjk.h) and the closed forms behind ContactQuery::distance, on
// pairs worked out by hand, against FCL on random poses, and the contact
// angle of the jaws on an ellipsoid against its tangency condition.
// Lengths in m.
#include <gtest/gtest.h>

#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/distance.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "gjk.h"
#include "stages.h"
#include "test_util.h"
#include "shape_specs.h"

namespace afford {
namespace {
using test::box;
using test::ellipsoid;
using test::at;

using Eigen::Isometry3d;
using Eigen::Vector3d;

constexpr double kGjkExact = 1e-12;

ShapeSpec round(ShapeKind kind, double r, double length) {
  ShapeSpec s;
  s.kind = kind;
  s.radius = r;
  s.length = length;
  return s;
}
ShapeSpec tetrahedron() {
  ShapeSpec s;
  s.kind = ShapeKind::convex;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  return s;
}

// ---------------------------------------------------------------- by hand

TEST(Gjk, EllipsoidOverABoxFace) {
  // The box reaches y = 0.5; the ellipsoid at y = 3 reaches down by its
  // y semi-axis, 1: the gap is 1.5, from the face to the ellipsoid's bottom.
  const Geometry b = Geometry::compile(box(2, 1, 2));
  const Geometry e = Geometry::compile(ellipsoid(3, 1, 2));
  const GjkResult r = gjk_distance(b, at(0, 0, 0), e, at(0.2, 3, 0.1));
  ASSERT_FALSE(r.overlap);
  EXPECT_NEAR(r.distance, 1.5, kGjkExact);
  EXPECT_NEAR(r.on_a.y(), 0.5, kGjkExact);
  EXPECT_NEAR((r.on_b - Vector3d(0.2, 2, 0.1)).norm(), 0, 1e-6);  // the bottom; flat: GJK's point slides
  // Turned a quarter about z, its 3 m semi-axis points down: 3 - 3 - 0.5 < 0.
  EXPECT_TRUE(gjk_distance(b, at(0, 0, 0), e, at(0, 3, 0, std::numbers::pi / 2)).overlap);
  // At y = 4 it clears the face by 0.5.
  EXPECT_NEAR(gjk_distance(b, at(0, 0, 0), e, at(0, 4, 0, std::numbers::pi / 2)).distance, 0.5, kGjkExact);
}

TEST(Gjk, BallLikeEllipsoidOffABoxEdgeAndCorner) {
  // An ellipsoid with equal semi-axes is a ball of radius 0.5: the distance
  // is that from the box's nearest edge or corner, less 0.5.
  const Geometry b = Geometry::compile(box(2, 2, 2));
  const Geometry e = Geometry::compile(ellipsoid(0.5, 0.5, 0.5));
  const GjkResult edge = gjk_distance(b, at(0, 0, 0), e, at(3, 3, 0.25));
  EXPECT_NEAR(edge.distance, std::sqrt(8.0) - 0.5, kGjkExact);
  // Along the edge the distance is flat to first order: a point off by s
  // adds s^2 / (2 d), so a picometre of distance leaves microns of point.
  EXPECT_NEAR((edge.on_a - Vector3d(1, 1, 0.25)).norm(), 0, 1e-6);
  const GjkResult corner = gjk_distance(b, at(0, 0, 0), e, at(3, -3, 3));
  EXPECT_NEAR(corner.distance, std::sqrt(12.0) - 0.5, kGjkExact);
  EXPECT_NEAR((corner.on_a - Vector3d(1, -1, 1)).norm(), 0, 1e-9);
  EXPECT_NEAR((corner.on_b - (Vector3d(3, -3, 3) - 0.5 * Vector3d(1, -1, 1).normalized())).norm(), 0, 1e-9);
}

TEST(Gjk, CapsuleAndCylinderAgainstABox) {
  const Geometry b = Geometry::compile(box(2, 2, 2));
  // A capsule along x above the top face: 3 - 1 - 0.5.
  const Geometry cap = Geometry::compile(round(ShapeKind::capsule, 0.5, 2));
  EXPECT_NEAR(gjk_distance(b, at(0, 0, 0), cap, at(0.5, 3, 0)).distance, 1.5, kGjkExact);
  // Turned upright (its axis along y), its end cap is 1 + 0.5 below its centre.
  EXPECT_NEAR(gjk_distance(b, at(0, 0, 0), cap, at(0, 4, 0, std::numbers::pi / 2)).distance, 1.5, kGjkExact);
  // Beside the box's z edge at (1, 1), the axis parallel to it: sqrt(8) - 0.5.
  Isometry3d along_z = at(3, 3, 0);
  along_z.linear() = Eigen::AngleAxisd(std::numbers::pi / 2, Vector3d::UnitY()).toRotationMatrix();
  EXPECT_NEAR(gjk_distance(b, at(0, 0, 0), cap, along_z).distance, std::sqrt(8.0) - 0.5, kGjkExact);
  // A cylinder end-on to the face: its flat end, 1 from its centre.
  const Geometry cyl = Geometry::compile(round(ShapeKind::cylinder, 0.5, 2));
  EXPECT_NEAR(gjk_distance(b, at(0, 0, 0), cyl, at(3.5, 0.2, 0)).distance, 1.5, kGjkExact);
}

TEST(Gjk, HullAgainstABox) {
  // The tetrahedron's slanted face x + y + z = 1 faces the corner (2, 2, 2)
  // of a box of half size 1 centred at (3, 3, 3): (6 - 1) / sqrt(3).
  const Geometry t = Geometry::compile(tetrahedron());
  const Geometry b = Geometry::compile(box(2, 2, 2));
  EXPECT_NEAR(gjk_distance(t, at(0, 0, 0), b, at(3, 3, 3)).distance, 5 / std::sqrt(3.0), kGjkExact);
  EXPECT_TRUE(gjk_distance(t, at(0, 0, 0), b, at(1.2, 0.5, 0.5)).overlap);
}

TEST(Gjk, OverlapAndTouching) {
  const Geometry b = Geometry::compile(box(2, 2, 2));
  const Geometry e = Geometry::compile(ellipsoid(1, 2, 1));
  EXPECT_TRUE(gjk_distance(b, at(0, 0, 0), e, at(0, 0, 0)).overlap);  // concentric
  EXPECT_TRUE(gjk_distance(b, at(0, 0, 0), e, at(0.5, 2.5, 0)).overlap);
  // Touching the face exactly: no gap worth a picometre.
  const GjkResult touching = gjk_distance(b, at(0, 0, 0), e, at(0, 3, 0));
  EXPECT_TRUE(touching.overlap || touching.distance < kGjkExact);
}

TEST(Gjk, ClosedFormsForSpheresThroughContactQuery) {
  // A sphere of radius 0.25 off a box of half size 1: face, edge, corner.
  ShapeSpec s;
  s.radius = 0.25;
  const Geometry ball = Geometry::compile(s);
  const Geometry b = Geometry::compile(box(2, 2, 2));
  ContactQuery q;
  EXPECT_NEAR(q.distance(ball, at(3, 0.5, 0), b, at(0, 0, 0)), 1.75, kGjkExact);
  EXPECT_NEAR(q.distance(b, at(0, 0, 0), ball, at(3, 3, -0.5)), std::sqrt(8.0) - 0.25, kGjkExact);
  Vector3d near_a, near_b;
  EXPECT_NEAR(q.distance(b, at(0, 0, 0), ball, at(-3, 3, 3), &near_a, &near_b), std::sqrt(12.0) - 0.25, kGjkExact);
  EXPECT_NEAR((near_a - Vector3d(-1, 1, 1)).norm(), 0, kGjkExact);
  EXPECT_NEAR((near_b - (Vector3d(-3, 3, 3) - 0.25 * Vector3d(-1, 1, 1).normalized())).norm(), 0, kGjkExact);
  // Against an ellipsoid (GJK from the centre): a ball-like one of radius 1 at 5.
  const Geometry e = Geometry::compile(ellipsoid(1, 1, 1));
  EXPECT_NEAR(q.distance(ball, at(0, 0, 0), e, at(3, 4, 0)), 5 - 1 - 0.25, kGjkExact);
}

TEST(Gjk, EllipsoidOverABoxFaceInClosedForm) {
  // ContactQuery takes a box and an ellipsoid apart across a face or an
  // edge in closed form. Turned 45 degrees about z, the ellipsoid (3, 1, 2) reaches down by
  // sqrt((3 sin)^2 + (1 cos)^2) = sqrt(5); its lowest point is
  // R diag(r)^2 d / |diag(r) d| with d = R^T (0, -1, 0): x = -8 / sqrt(20)
  // from its centre. Over the face (|x| < 1): the gap 5 - sqrt(5) - 0.5,
  // exactly, and the nearest points without GJK's sliding.
  const Geometry b = Geometry::compile(box(2, 1, 2));
  const Geometry e = Geometry::compile(ellipsoid(3, 1, 2));
  ContactQuery q;
  Vector3d on_box, on_e;
  const Isometry3d pe = at(1.5, 5, 0.1, std::numbers::pi / 4);
  const double x = 1.5 - 8 / std::sqrt(20.0);
  EXPECT_NEAR(q.distance(b, at(0, 0, 0), e, pe, &on_box, &on_e), 4.5 - std::sqrt(5.0), kGjkExact);
  EXPECT_NEAR((on_box - Vector3d(x, 0.5, 0.1)).norm(), 0, kGjkExact);
  EXPECT_NEAR((on_e - Vector3d(x, 5 - std::sqrt(5.0), 0.1)).norm(), 0, kGjkExact);
  // The same pair the other way round, and the box turned and moved with it.
  EXPECT_NEAR(q.distance(e, pe, b, at(0, 0, 0), &on_e, &on_box), 4.5 - std::sqrt(5.0), kGjkExact);
  EXPECT_NEAR((on_box - Vector3d(x, 0.5, 0.1)).norm(), 0, kGjkExact);
  const Isometry3d move = at(0.3, -0.2, 0.7, 1.1);
  EXPECT_NEAR(q.distance(b, move, e, move * pe, &on_box, &on_e), 4.5 - std::sqrt(5.0), kGjkExact);
  EXPECT_NEAR((on_e - move * Vector3d(x, 5 - std::sqrt(5.0), 0.1)).norm(), 0, kGjkExact);
  // Centred at x = 0.2 its lowest point is at x = -1.59, beyond the face's
  // edge at -1: the edge is nearest, and GJK answers (as gjk_distance does).
  const Isometry3d off = at(0.2, 5, 0.1, std::numbers::pi / 4);
  EXPECT_NEAR(q.distance(b, at(0, 0, 0), e, off), gjk_distance(b, at(0, 0, 0), e, off).distance, kGjkExact);
  EXPECT_GT(q.distance(b, at(0, 0, 0), e, off), 4.5 - std::sqrt(5.0));
  // Off an edge: a ball-like ellipsoid of radius 0.5 beside the z edge of a
  // box of half size 1 at (1, 1): sqrt(8) - 0.5, the box's point on the edge
  // level with the centre (no slide along the edge as GJK's would).
  const Geometry cube = Geometry::compile(box(2, 2, 2));
  const Geometry ball = Geometry::compile(ellipsoid(0.5, 0.5, 0.5));
  EXPECT_NEAR(q.distance(cube, at(0, 0, 0), ball, at(3, 3, 0.25), &on_box, &on_e), std::sqrt(8.0) - 0.5, 1e-13);
  EXPECT_NEAR((on_box - Vector3d(1, 1, 0.25)).norm(), 0, 1e-9);
  EXPECT_NEAR((on_e - (Vector3d(3, 3, 0.25) - 0.5 * Vector3d(1, 1, 0).normalized())).norm(), 0, 1e-9);
}

// Random pairs of a box and an ellipsoid or a capsule: ContactQuery (in
// closed form where a face or an edge is nearest) and GJK agree on the
// distance to GJK's tolerance, and on an ellipsoid's nearest points as far
// as GJK's slide on a flat face allows. Both answers are upper bounds of the true
// distance; the closed form's is within a tenth of the tolerance of it.
TEST(Gjk, BoxClosedFormsAgreeWithGjkOnRandomPoses) {
  const Geometry b = Geometry::compile(box(0.185, 0.012, 0.016));
  const std::vector<Geometry> shapes = {Geometry::compile(ellipsoid(0.018, 0.0141, 0.0125)),
                                        Geometry::compile(round(ShapeKind::capsule, 0.008, 0.032))};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> place(-0.1, 0.1), unit(-1, 1);
  ContactQuery q;
  int on_a_face = 0, on_an_edge = 0, at_a_corner = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Geometry& e = shapes[static_cast<size_t>(trial) % shapes.size()];
    Isometry3d pe = Isometry3d::Identity();
    pe.linear() = Eigen::Quaterniond(Eigen::Vector4d(unit(rng), unit(rng), unit(rng), unit(rng)).normalized())
                      .toRotationMatrix();
    pe.translation() = Vector3d(place(rng), 0.3 * place(rng), 0.3 * place(rng));
    const GjkResult g = gjk_distance(b, at(0, 0, 0), e, pe);
    Vector3d on_box, on_e;
    const double d = q.distance(b, at(0, 0, 0), e, pe, &on_box, &on_e);
    if (g.overlap) {
      EXPECT_EQ(d, 0) << "trial " << trial;
      continue;
    }
    EXPECT_NEAR(d, g.distance, kGjkDistanceTolerance) << "trial " << trial;
    EXPECT_LE(d, g.distance + 0.1 * kGjkDistanceTolerance) << "trial " << trial;
    // The ellipsoid's nearest point is unique (a capsule's is not where it
    // lies parallel to the face).
    if (e.spec().kind == ShapeKind::ellipsoid) {
      EXPECT_NEAR((on_box - g.on_a).norm(), 0, 1e-5) << "trial " << trial;
    }
    // Where the box's nearest point lies: inside a face (two coordinates
    // strictly within), on an edge (one), at a corner (none).
    const auto inside = ((0.5 * b.spec().size - on_box.cwiseAbs()).array() > 1e-9).count();
    (inside == 2 ? on_a_face : inside == 1 ? on_an_edge : at_a_corner) += 1;
  }
  EXPECT_GT(on_a_face, 300);
  EXPECT_GT(on_an_edge, 400);
  EXPECT_GT(at_a_corner, 100);
}

// ---------------------------------------------------------------- against FCL

// Random convex pairs apart by at least a millimetre: our distance agrees
// with FCL's GJK (asked for 1e-10) to FCL's own accuracy, and our nearest
// points are a witness pair: the plane between them separates the shapes.
TEST(Gjk, AgreesWithFclOnRandomPoses) {
  const std::vector<ShapeSpec> specs = {box(0.02, 0.05, 0.03), ellipsoid(0.018, 0.0141, 0.0141),
                                        ellipsoid(0.03, 0.01, 0.02), round(ShapeKind::capsule, 0.008, 0.032),
                                        round(ShapeKind::cylinder, 0.01, 0.04), tetrahedron()};
  std::vector<Geometry> shapes;
  for (ShapeSpec spec : specs) {
    for (Vector3d& v : spec.vertices) v *= 0.04;  // the tetrahedron's
    shapes.push_back(Geometry::compile(spec));
  }
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> place(-0.08, 0.08), unit(-1, 1);
  auto pose = [&] {
    Isometry3d p = Isometry3d::Identity();
    p.linear() = Eigen::Quaterniond(Eigen::Vector4d(unit(rng), unit(rng), unit(rng), unit(rng)).normalized())
                     .toRotationMatrix();
    p.translation() = Vector3d(place(rng), place(rng), place(rng));
    return p;
  };
  const fcl::DistanceRequestd request{true, false, 0, 0, 1e-10, fcl::GST_INDEP};
  int compared = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Geometry& a = shapes[static_cast<size_t>(trial) % shapes.size()];
    const Geometry& b = shapes[static_cast<size_t>(trial / 7) % shapes.size()];
    const Isometry3d pa = pose(), pb = pose();
    fcl::DistanceResultd fr;
    const double theirs = fcl::distance(&a.fcl(), pa * a.fcl_offset(), &b.fcl(), pb * b.fcl_offset(), request, fr);
    const GjkResult ours = gjk_distance(a, pa, b, pb);
    if (theirs < 1e-3) {
      if (theirs <= 0) {
        EXPECT_TRUE(ours.overlap || ours.distance < 1e-6) << "trial " << trial;
      }
      continue;
    }
    ++compared;
    ASSERT_FALSE(ours.overlap) << "trial " << trial;
    EXPECT_NEAR(ours.distance, theirs, 1e-7) << "trial " << trial;
    EXPECT_NEAR((ours.on_b - ours.on_a).norm(), ours.distance, 1e-12);
    const Vector3d n = (ours.on_b - ours.on_a) / ours.distance;
    // a reaches no farther along n than its nearest point, b no nearer. A
    // direction off by e changes the distance by d e^2 / 2, so GJK's
    // tolerance leaves n known to sqrt(2 tolerance / d): across the 6 cm
    // of these shapes, that tilts the plane by up to 6 cm times as much.
    const double tilt = 0.06 * std::sqrt(2 * kGjkDistanceTolerance / ours.distance);
    EXPECT_NEAR(a.support(pa.linear().transpose() * n) + pa.translation().dot(n), n.dot(ours.on_a), tilt);
    EXPECT_NEAR(b.support(pb.linear().transpose() * -n) - pb.translation().dot(n), -n.dot(ours.on_b), tilt);
  }
  EXPECT_GT(compared, 1000);
}

// ---------------------------------------------------------------- the jaws

// The nutcracker's moving jaw face (the plane through the hinge at angle
// theta, normal (-sin, cos, 0), the arm on its positive side) touches an
// ellipsoid of semi-axes (a, b, b) centred at (r, b) below it when the
// centre's depth under the plane equals the ellipsoid's reach along the
// normal: r sin - b cos = sqrt(a^2 sin^2 + b^2 cos^2); their difference is
// the gap. The jaw pushes it along that normal where it touches it: the
// load's lever arm (test_util.h's ellipsoid_under_jaw) is short of r for
// an ellipsoid long along the jaw.
TEST(Gjk, ContactAngleOnAnEllipsoidIsTheTangentPlane) {
  const double a = 0.018, b = 0.0141;
  Model m;
  m.theta_min = 0;
  m.theta_max = 30 * std::numbers::pi / 180;
  m.contact_tolerance = 5e-4;
  ModelPart fixed, moving;
  fixed.name = "fixed_arm";
  fixed.geometry = Geometry::compile(box(0.185, 0.012, 0.016));
  fixed.in_arm.translation() = Vector3d(0.0925, -0.006, 0);
  moving = fixed;
  moving.name = "moving_arm";
  moving.arm = Arm::moving;
  moving.in_arm.translation() = Vector3d(0.0925, 0.006, 0);
  m.parts = {fixed, moving};
  m.has_actee = true;
  m.actee_geometry = {Geometry::compile(ellipsoid(a, b, b))};
  ContactQuery q;
  for (double r : {0.065, 0.075, 0.090, 0.120}) {
    auto excess = [&](double t) {
      return r * std::sin(t) - b * std::cos(t) - std::hypot(a * std::sin(t), b * std::cos(t));
    };
    double theta_c = 0, load_distance = 0;
    std::vector<JawContact> contacts(2);
    ASSERT_EQ(find_contact_angle(m, at(r, b, 0), q, &theta_c, &load_distance, &contacts), JawFit::fits) << r;
    // The jaw within 1e-11 m of the actee, on the open side, as
    // find_contact_angle promises.
    // (GJK's tolerance, 1e-12 m, on the other side).
    EXPECT_GE(excess(theta_c), -kGjkExact) << "r = " << r;
    EXPECT_LE(excess(theta_c), 1e-11) << "r = " << r;
    EXPECT_TRUE(contacts[0].touching && contacts[1].touching);
    const test::JawTouch touch = test::ellipsoid_under_jaw(a, b, r, m.theta_max);
    EXPECT_NEAR(theta_c, touch.angle, 1e-9) << "r = " << r;
    EXPECT_NEAR(load_distance, touch.lever, 1e-9) << "r = " << r;
    EXPECT_LT(load_distance, r - 1e-3) << "r = " << r;
  }
}

}  // namespace
}  // namespace afford
