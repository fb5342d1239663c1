// Agent scripts: YAML keyframes -> ScriptSpec -> Script (see script.h).
#include "script.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "did_you_mean.h"
#include "grasps.h"
#include "load.h"
#include "reach.h"
#include "squeeze.h"
#include "units.h"

namespace afford {

const std::array<Eigen::Vector3d, kFingers> kCurledFingertip = {
    Eigen::Vector3d(0.060, 0.030, -0.030),   // thumb, folded over the palm
    Eigen::Vector3d(0.070, 0.010, -0.030),   // index
    Eigen::Vector3d(0.072, -0.008, -0.030),  // middle
    Eigen::Vector3d(0.068, -0.025, -0.028),  // ring
    Eigen::Vector3d(0.060, -0.040, -0.025),  // little
};

namespace {

constexpr double kMinGripDistance = 1e-3;  // m: closer to the fulcrum a thumb cannot turn the lever


const MapSchema& squeeze_until_schema() {
  using namespace schema;
  static const MapSchema kUntil{
      "squeeze until a force, in the lever's static balance (engine/model/squeeze.h)",
      {required_key("until", choice({"actee_force", "effort"}), "the force: the actee's, or the hand's effort"),
       required_key("value", quantity(dim::force), "the force reached, above 0")}};
  return kUntil;
}

const MapSchema& grip_schema() {
  using namespace schema;
  static const MapSchema kGrip{
      "thumb and index on the arms, by distance from the fulcrum",
      {required_key("thumb", quantity(dim::length),
                    "the thumb on the moving arm's outer face, at this signed distance"),
       required_key("index", any_of({quantity(dim::length), choice({"none"})}),
                    "the index on the fixed arm's outer face at this distance, or none"),
       required_key("squeeze", any_of({quantity(dim::length), mapping(squeeze_until_schema())}),
                    "how far the thumb is advanced past the rest angle (0 or more), or the force it squeezes until")}};
  return kGrip;
}

const MapSchema& hand_schema() {
  static const MapSchema kHand{"the hand's pose in the world", pose_keys("the hand")};
  return kHand;
}

// Every finger, each with `value`.
MapSchema per_finger(const std::string& description, const ValueSchema& value, const std::string& what) {
  MapSchema m{description};
  for (const char* finger : kFingerNames) {
    m.keys.push_back(schema::required_key(finger, value, what + " of the " + finger));
  }
  return m;
}

const MapSchema& fingertips_schema() {
  static const MapSchema kTips =
      per_finger("every fingertip's target, in the hand frame", schema::vector(dim::length), "the target");
  return kTips;
}

const MapSchema& posture_schema() {
  static const MapSchema kPosture =
      per_finger("every finger's joint angles", schema::sequence(schema::quantity(dim::angle), kJoints, kJoints),
                 "the angles [distal, proximal, metacarpal]");
  return kPosture;
}

GripSpec read_grip(const Node& node) {
  MapReader m(node, "the grip", grip_schema());
  GripSpec g;
  const Node thumb = m.required("thumb");
  g.thumb = read_quantity(thumb, dim::length);
  g.thumb_loc = thumb.loc();
  const Node index = m.required("index");
  g.index_loc = index.loc();
  if (index.is_scalar() && index.yaml().Scalar() == "none") {
    g.has_index = false;
  } else {
    if (!index.is_scalar()) index.fail("a length (e.g. '130 mm') or none");
    g.index = read_quantity(index, dim::length);
  }
  const Node squeeze = m.required("squeeze");
  g.squeeze_loc = squeeze.loc();
  if (squeeze.is_map()) {
    MapReader until(squeeze, "the squeeze", squeeze_until_schema());
    const std::string by = read_choice(until.required("until"), {"actee_force", "effort"});
    g.squeeze_by = by == "actee_force" ? SqueezeBy::actee_force : SqueezeBy::effort;
    g.until = read_positive(until.required("value"), dim::force);
  } else {
    g.squeeze = read_non_negative(squeeze, dim::length);
  }
  return g;
}

void read_posture(const Node& node, KeyframeSpec& k) {
  k.posture_loc = node.loc();
  if (node.is_scalar()) {
    k.posture = PostureSource::named;
    k.posture_name = read_name(node);
    return;
  }
  if (!node.is_map()) node.fail("a grasp type's name or a mapping of every finger's joint angles");
  k.posture = PostureSource::angles;
  MapReader fingers(node, "the posture", posture_schema());
  for (size_t f = 0; f < kFingers; ++f) {
    const Node angles = fingers.required(kFingerNames[f]);
    if (!angles.is_sequence() || angles.size() != kJoints) {
      angles.fail("three angles [distal, proximal, metacarpal]");
    }
    for (size_t j = 0; j < kJoints; ++j) {
      k.joint[f][j] = read_quantity(angles[j], dim::angle);
      k.joint_loc[f][j] = angles[j].loc();
    }
  }
}

}  // namespace

const MapSchema& keyframe_schema() {
  using namespace schema;
  static const MapSchema kKeyframe{
      "a keyframe: later keyframes carry forward what they omit",
      {optional_key("t", quantity(dim::time), "the keyframe's time, after the previous one's"),
       optional_key("after", quantity(dim::time), "the keyframe's time as a wait after the previous one's (or 0 s)"),
       optional_key("hold", quantity(dim::time), "alone: everything held still this long after the previous keyframe"),
       optional_key("release", boolean(),
                    "true: the fingers leave the tool, curled into the palm, by this keyframe (not with grip or "
                    "fingertips)"),
       optional_key("actee", name(), "the session's actee (of its `actees:`) on the tool from this keyframe on"),
       optional_key("hand", mapping(hand_schema()), "the hand's pose (required in the first keyframe)"),
       optional_key("grip", mapping(grip_schema()), "thumb and index on the arms (or fingertips)"),
       optional_key("fingertips", mapping(fingertips_schema()), "every fingertip's target (or grip)"),
       optional_key("posture", any_of({name(), mapping(posture_schema())}),
                    "a grasp type's name, or every finger's joint angles")},
      false,
      {{"t", "after", "hold"}}};
  return kKeyframe;
}

const MapSchema& first_keyframe_schema() {
  static const MapSchema kFirst = [] {
    MapSchema m = keyframe_schema();
    m.description = "the first keyframe: it gives hand, grip or fingertips, and posture";
    for (KeySchema& k : m.keys) k.required = k.required || k.key == "hand" || k.key == "posture";
    m.exactly_one_of.push_back({"grip", "fingertips"});
    return m;
  }();
  return kFirst;
}

namespace {

KeyframeSpec read_keyframe(const Node& node, const KeyframeSpec* previous) {
  MapReader m(node, "a keyframe", keyframe_schema());
  KeyframeSpec k;
  k.loc = node.loc();
  // The time: `t`, or a wait after the previous keyframe (`after`, or
  // `hold` for a keyframe that changes nothing).
  const int timings = (m.has("t") ? 1 : 0) + (m.has("after") ? 1 : 0) + (m.has("hold") ? 1 : 0);
  if (timings == 0) node.fail("key 't' (or 'after' or 'hold': the keyframe's time)", "none of them");
  if (timings > 1) {
    key_node(node, m.has("after") && m.has("t") ? "after" : "hold")
        .fail("one of t, after and hold (the keyframe's time)", "two of them");
  }
  const char* const timing = m.has("t") ? "t" : (m.has("after") ? "after" : "hold");
  const Node t = m.required(timing);
  k.t_loc = t.loc();
  const double since = previous == nullptr ? 0.0 : previous->t;
  k.t = std::string_view(timing) == "t" ? read_quantity(t, dim::time) : since + read_positive(t, dim::time);
  if (previous == nullptr && k.t < 0) t.fail("a time of 0 s or more");
  if (previous != nullptr && !(k.t > previous->t)) {
    t.fail("a time after the previous keyframe's (" + format_quantity(previous->t, dim::time) + ")");
  }
  if (m.has("hold") && m.entries().size() > 1) {
    key_node(node, m.entries()[m.entries()[0].first == "hold" ? 1 : 0].first)
        .fail("nothing beside 'hold' (it holds everything still; use 'after' to change something after a wait)",
              "more keys");
  }
  if (std::optional<Node> release = m.optional("release")) {
    if (!read_bool(*release)) release->fail("true (leave the key out to keep the fingers where they are)", "false");
    if (previous == nullptr) release->fail("a keyframe after the first (the first places the fingers)", "release");
    if (m.has("grip") || m.has("fingertips")) {
      release->fail("release alone or with hand and posture (it takes the fingers off the tool)",
                    "release with grip or fingertips");
    }
    k.fingers = FingerSource::fingertips;
    k.fingertip = kCurledFingertip;
  }
  if (std::optional<Node> hand = m.optional("hand")) {
    MapReader h(*hand, "the hand", hand_schema());
    k.hand = read_pose(h);
    k.has_hand = true;
  }
  if (m.has("grip") && m.has("fingertips")) {
    key_node(node, "fingertips").fail("either grip or fingertips in one keyframe", "both");
  }
  if (std::optional<Node> grip = m.optional("grip")) {
    k.fingers = FingerSource::grip;
    k.grip = read_grip(*grip);
  }
  if (std::optional<Node> tips = m.optional("fingertips")) {
    k.fingers = FingerSource::fingertips;
    MapReader fingers(*tips, "the fingertips", fingertips_schema());
    for (size_t f = 0; f < kFingers; ++f) {
      k.fingertip[f] = read_vector(fingers.required(kFingerNames[f]), dim::length);
    }
  }
  if (std::optional<Node> posture = m.optional("posture")) read_posture(*posture, k);
  if (std::optional<Node> actee = m.optional("actee")) {
    k.actee = read_name(*actee);
    k.actee_loc = actee->loc();
  }
  if (previous == nullptr) {
    const char* const kWhy = " in the first keyframe (it gives hand, grip or fingertips, and posture; later "
                             "keyframes carry forward what they omit)";
    if (!k.has_hand) node.fail("key 'hand'" + std::string(kWhy), "no such key");
    if (k.fingers == FingerSource::carried) node.fail("key 'grip' or 'fingertips'" + std::string(kWhy), "neither");
    if (k.posture == PostureSource::carried) node.fail("key 'posture'" + std::string(kWhy), "no such key");
  }
  return k;
}

Eigen::Isometry3d pose_of(const Eigen::Vector3d& position, const Eigen::Quaterniond& rotation) {
  Eigen::Isometry3d iso = Eigen::Isometry3d::Identity();
  iso.linear() = rotation.toRotationMatrix();
  iso.translation() = position;
  return iso;
}

// The extent of an arm: the lowest and highest distance any of its parts covers.
void arm_extent(const Model& m, Arm arm, double* from, double* to) {
  *from = std::numeric_limits<double>::infinity();
  *to = -std::numeric_limits<double>::infinity();
  for (const ModelPart& part : m.parts) {
    if (part.arm != arm) continue;
    const Eigen::Matrix3d rt = part.in_arm.linear().transpose();
    const double x = part.in_arm.translation().x();
    *from = std::min(*from, x - part.geometry.support(-rt * Eigen::Vector3d::UnitX()));
    *to = std::max(*to, x + part.geometry.support(rt * Eigen::Vector3d::UnitX()));
  }
}

// The point a fingertip of radius `radius` takes on an arm's outer face at r.
Eigen::Vector3d on_face(const Model& m, Arm arm, double r, double radius, const SourceLoc& loc) {
  const char* name = arm == Arm::moving ? "moving" : "fixed";
  if (std::abs(r) < kMinGripDistance) {
    fail(loc, std::string("a distance on the ") + name + " arm at least " +
                  format_quantity(kMinGripDistance, dim::length) + " from the fulcrum",
         format_quantity(r, dim::length));
  }
  double face = 0, z = 0;
  if (!arm_outer_face(m, arm, r, &face, &z)) {
    double from = 0, to = 0;
    arm_extent(m, arm, &from, &to);
    fail(loc,
         std::string("a distance on the ") + name + " arm (its parts cover " + format_quantity(from, dim::length) +
             " to " + format_quantity(to, dim::length) + ")",
         format_quantity(r, dim::length));
  }
  const double side = face >= 0 ? 1.0 : -1.0;
  return {r, face + side * (radius - kGripPress), z};
}

// Angles written in a keyframe must lie within the agent's ranges.
void check_joints(const Model& m, const KeyframeSpec& k) {
  for (size_t f = 0; f < kFingers; ++f) {
    for (size_t j = 0; j < kJoints; ++j) {
      const double v = k.joint[f][j], lo = m.joint_min[f][j], hi = m.joint_max[f][j];
      if (v >= lo && v <= hi) continue;
      fail(k.joint_loc[f][j],
           "an angle within the agent's range (" + std::string(kFingerNames[f]) + " " + kJointNames[j] +
               " between " + format_quantity(lo, dim::angle) + " and " + format_quantity(hi, dim::angle) + ")",
           format_quantity(v, dim::angle));
    }
  }
}

// The joint angles that stand for the named grasp type.
JointAngles named_posture(const Model& m, const KeyframeSpec& k) {
  const std::vector<std::string>& names = m.grasp_name;
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] != k.posture_name) continue;
    JointAngles joint{};
    std::string why;
    if (!grasp_posture(m, static_cast<int>(i), &joint, &why)) {
      fail(k.posture_loc, "a grasp type the agent's joints can take", "'" + k.posture_name + "': " + why);
    }
    const int type = classify_grasp(m, joint);
    if (type != static_cast<int>(i)) {
      fail(k.posture_loc, "a grasp type whose posture the taxonomy classifies as itself",
           "'" + k.posture_name + "', classified as " + (type < 0 ? "no type" : "'" + names[static_cast<size_t>(type)] + "'") +
               " (an earlier type covers it)");
    }
    return joint;
  }
  if (names.empty()) {
    fail(k.posture_loc, "joint angles (the session has no grasp taxonomy to name a posture from)",
         "'" + k.posture_name + "'");
  }
  std::string expected = "a grasp type of the taxonomy (";
  for (size_t i = 0; i < names.size(); ++i) expected += (i ? ", " : "") + names[i];
  fail(k.posture_loc, expected + ")", "'" + k.posture_name + "'" + did_you_mean(k.posture_name, names));
}

