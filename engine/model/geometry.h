// Collision geometry compiled from a ShapeSpec: an FCL shape that sessions
// share read-only, plus the few exact facts the solver and the guides need
// without a query (bounding box, support function).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <vector>

#include "spec.h"

namespace fcl {
template <typename S>
class CollisionGeometry;
}

namespace afford {

class Geometry {
 public:
  // Builds the FCL shape. Capsules and cylinders lie along the local x axis
  // (FCL's lie along z; the turn is folded in here). A convex shape is the
  // hull of its vertices; fewer than four points, or points that span no
  // volume, are a DataError at spec.loc.
  static Geometry compile(const ShapeSpec& spec);

  const fcl::CollisionGeometry<double>& fcl() const { return *fcl_; }
  // Maps this shape's local frame to FCL's frame for the shape (identity but
  // for capsules and cylinders).
  const Eigen::Isometry3d& fcl_offset() const { return fcl_offset_; }
  // Axis-aligned box of the shape in its local frame, m.
  const Eigen::AlignedBox3d& local_box() const { return local_box_; }
  // max over the shape of x . direction, local frame, m (direction unit).
  double support(const Eigen::Vector3d& direction) const;
  // A point of the shape where that maximum is reached, local frame, m
  // (direction of any length but zero): what GJK asks of a shape.
  Eigen::Vector3d support_point(const Eigen::Vector3d& direction) const;
  const ShapeSpec& spec() const { return spec_; }
  double volume() const;              // m^3
  Eigen::Vector3d centroid() const;   // m, of the volume, local frame

 private:
  ShapeSpec spec_;
  std::shared_ptr<fcl::CollisionGeometry<double>> fcl_;
  Eigen::Isometry3d fcl_offset_ = Eigen::Isometry3d::Identity();
  Eigen::AlignedBox3d local_box_;
  std::vector<Eigen::Vector3d> hull_vertices_;  // convex: the hull's vertices only
};

// The convex hull of points: its corners and its triangles, counter-
// clockwise seen from outside. Incremental, O(n^2): for the few hundred
// points of a shape written by hand (a `convex` part) or a mesh's extreme
// points. DataError at loc for fewer than four points, a non-finite one, or
// points that span no volume.
struct ConvexHull {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};
ConvexHull convex_hull(const std::vector<Eigen::Vector3d>& points, const SourceLoc& loc);

// One contact between two placed shapes: where, which way, how deep.
struct ContactPoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // m, world
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit, world, from shape a to shape b
  double distance = 0;  // m: > 0 a gap within tolerance, <= 0 touching or overlapping
};

// Pair queries between two placed geometries. One ContactQuery per session:
// it keeps FCL's request and result objects so that a frame allocates nothing.
class ContactQuery {
 public:
  ContactQuery();
  ~ContactQuery();
  ContactQuery(const ContactQuery&) = delete;
  ContactQuery& operator=(const ContactQuery&) = delete;

  // Separation distance, m; 0 when the shapes touch or overlap.
  double distance(const Geometry& a, const Eigen::Isometry3d& pose_a, const Geometry& b,
                  const Eigen::Isometry3d& pose_b);
  // The same, and when it is above 0 the nearest points (m, world) of each.
  // `start`, for a pair without a closed form: a direction from a to b to
  // begin the search from (the last answer for a pair that moved a little).
  double distance(const Geometry& a, const Eigen::Isometry3d& pose_a, const Geometry& b,
                  const Eigen::Isometry3d& pose_b, Eigen::Vector3d* near_a, Eigen::Vector3d* near_b,
                  const Eigen::Vector3d& start = Eigen::Vector3d::Zero());

  // True when the shapes are more than margin (m) apart: a distance that
  // may stop at a bound instead of the exact value.
  bool apart(const Geometry& a, const Eigen::Isometry3d& pose_a, const Geometry& b, const Eigen::Isometry3d& pose_b,
             double margin);

  // True when the shapes overlap or are closer than tolerance (m); then
  // `out` holds the deepest point (or the midpoint of the gap) and normal.
  bool contact(const Geometry& a, const Eigen::Isometry3d& pose_a, const Geometry& b,
               const Eigen::Isometry3d& pose_b, double tolerance, ContactPoint* out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Cheap rejection before a query: true when the world boxes of the two
// placed shapes, grown by margin (m), cannot touch.
bool boxes_apart(const Geometry& a, const Eigen::Isometry3d& pose_a, const Geometry& b,
                 const Eigen::Isometry3d& pose_b, double margin);

// The same in two steps, for a frame that tests one shape against several:
// a placed shape's world box once, then any pair of boxes.
struct WorldBox {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // m, world
  Eigen::Vector3d half = Eigen::Vector3d::Zero();    // m, half extents along the world axes
};
WorldBox world_box(const Geometry& g, const Eigen::Isometry3d& pose);
inline bool boxes_apart(const WorldBox& a, const WorldBox& b, double margin) {
  return ((a.centre - b.centre).cwiseAbs() - a.half - b.half).maxCoeff() > margin;
}

}  // namespace afford
