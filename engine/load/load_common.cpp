// Readers shared by every kind of file: shapes, poses, ranges, directions,
// friction.
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
  for (int i = 0; i < 3; ++i) {
    // Each size as a sphere's radius: above 0 and at least the smallest length (1 um).
    require_positive(node[static_cast<size_t>(i)], v[i]);
    require_at_least_smallest(node[static_cast<size_t>(i)], d, v[i]);
  }
  return v;
}

}  // namespace

const MapSchema& shape_schema() {
  using namespace schema;
  static const MapSchema kSphere{"a sphere about the part's origin",
                                 {required_key("radius", quantity(dim::length), "the sphere's radius")}};
  static const MapSchema kBox{"a box centred on the part's origin",
                              {required_key("size", vector(dim::length), "the edge lengths along x, y, z")}};
  static const MapSchema kCapsule{
      "a capsule along the part's z axis",
      {required_key("radius", quantity(dim::length), "the radius of the cylinder and its end caps"),
       required_key("length", quantity(dim::length), "the length of the cylinder between the caps")}};
  static const MapSchema kCylinder{"a cylinder along the part's z axis",
                                   {required_key("radius", quantity(dim::length), "the cylinder's radius"),
                                    required_key("length", quantity(dim::length), "the cylinder's length")}};
  static const MapSchema kEllipsoid{"an ellipsoid about the part's origin",
                                    {required_key("radii", vector(dim::length), "the semi-axes along x, y, z")}};
  static const MapSchema kConvex{
      "the convex hull of points",
      {required_key("unit", text(), "the length unit of the vertices, such as mm"),
       required_key("vertices", sequence(plain_vector()), "the points [x, y, z] in that unit")}};
  static const MapSchema kShape{"exactly one kind of shape and its sizes",
                                {optional_key("sphere", mapping(kSphere), "a sphere"),
                                 optional_key("box", mapping(kBox), "a box"),
                                 optional_key("capsule", mapping(kCapsule), "a capsule"),
                                 optional_key("cylinder", mapping(kCylinder), "a cylinder"),
                                 optional_key("ellipsoid", mapping(kEllipsoid), "an ellipsoid"),
                                 optional_key("convex", mapping(kConvex), "a convex hull")},
                                true};
  return kShape;
}

const MapSchema& range_schema() {
  using namespace schema;
  static const MapSchema kRange{"a stretch of the arm, by distance from the fulcrum",
                                {required_key("from", quantity(dim::length), "where it starts"),
                                 required_key("to", quantity(dim::length), "where it ends, beyond from")}};
  return kRange;
}

std::vector<KeySchema> pose_keys(const std::string& what) {
  using namespace schema;
  return {required_key("position", vector(dim::length), "the position of " + what),
          optional_key("rotation", vector(dim::angle), "the turns of " + what + " about x, then y, then z")};
}

ShapeSpec read_shape(const Node& node) {
  const MapSchema& kinds = shape_schema();
  MapReader outer(node, "a shape", kinds);
  const auto entries = outer.entries();
  if (entries.size() != 1) {
    node.fail("exactly one of sphere, box, capsule, cylinder, ellipsoid, convex",
              std::to_string(entries.size()) + " keys");
  }
  ShapeSpec shape;
  shape.loc = node.loc();
  const std::string kind = entries[0].first;
  size_t index = 0;
  for (size_t i = 0; i < kinds.keys.size(); ++i) {
    if (kind == kinds.keys[i].key) index = i;  // the reader has rejected any other
  }
  shape.kind = static_cast<ShapeKind>(index);
  MapReader m(outer.required(kind), "a " + kind, *kinds.keys[index].value.mapping);
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
  MapReader m(node, what, range_schema());
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

// Rubber on rough steel reaches about 1 to 2; beyond 3 is a typo.
constexpr double kMaxFriction = 3;

const MapSchema& friction_schema() {
  using namespace schema;
  static const MapSchema kFriction{
      "a coefficient of static friction against the tool's jaws, and where it was published",
      {required_key("coefficient", number(), "mu: above 0, at most 3"),
       required_key("source", text(), "the publication the coefficient comes from")}};
  return kFriction;
}

double read_friction(const Node& node, std::string* source) {
  MapReader m(node, "the friction", friction_schema());
  const Node mu = m.required("coefficient");
  const double friction = read_number(mu);
  if (!(friction > 0) || friction > kMaxFriction) mu.fail("a coefficient above 0 and at most 3");
  *source = read_string(m.required("source"));
  return friction;
}

std::string file_kind(const Node& root) {
  if (!root.is_map() || root.size() == 0) root.fail("a mapping whose first key names the kind of file");
  return root.yaml().begin()->first.Scalar();
}

}  // namespace afford