// A squeeze given as a force, as the thumb's advance that reaches it
// (squeeze.h), within the hand's largest effort and its grasp's.
double squeeze_until(const Model& m, const GripSpec& grip, const JointAngles& joint, const ForcedLever& lever) {
  const int type = m.grasp_name.empty() ? -1 : classify_grasp(m, joint);
  const double cap = grasp_force_cap(m, type);
  const std::string whose =
      cap < m.max_force ? "the grasp " + m.grasp_name[static_cast<size_t>(type)] + "'s" : std::string("the agent's");
  double effort = grip.until;
  if (grip.squeeze_by == SqueezeBy::effort && effort > cap) {
    fail(grip.squeeze_loc, "an effort within " + whose + " largest, " + format_quantity(cap, dim::force),
         format_quantity(effort, dim::force));
  }
  std::string why;
  if (grip.squeeze_by == SqueezeBy::actee_force &&
      !effort_for_actee_force(m, lever, grip.thumb, grip.until, cap, &effort, &why)) {
    fail(grip.squeeze_loc, "an actee force the hand reaches (" + whose + " largest effort is " +
                               format_quantity(cap, dim::force) + ")",
         format_quantity(grip.until, dim::force) + ": " + why);
  }
  return squeeze_for_effort(m, lever, grip.thumb, effort);
}

}  // namespace

