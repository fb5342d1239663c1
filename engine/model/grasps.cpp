// rules/grasps.yaml -> GraspTypeSpec, the compiler pass into the Model, and
// the per-frame classification of a posture.
#include "grasps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "model.h"
#include "yaml_reader.h"

namespace afford {

const char* grasp_kind_name(GraspKind k) {
  switch (k) {
    case GraspKind::power: return "power";
    case GraspKind::precision: return "precision";
  }
  return "?";
}

namespace {

// No joint of a hand turns further than this from the straight finger.
constexpr double kMaxJointAngle = std::numbers::pi;  // rad

JointRange read_joint_range(const Node& node) {
  if (!node.is_sequence() || node.size() != 2) node.fail("a pair [min, max] of angles");
  JointRange r;
  for (size_t i = 0; i < 2; ++i) {
    const double a = read_quantity(node[i], dim::angle);
    if (!(std::abs(a) <= kMaxJointAngle)) node[i].fail("an angle between -180 deg and 180 deg");
    (i == 0 ? r.min : r.max) = a;
  }
  if (!(r.max > r.min)) {
    node[1].fail("a maximum above the minimum (" + format_quantity(r.min, dim::angle) + ")");
  }
  return r;
}

const MapSchema& grasp_finger_schema() {
  using namespace schema;
  static const MapSchema kFinger = [] {
    MapSchema m{"the joint ranges of one finger; a joint not given is free"};
    for (const char* joint : kJointNames) {
      m.keys.push_back(optional_key(joint, sequence(quantity(dim::angle), 2, 2),
                                    std::string("the range [min, max] of the ") + joint + " joint"));
    }
    return m;
  }();
  return kFinger;
}

const MapSchema& grasp_fingers_schema() {
  using namespace schema;
  static const MapSchema kFingers = [] {
    MapSchema m{"the fingers the grasp type constrains; a finger not given is free"};
    for (const char* finger : kFingerNames) {
      m.keys.push_back(optional_key(finger, mapping(grasp_finger_schema()), std::string("the ") + finger));
    }
    return m;
  }();
  return kFingers;
}

const MapSchema& grasp_type_schema() {
  using namespace schema;
  static const MapSchema kType{
      "a grasp type: joint ranges that classify a hand posture",
      {required_key("name", name(), "the grasp type's name, unique in the file"),
       required_key("kind", choice({"power", "precision"}), "a power or a precision grasp"),
       required_key("description", text(), "what the grasp is, in a sentence"),
       required_key("max_force", quantity(dim::force), "the largest force a finger exerts in this grasp"),
       required_key("fingers", mapping(grasp_fingers_schema()), "the joint ranges, per finger")}};
  return kType;
}

GraspTypeSpec read_grasp_type(const Node& node, const std::vector<GraspTypeSpec>& before) {
  MapReader m(node, "a grasp type", grasp_type_schema());
  GraspTypeSpec g;
  g.loc = node.loc();
  const Node name = m.required("name");
  g.name = read_name(name);
  for (const GraspTypeSpec& other : before) {
    if (other.name == g.name) {
      name.fail("a grasp type name not used before", "'" + g.name + "' again (first at " + other.loc.str() + ")");
    }
  }
  g.kind = read_choice(m.required("kind"), {"power", "precision"}) == "power" ? GraspKind::power
                                                                              : GraspKind::precision;
  g.description = read_string(m.required("description"));
  g.max_force = read_positive(m.required("max_force"), dim::force);
  const Node fingers_node = m.required("fingers");
  MapReader fingers(fingers_node, "the fingers of " + g.name, grasp_fingers_schema());
  // A type that constrains nothing would take every posture, the open hand
  // too, for a grasp.
  if (fingers_node.size() == 0) fingers_node.fail("at least one finger with a joint range", "none");
  for (size_t f = 0; f < kFingers; ++f) {
    const std::optional<Node> finger_node = fingers.optional(kFingerNames[f]);
    if (!finger_node) continue;  // free
    const std::string what = std::string("the ") + kFingerNames[f] + " of " + g.name;
    MapReader finger(*finger_node, what, grasp_finger_schema());
    if (finger_node->size() == 0) finger_node->fail("at least one of distal, proximal, metacarpal", "none");
    for (size_t j = 0; j < kJoints; ++j) {
      if (std::optional<Node> range = finger.optional(kJointNames[j])) g.range[f][j] = read_joint_range(*range);
    }
  }
  return g;
}

}  // namespace

const MapSchema& grasps_schema() {
  using namespace schema;
  static const MapSchema kGrasps{
      "a grasp taxonomy file (rules/README.md)",
      {required_key("grasps", sequence(mapping(grasp_type_schema()), 1), "the grasp types, first match wins")}};
  return kGrasps;
}

std::vector<GraspTypeSpec> read_grasps(const Node& root) {
  MapReader top(root, "a grasps file", grasps_schema());
  const Node list = top.required("grasps");
  if (!list.is_sequence() || list.size() == 0) list.fail("a sequence of grasp types");
  std::vector<GraspTypeSpec> grasps;
  for (size_t i = 0; i < list.size(); ++i) grasps.push_back(read_grasp_type(list[i], grasps));
  return grasps;
}

std::vector<GraspTypeSpec> load_grasps(const std::string& path) { return read_grasps(load_yaml_file(path)); }

void compile_grasps(const std::vector<GraspTypeSpec>& grasps, Model& m) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (const GraspTypeSpec& g : grasps) {
    m.grasp_name.push_back(g.name);
    m.grasp_kind.push_back(g.kind);
    m.grasp_max_force.push_back(g.max_force);
    for (size_t f = 0; f < kFingers; ++f) {
      for (size_t j = 0; j < kJoints; ++j) {
        const std::optional<JointRange>& r = g.range[f][j];
        m.grasp_joint_min.push_back(r ? r->min : -kInf);
        m.grasp_joint_max.push_back(r ? r->max : kInf);
      }
    }
  }
}

double grasp_force_cap(const Model& m, int type) {
  return type >= 0 ? std::min(m.max_force, m.grasp_max_force[static_cast<size_t>(type)]) : m.max_force;
}

int classify_grasp(const Model& m, const std::array<std::array<double, kJoints>, kFingers>& joints) {
  constexpr size_t kPerType = static_cast<size_t>(kFingers) * kJoints;
  const size_t types = m.grasp_max_force.size();
  for (size_t t = 0; t < types; ++t) {
    const double* lo = m.grasp_joint_min.data() + t * kPerType;
    const double* hi = m.grasp_joint_max.data() + t * kPerType;
    bool inside = true;
    for (size_t k = 0; k < kPerType && inside; ++k) {
      const double q = joints[k / kJoints][k % kJoints];
      inside = q >= lo[k] && q <= hi[k];  // a NaN joint is in no range
    }
    if (inside) return static_cast<int>(t);
  }
  return -1;
}

}  // namespace afford
