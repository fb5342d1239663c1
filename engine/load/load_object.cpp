// objects/*.yaml -> ObjectSpec, with every physical check that one file
// can answer by itself.
#include <cmath>
#include <numbers>

#include "did_you_mean.h"
#include "lever.h"
#include "load.h"

namespace afford {
namespace {

void require_on_arm(const Node& node, double distance, const RangeSpec& arm) {
  if (distance < arm.from || distance > arm.to) {
    node.fail("a distance on the arm, between " + format_quantity(arm.from, dim::length) +
              " and " + format_quantity(arm.to, dim::length));
  }
}

// A {from, to} region on the arm: reports at the value that is off it.
void require_region_on_arm(const Node& region_node, const RangeSpec& region, const RangeSpec& arm) {
  require_on_arm(region_node.child(region_node.yaml()["from"]), region.from, arm);
  require_on_arm(region_node.child(region_node.yaml()["to"]), region.to, arm);
}

const MapSchema& lever_schema() {
  using namespace schema;
  static const MapSchema kLever{
      "the lever: its pattern, the arm's extent and the opening angles",
      {required_key("pattern", choice({"type1-power", "type1-distance", "type1-balance", "type2", "type3"}),
                    "the lever pattern the emphasis and application regions make"),
       required_key("arm", mapping(range_schema()), "the extent of the arm, from the fulcrum"),
       required_key("theta_min", quantity(dim::angle), "the smallest opening angle, 0 deg or more"),
       required_key("theta_max", quantity(dim::angle), "the largest opening angle, below 180 deg"),
       required_key("rest", quantity(dim::angle), "the opening angle of the untouched tool")}};
  return kLever;
}

const MapSchema& spring_schema() {
  using namespace schema;
  static const MapSchema kSpring{
      "the spring between the arms: exactly one of rest_length and preload",
      {required_key("constant", quantity(dim::stiffness), "the spring's stiffness"),
       required_key("position", quantity(dim::length), "where it sits on the arm, away from the fulcrum"),
       optional_key("rest_length", quantity(dim::length), "its free length"),
       optional_key("preload", quantity(dim::force), "its force at the rest angle")},
      false,
      {{"rest_length", "preload"}}};
  return kSpring;
}

const MapSchema& part_schema() {
  using namespace schema;
  static const MapSchema kPart = [] {
    MapSchema m{"a rigid part on one arm",
                {required_key("name", name(), "the part's name, unique in the object"),
                 required_key("arm", choice({"fixed", "moving"}), "the arm the part belongs to"),
                 required_key("shape", mapping(shape_schema()), "the part's collision shape")}};
    for (KeySchema& k : pose_keys("the part")) m.keys.push_back(std::move(k));
    m.keys.push_back(optional_key("friction", mapping(friction_schema()),
                                  "its surface's static friction on any actee (rubber tips, serrations); "
                                  "without it, the actee's own"));
    return m;
  }();
  return kPart;
}

const MapSchema& functional_pose_schema() {
  static const MapSchema kPose{"where the tool is held while it works", pose_keys("the tool")};
  return kPose;
}

const MapSchema& symmetry_plane_schema() {
  using namespace schema;
  static const MapSchema kPlane{"the tool's plane of symmetry",
                                {required_key("point", vector(dim::length), "a point on the plane"),
                                 required_key("normal", plain_vector(), "the plane's normal, not all zeros")}};
  return kPlane;
}

LeverSpec read_lever(const Node& node) {
  MapReader m(node, "the lever", lever_schema());
  LeverSpec lever;
  lever.loc = node.loc();
  const Node pattern = m.required("pattern");
  lever.pattern_loc = pattern.loc();
  const std::string p = read_choice(
      pattern, {"type1-power", "type1-distance", "type1-balance", "type2", "type3"});
  for (LeverPattern candidate : {LeverPattern::type1_power, LeverPattern::type1_distance,
                                 LeverPattern::type1_balance, LeverPattern::type2,
                                 LeverPattern::type3}) {
    if (p == pattern_name(candidate)) lever.pattern = candidate;
  }
  lever.arm = read_range(m.required("arm"), "the arm's extent");
  const Node tmin = m.required("theta_min");
  const Node tmax = m.required("theta_max");
  const Node rest = m.required("rest");
  lever.theta_min = read_quantity(tmin, dim::angle);
  lever.theta_max = read_quantity(tmax, dim::angle);
  lever.theta_rest = read_quantity(rest, dim::angle);
  if (lever.theta_min < 0) tmin.fail("an opening angle of 0 deg or more");
  if (!(lever.theta_max > lever.theta_min)) {
    tmax.fail("theta_max greater than theta_min (" + format_quantity(lever.theta_min, dim::angle) + ")");
  }
  if (lever.theta_max >= std::numbers::pi) tmax.fail("an opening angle below 180 deg");
  if (lever.theta_rest < lever.theta_min || lever.theta_rest > lever.theta_max) {
    rest.fail("a rest angle between theta_min and theta_max");
  }
  return lever;
}

SpringSpec read_spring(const Node& node, const LeverSpec& lever) {
  MapReader m(node, "the spring", spring_schema());
  SpringSpec spring;
  spring.loc = node.loc();
  spring.constant = read_positive(m.required("constant"), dim::stiffness);
  const Node pos = m.required("position");
  spring.position = read_quantity(pos, dim::length);
  require_on_arm(pos, spring.position, lever.arm);
  if (spring.position == 0) pos.fail("a spring away from the fulcrum");
  const std::optional<Node> rest_length = m.optional("rest_length");
  const std::optional<Node> preload = m.optional("preload");
  if (rest_length.has_value() == preload.has_value()) {
    node.fail("exactly one of rest_length and preload",
              rest_length ? "both" : "neither");
  }
  // Either way the spring is a spring free at the rest angle plus a preload:
  // k * (rest_length - |S_p| * theta) = k * |S_p| * (rest - theta) + preload.
  const Node& where = rest_length ? *rest_length : *preload;
  spring.preload_loc = where.loc();
  if (rest_length) {
    const double gap_at_rest = std::abs(spring.position) * lever.theta_rest;
    spring.preload = spring.constant * (read_positive(*rest_length, dim::length) - gap_at_rest);
  } else {
    spring.preload = read_non_negative(*preload, dim::force);
  }
  return spring;
}

// The untouched tool must be at rest: a spring that pushes at the rest angle
// holds it open against theta_max, one that pulls holds it closed against
// theta_min.
void check_preload(const LeverSpec& lever, const SpringSpec& spring, double preload, const SourceLoc& where) {
  const double compression = preload / spring.constant;
  if (compression > 1e-12 && lever.theta_rest != lever.theta_max) {
    fail(where, "a spring free at the rest angle, or the rest angle at theta_max",
         "a spring compressed by " + format_quantity(compression, dim::length) + " at a rest angle below theta_max");
  }
  if (compression < -1e-12 && lever.theta_rest != lever.theta_min) {
    fail(where, "a spring free at the rest angle, or the rest angle at theta_min",
         "a spring stretched by " + format_quantity(-compression, dim::length) + " at a rest angle above theta_min");
  }
}

// The spring section's preload is the spring_preload effect's parameter;
// given in both places it would be counted twice.
void add_spring_preload(ObjectSpec& o) {
  for (const EffectSpec& e : o.effects) {
    if (e.kind != EffectKind::spring_preload) continue;
    if (o.spring.preload != 0) {
      fail(e.loc, "the spring's preload given once",
           "spring_preload here and a preload of " + format_quantity(o.spring.preload, dim::force) + " at line " +
               std::to_string(o.spring.preload_loc.line) + " in the spring section");
    }
    if (e.enabled) check_preload(o.lever, o.spring, e.param[0], e.loc);
    return;
  }
  check_preload(o.lever, o.spring, o.spring.preload, o.spring.preload_loc);
  if (o.spring.preload == 0) return;
  EffectSpec e;
  e.name = "spring_preload";
  e.kind = EffectKind::spring_preload;
  e.param[0] = o.spring.preload;
  e.loc = o.spring.preload_loc;
  o.effects.push_back(e);
}

// The regions must agree with the declared lever pattern (Fig. 2).
void check_pattern(const ObjectSpec& o) {
  std::string why;
  const std::optional<LeverPattern> derived = derive_pattern(o.emphasis, o.application, &why);
  if (!derived) fail(o.application.loc, why, "regions that make no lever pattern");
  if (*derived != o.lever.pattern) {
    fail(o.lever.pattern_loc, std::string("the pattern that the emphasis and application regions make, ") +
                          pattern_name(*derived),
                      std::string("'") + pattern_name(o.lever.pattern) + "'");
  }
}

const MapSchema& interaction_space_schema() {
  using namespace schema;
  static const MapSchema kSpace{
      "the interaction space L_is from the shape: the jaws' gap fully open along the arm",
      {required_key("distances", sequence(quantity(dim::length), 2),
                    "signed distances along the fixed arm, increasing, within the application region"),
       required_key("gap_at_theta_max", sequence(quantity(dim::length), 2),
                    "the gap between the jaws at theta_max at each distance, from the fixed jaw's face")}};
  return kSpace;
}

// At least two lengths, one per element: the distances or the gaps.
std::vector<double> read_lengths(const Node& node, const std::string& what) {
  if (!node.is_sequence() || node.size() < 2) node.fail("a sequence of at least 2 " + what);
  std::vector<double> out;
  for (size_t i = 0; i < node.size(); ++i) out.push_back(read_quantity(node[i], dim::length));
  return out;
}

InteractionSpaceSpec read_interaction_space(const Node& node, const RangeSpec& application) {
  MapReader m(node, "the interaction space", interaction_space_schema());
  InteractionSpaceSpec s;
  s.loc = node.loc();
  const Node distances = m.required("distances");
  s.distances = read_lengths(distances, "distances");
  for (size_t i = 0; i < s.distances.size(); ++i) {
    const double r = s.distances[i];
    if (i > 0 && !(r > s.distances[i - 1])) {
      distances[i].fail("a distance greater than the one before (" + format_quantity(s.distances[i - 1], dim::length) +
                        ")");
    }
    if (r < application.from || r > application.to) {
      distances[i].fail("a distance in the application region, between " +
                        format_quantity(application.from, dim::length) + " and " +
                        format_quantity(application.to, dim::length));
    }
  }
  const Node gaps = m.required("gap_at_theta_max");
  s.gaps = read_lengths(gaps, "gaps");
  if (s.gaps.size() != s.distances.size()) {
    gaps.fail("as many gaps as distances (" + std::to_string(s.distances.size()) + ")",
              std::to_string(s.gaps.size()));
  }
  // The moving jaw's nearest point to a place on the fixed jaw is at most
  // the distance between two places farther from the next: a gap changes
  // no faster than the distance along the arm (1 um for the written digits).
  constexpr double kWritten = 1e-6;  // m
  for (size_t i = 0; i < s.gaps.size(); ++i) {
    require_non_negative(gaps[i], s.gaps[i]);
    if (i == 0) continue;
    const double step = s.distances[i] - s.distances[i - 1];
    if (std::abs(s.gaps[i] - s.gaps[i - 1]) > step + kWritten) {
      gaps[i].fail("a gap within " + format_quantity(step, dim::length) + " of the one before (" +
                   format_quantity(s.gaps[i - 1], dim::length) +
                   "): a gap changes no faster than the distance along the arm");
    }
  }
  return s;
}

// A part sits on its arm: its position along the arm (x) within the arm's
// extent, else it would hang in the air beyond the tool.
PartSpec read_part(const Node& node, const RangeSpec& arm) {
  MapReader m(node, "a part", part_schema());
  PartSpec part;
  part.loc = node.loc();
  part.name = read_name(m.required("name"));
  part.arm = read_choice(m.required("arm"), {"fixed", "moving"}) == "fixed" ? Arm::fixed : Arm::moving;
  part.shape = read_shape(m.required("shape"));
  part.pose = read_pose(m);
  if (std::optional<Node> friction = m.optional("friction")) part.friction = read_friction(*friction, &part.friction_source);
  const double along = part.pose.position.x();
  if (along < arm.from || along > arm.to) {
    fail(node.child(node.yaml()["position"]).loc(),
         "a part on its arm: a position along it (x) between " + format_quantity(arm.from, dim::length) + " and " +
             format_quantity(arm.to, dim::length),
         format_quantity(along, dim::length));
  }
  return part;
}

}  // namespace

const MapSchema& object_schema() {
  using namespace schema;
  static const MapSchema kObject{
      "an object file: an articulated hand tool (objects/README.md)",
      {required_key("object", name(), "the tool's name"),
       required_key("description", text(), "what the tool is, in a sentence"),
       required_key("mass", quantity(dim::mass), "the tool's mass"),
       required_key("centre_of_gravity", vector(dim::length), "the centre of gravity in the object frame"),
       required_key("functional_pose", mapping(functional_pose_schema()), "where the tool is held while it works"),
       required_key("symmetry_plane", mapping(symmetry_plane_schema()), "the tool's plane of symmetry"),
       required_key("lever", mapping(lever_schema()), "the lever: pattern, arm and opening angles"),
       required_key("spring", mapping(spring_schema()), "the spring between the arms"),
       required_key("emphasis", mapping(range_schema()), "where the hand pushes, on the arm"),
       required_key("application", mapping(range_schema()), "where the tool acts on the actee, on the arm"),
       optional_key("interaction_space", mapping(interaction_space_schema()),
                    "the jaws' gap fully open along the arm, from the shape (afford model); without it the wedge "
                    "of flat jaw faces through the pivot"),
       required_key("parts", sequence(mapping(part_schema()), 1), "the rigid parts, on both arms"),
       optional_key("effects", mapping(effects_schema(EffectHome::object)), "optional effects of the lever")}};
  return kObject;
}

ObjectSpec read_object(const Node& root) {
  MapReader m(root, "an object file", object_schema());
  ObjectSpec o;
  o.loc = root.loc();
  o.file = root.loc().file;
  o.name = read_name(m.required("object"));
  o.description = read_string(m.required("description"));
  o.mass = read_positive(m.required("mass"), dim::mass);
  o.centre_of_gravity = read_vector(m.required("centre_of_gravity"), dim::length);
  {
    MapReader pose(m.required("functional_pose"), "the functional pose", functional_pose_schema());
    o.functional_pose = read_pose(pose);
  }
  {
    MapReader plane(m.required("symmetry_plane"), "the symmetry plane", symmetry_plane_schema());
    o.symmetry_plane.point = read_vector(plane.required("point"), dim::length);
    o.symmetry_plane.normal = read_direction(plane.required("normal"));
  }
  const Node lever = m.required("lever");
  o.lever = read_lever(lever);
  // A tool modelled from a mesh or a URDF has no spring until one is given.
  if (!m.has("spring")) {
    root.fail("key 'spring' in an object file (a tool modelled from a mesh or a URDF has none)",
              "none: give it with afford model ... --spring K_N_M_PER_RAD,REST_DEG, or write a guess and fit it to a "
              "probing trace with afford gap --probe");
  }
  o.spring = read_spring(m.required("spring"), o.lever);
  const Node emphasis = m.required("emphasis");
  o.emphasis = read_range(emphasis, "the emphasis region");
  require_region_on_arm(emphasis, o.emphasis, o.lever.arm);
  const Node application = m.required("application");
  o.application = read_range(application, "the application region");
  require_region_on_arm(application, o.application, o.lever.arm);
  check_pattern(o);
  if (std::optional<Node> space = m.optional("interaction_space")) {
    o.interaction_space = read_interaction_space(*space, o.application);
  }
  const Node parts = m.required("parts");
  if (!parts.is_sequence() || parts.size() == 0) parts.fail("a sequence of parts");
  bool has_arm[2] = {false, false};
  for (size_t i = 0; i < parts.size(); ++i) {
    PartSpec part = read_part(parts[i], o.lever.arm);
    for (const PartSpec& other : o.parts) {
      if (other.name == part.name) parts[i].fail("a part name used once", "'" + part.name + "' again");
    }
    has_arm[static_cast<int>(part.arm)] = true;
    o.parts.push_back(std::move(part));
  }
  if (!has_arm[0] || !has_arm[1]) parts.fail("parts on both arms, fixed and moving");
  if (std::optional<Node> effects = m.optional("effects")) o.effects = read_effects(*effects, EffectHome::object);
  add_spring_preload(o);
  return o;
}

ObjectSpec load_object(const std::string& path) { return read_object(load_yaml_file(path)); }

}  // namespace afford