ScriptSpec read_script(const Node& sequence) {
  ScriptSpec spec;
  spec.loc = sequence.loc();
  if (!sequence.is_sequence() || sequence.size() == 0) sequence.fail("a sequence of keyframes");
  for (size_t i = 0; i < sequence.size(); ++i) {
    spec.keyframes.push_back(read_keyframe(sequence[i], i == 0 ? nullptr : &spec.keyframes.back()));
  }
  if (!(spec.keyframes.back().t > 0)) {
    fail(spec.keyframes.back().t_loc, "a last keyframe after 0 s (the script's duration)",
         format_quantity(spec.keyframes.back().t, dim::time));
  }
  // A session runs its script's duration: bounded, so that a typo cannot
  // run for ever and fill the disk with trace.csv.
  if (spec.keyframes.back().t > kMaxScriptDuration) {
    fail(spec.keyframes.back().t_loc,
         "a last keyframe at most " + format_quantity(kMaxScriptDuration, dim::time) + " (the script's duration)",
         format_quantity(spec.keyframes.back().t, dim::time));
  }
  return spec;
}

bool arm_outer_face(const Model& m, Arm arm, double r, double* face_y, double* mid_z) {
  // Moving arm: +y for r > 0, -y for r < 0; the fixed arm the other way.
  const double side = ((arm == Arm::moving) == (r >= 0)) ? 1.0 : -1.0;
  const Eigen::Vector3d out = side * Eigen::Vector3d::UnitY();
  bool found = false;
  double best = -std::numeric_limits<double>::infinity();
  for (const ModelPart& part : m.parts) {
    if (part.arm != arm) continue;
    const Eigen::Matrix3d rt = part.in_arm.linear().transpose();
    const Eigen::Vector3d& p = part.in_arm.translation();
    const Geometry& g = part.geometry;
    const double x_lo = p.x() - g.support(-rt * Eigen::Vector3d::UnitX());
    const double x_hi = p.x() + g.support(rt * Eigen::Vector3d::UnitX());
    if (r < x_lo || r > x_hi) continue;
    const double reach = p.dot(out) + g.support(rt * out);  // furthest extent along `out`
    if (found && reach <= best) continue;
    found = true;
    best = reach;
    *mid_z = p.z() + 0.5 * (g.support(rt * Eigen::Vector3d::UnitZ()) - g.support(-rt * Eigen::Vector3d::UnitZ()));
  }
  if (found) *face_y = side * best;
  return found;
}

