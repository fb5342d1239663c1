// The shapes the contact and GJK tests build, by their sizes (m), and
// where they stand.
#pragma once

#include <Eigen/Geometry>

#include "spec.h"

namespace afford::test {

inline ShapeSpec box(double x, double y, double z) {  // full edge lengths
  ShapeSpec s;
  s.kind = ShapeKind::box;
  s.size = {x, y, z};
  return s;
}

inline ShapeSpec ellipsoid(double a, double b, double c) {  // semi-axes
  ShapeSpec s;
  s.kind = ShapeKind::ellipsoid;
  s.radii = {a, b, c};
  return s;
}

// At (x, y, z) (m), turned by turn_z (rad) about z.
inline Eigen::Isometry3d at(double x, double y, double z, double turn_z = 0) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = Eigen::AngleAxisd(turn_z, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  p.translation() = Eigen::Vector3d(x, y, z);
  return p;
}

}  // namespace afford::test
