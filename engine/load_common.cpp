// Readers shared by every kind of file: shapes, poses, ranges, directions.
#include <cmath>

#include "load.h"

namespace afford {
namespace {

Eigen::Matrix3d rotation_xyz(const Eigen::Vector3d& angles_rad) {
  // Turns about the fixed x, then y, then z axes.
  return (Eigen::AngleAxisd(angles_rad.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(angles_rad.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(angles_rad.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Vector3d read_positive_vector(const Node& node, const Dimension& d) {
  const Eigen::Vector3d v = read_vector(node, d);
  for (int i = 0; i < 3; ++i) require_positive(node[static_cast<size_t>(i)], v[i]);
  return v;
}

}  // namespace

ShapeSpec read_shape(const Node& node) {
  static const char* const kKinds[] = {"sphere", "box", "capsule", "cylinder", "ellipsoid", "convex"};
  MapReader outer(node, "a shape", {kKinds, kKinds + 6});
  const auto entries = outer.entries();
  if (entries.size() != 1) {
    node.fail("exactly one of sphere, box, capsule, cylinder, ellipsoid, convex",
              std::to_string(entries.size()) + " keys");
  }
  ShapeSpec shape;
  shape.loc = node.loc();
  const std::string kind = entries[0].first;
  int index = 0;
  for (int i = 0; i < 6; ++i) {
    if (kind == kKinds[i]) index = i;  // the reader has rejected any other
  }
  shape.kind = static_cast<ShapeKind>(index);
  static const std::vector<std::string> kKeys[] = {
      {"radius"}, {"size"}, {"radius", "length"}, {"radius", "length"}, {"radii"}, {"unit", "vertices"}};
  MapReader m(outer.required(kind), "a " + kind, kKeys[index]);
  switch (shape.kind) {
    case ShapeKind::sphere:
      shape.radius = read_positive(m.required("radius"), dim::length);
      break;
    case ShapeKind::box:
      shape.size = read_positive_vector(m.required("size"), dim::length);
      break;
    case ShapeKind::capsule:
    case ShapeKind::cylinder: {
      shape.radius = read_positive(m.required("radius"), dim::length);
      shape.length = read_positive(m.required("length"), dim::length);
      break;
    }
    case ShapeKind::ellipsoid:
      shape.radii = read_positive_vector(m.required("radii"), dim::length);
      break;
    case ShapeKind::convex: {
      const Node unit_node = m.required("unit");
      std::string error;
      const std::optional<Quantity> unit = parse_unit(read_string(unit_node), &error);
      if (!unit || !(unit->dimension == dim::length)) unit_node.fail("a length unit such as mm");
      const Node list = m.required("vertices");
      if (!list.is_sequence()) list.fail("a sequence of [x, y, z] points");
      for (size_t i = 0; i < list.size(); ++i) {
        shape.vertices.push_back(read_plain_vector(list[i]) * unit->si);
      }
      break;
    }
  }
  return shape;
}

}  // namespace afford

namespace afford {

PoseSpec read_pose(MapReader& map) {
  PoseSpec pose;
  pose.position = read_vector(map.required("position"), dim::length);
  if (std::optional<Node> r = map.optional("rotation")) {
    pose.rotation = rotation_xyz(read_vector(*r, dim::angle));
  }
  return pose;
}

RangeSpec read_range(const Node& node, const std::string& what) {
  MapReader m(node, what, {"from", "to"});
  RangeSpec range;
  range.loc = node.loc();
  range.from = read_quantity(m.required("from"), dim::length);
  const Node to = m.required("to");
  range.to = read_quantity(to, dim::length);
  if (!(range.to > range.from)) {
    to.fail("'to' greater than 'from' (" + format_quantity(range.from, dim::length) + ")");
  }
  return range;
}

Eigen::Vector3d read_direction(const Node& node) {
  const Eigen::Vector3d v = read_plain_vector(node);
  if (!(v.norm() > 1e-12)) node.fail("a direction, not all zeros");
  return v.normalized();
}

std::string file_kind(const Node& root) {
  if (!root.is_map() || root.size() == 0) root.fail("a mapping whose first key names the kind of file");
  return root.yaml().begin()->first.Scalar();
}

}  // namespace afford