void grip_points(const Model& m, const GripSpec& grip, Eigen::Vector3d* thumb_rest, double* thumb_angle,
                 Eigen::Vector3d* index) {
  *thumb_rest = on_face(m, Arm::moving, grip.thumb, m.tip_radius[0], grip.thumb_loc);
  // Squeezing turns the thumb's point about the pivot, closing.
  *thumb_angle = m.theta_rest - grip.squeeze / std::abs(grip.thumb);
  if (grip.has_index) *index = on_face(m, Arm::fixed, grip.index, m.tip_radius[1], grip.index_loc);
}

Eigen::Vector3d grip_thumb(const Keyframe& k, double angle_rad) {
  return k.object_in_hand * (Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ()) * k.thumb_rest);
}

bool grasp_posture(const Model& m, int type, JointAngles* out, std::string* why) {
  constexpr size_t kPerType = static_cast<size_t>(kFingers) * kJoints;
  const size_t base = static_cast<size_t>(type) * kPerType;
  for (size_t f = 0; f < kFingers; ++f) {
    for (size_t j = 0; j < kJoints; ++j) {
      const double lo = std::max(m.grasp_joint_min[base + f * kJoints + j], m.joint_min[f][j]);
      const double hi = std::min(m.grasp_joint_max[base + f * kJoints + j], m.joint_max[f][j]);
      if (!(lo <= hi)) {
        *why = std::string("its ") + kFingerNames[f] + " " + kJointNames[j] + " range lies outside the agent's (" +
               format_quantity(m.joint_min[f][j], dim::angle) + " to " + format_quantity(m.joint_max[f][j], dim::angle) +
               ")";
        return false;
      }
      (*out)[f][j] = 0.5 * (lo + hi);
    }
  }
  return true;
}

Script compile_script(const ScriptSpec& spec, const Model& first, std::span<const Model> actee_models) {
  if (!first.has_agent) throw LogicError("compile_script() needs a model with its agent");
  const Model* in_play = &first;  // the model of the actee on the tool at this keyframe
  Script script;
  script.keyframes.reserve(spec.keyframes.size());
  Eigen::Isometry3d object_world = first.object_start;  // where the script expects the tool
  Eigen::Isometry3d object_in_hand = Eigen::Isometry3d::Identity();
  bool holding = false;  // the last keyframe grasped the tool: a finger on the fixed arm, a grasp posture
  Keyframe current;
  const GripSpec* grip = nullptr;  // the grip in force, if the fingers come from one
  std::optional<ForcedLever> lever;  // the lever at the start, once a squeeze is given as a force
  for (const KeyframeSpec& k : spec.keyframes) {
    if (k.actee_index >= 0) {
      if (static_cast<size_t>(k.actee_index) >= actee_models.size()) {
        throw LogicError("compile_script(): a keyframe's actee has no model");
      }
      in_play = &actee_models[static_cast<size_t>(k.actee_index)];
      lever.reset();  // a squeeze by force is the new actee's
    }
    const Model& m = *in_play;
    current.t = k.t;
    if (k.has_hand) {
      current.hand_position = k.hand.position;
      current.hand_rotation = Eigen::Quaterniond(k.hand.rotation).normalized();
    }
    const Eigen::Isometry3d hand = pose_of(current.hand_position, current.hand_rotation);
    if (k.posture == PostureSource::named) {
      current.joint = named_posture(m, k);
    } else if (k.posture == PostureSource::angles) {
      check_joints(m, k);
      current.joint = k.joint;
    }
    // Only a posture of the taxonomy grasps (when there is one).
    const bool posture_grasps = m.grasp_name.empty() || classify_grasp(m, current.joint) >= 0;
    if (k.fingers == FingerSource::grip) grip = &k.grip;
    if (k.fingers == FingerSource::fingertips) {
      grip = nullptr;
      current.fingertip = k.fingertip;
    }
    current.grip = grip != nullptr;
    if (grip != nullptr) {
      Eigen::Vector3d index = Eigen::Vector3d::Zero();
      GripSpec resolved = *grip;
      if (grip->squeeze_by != SqueezeBy::distance) {
        if (!lever) lever = lever_at_start(m);
        resolved.squeeze = squeeze_until(m, *grip, current.joint, *lever);
      }
      grip_points(m, resolved, &current.thumb_rest, &current.thumb_angle, &index);
      const bool grasps = grip->has_index && posture_grasps;
      if (grasps && holding) {
        object_world = hand * object_in_hand;  // grasped: the tool moves with the hand
      } else {
        object_in_hand = hand.inverse() * object_world;
      }
      current.object_in_hand = object_in_hand;
      current.fingertip = kCurledFingertip;
      current.fingertip[0] = grip_thumb(current, current.thumb_angle);
      if (grip->has_index) current.fingertip[1] = object_in_hand * index;
      holding = grasps;
    } else {
      holding = false;
    }
    current.grasps = holding;
    script.keyframes.push_back(current);
  }
  return script;
}

namespace {

// The named child of a mapping, if it has one.
std::optional<Node> child_of(const Node& map, const char* key) {
  if (!map.is_map()) return std::nullopt;
  for (auto it = map.yaml().begin(); it != map.yaml().end(); ++it) {
    if (it->first.Scalar() == key) return map.child(it->second);
  }
  return std::nullopt;
}

}  // namespace

void check_script_reach(const Node& script_node, const Script& script, const Model& m) {
  if (!m.has_agent || !m.has_reach) return;
  const double arm_lo = std::min(m.theta_min, m.theta_max), arm_hi = std::max(m.theta_min, m.theta_max);
  size_t hand_from = 0;  // the keyframe that last gave the hand's pose
  for (size_t i = 0; i < script.keyframes.size() && i < script_node.size(); ++i) {
    const Keyframe& k = script.keyframes[i];
    const Node key = script_node[i];
    if (child_of(key, "hand")) hand_from = i;
    for (int f = 0; f < kFingers; ++f) {
      Eigen::Vector3d tip = k.fingertip[static_cast<size_t>(f)];
      if (f == 0 && k.grip) tip = grip_thumb(k, std::clamp(k.thumb_angle, arm_lo, arm_hi));
      const double short_by = reach_short(m, f, tip);
      if (short_by <= 0) continue;
      const Node hand = *child_of(script_node[hand_from], "hand");
      const std::optional<Node> position = child_of(hand, "position");
      const SourceLoc at = position ? position->loc() : hand.loc();
      const size_t fu = static_cast<size_t>(f);
      fail(at,
           "a hand within reach of where the script puts the fingertips (" + m.agent_file + ": the " +
               kFingerNames[fu] + "'s tip reaches " + format_quantity(m.reach_min[fu], dim::length) + " to " +
               format_quantity(m.reach_max[fu], dim::length) + " from the wrist)",
           "the " + std::string(kFingerNames[fu]) + "'s tip " + format_quantity(tip.norm(), dim::length) +
               " from the wrist at " + format_quantity(k.t, dim::time) + " (keyframe at line " +
               std::to_string(key.loc().line) + "): " + format_quantity(short_by, dim::length) + " out of its reach");
    }
  }
}

}  // namespace afford
