// The agent script of a session: keyframes of the hand's pose, its
// fingertips and its posture, interpolated linearly in time
// (devices/scripted_agent.h plays it). Read from YAML into a ScriptSpec
// that keeps the location of every value, then compiled against the Model
// into a Script of plain numbers: a `grip` is resolved to fingertip points
// on the tool's arms, a named posture to joint angles.
//
// A keyframe (a mapping in the session's `script:` sequence):
//
//   t: 1.5 s                     time, strictly increasing, the first >= 0;
//                                or instead `after: 0.5 s` (a wait after the
//                                previous keyframe), or `hold: 0.5 s` alone
//                                (everything held still that long)
//   release: true                the fingers curl off the tool into the
//                                palm (kCurledFingertip) by this keyframe;
//                                not with grip or fingertips
//   hand: {position: [x, y, z], rotation: [rx, ry, rz]}
//                                world pose of the hand frame; rotation
//                                optional (three angles about the world
//                                x, y, z axes, in that order; omitted means
//                                none), as a functional_pose
//   grip: {thumb: 130 mm, index: 130 mm, squeeze: 12 mm}
//                                the thumb on the moving arm's outer face at
//                                that signed distance from the fulcrum, the
//                                index on the fixed arm's outer face (or
//                                `index: none`), and the thumb advanced
//                                `squeeze` (>= 0) along the rotation
//                                direction past the rest angle, or
//                                `squeeze: {until: actee_force | effort,
//                                value: 150 N}`: the squeeze at which the
//                                lever settles with that force (squeeze.h)
//   fingertips: {thumb: [x, y, z], index: ..., middle: ..., ring: ...,
//                little: ...}    every fingertip centre in the hand frame
//   actee: hazelnut              in a session with several actees, the one
//                                on the tool from this keyframe on
//                                (session.h)
//   posture: medium_wrap         a grasp type of the model's grasp taxonomy
//                                (rules/grasps.yaml): every joint at the
//                                middle of the type's range and the agent's;
//                                a joint the type leaves free at the middle of
//                                the agent's range (this posture must
//                                classify as the type itself)
//   posture: {thumb: [distal, proximal, metacarpal], index: ..., ...}
//                                every joint angle (Fig. 8), within the
//                                agent's ranges
//
// The first keyframe gives `hand`, one of `grip` or `fingertips`, and
// `posture`. A later keyframe carries forward each of the three it omits
// (the hand stays, the fingers keep their grip, the posture is kept);
// `grip` and `fingertips` are two ways of giving the fingers, one at a
// time.
//
// Hand frame: origin at the wrist, +x from the wrist toward the fingers,
// +y toward the thumb, +z out of the back of the hand (the palm faces -z).
// Fingers that a `grip` does not use sit curled into the palm, at
// kCurledFingertip (hand frame), off the tool wherever the hand is held
// clear of it.
//
// How a grip is resolved. The outer face of an arm at distance r is found
// from the geometry of the arm's parts that cover r (Geometry::support and
// the parts' poses): the moving arm's face is +y of its frame for r > 0
// and -y for r < 0 (type 1 handles); the fixed arm's face is the opposite
// side. A fingertip sits on that face, pressed kGripPress into it, at the
// middle of the part's height (z). The thumb's point is then turned about
// the pivot (+z through the object origin) to the rest angle minus
// squeeze / |r|. The points are placed in the world through the tool's
// pose and into the hand frame through the keyframe's hand pose. The tool's
// pose is its functional pose (Model::object_start) until a grip with a
// finger on the fixed arm, in a posture of the grasp taxonomy, starts (the
// simulation's grasp, Sec. 4.3.1); while such grips follow one another the
// tool moves with the hand (the simulation grasps it), so the tool keeps
// its pose in the hand frame from the keyframe where the grip started;
// after the grip ends the tool stays where the last grip keyframe left it.
// Close the fingers on the tool, and open them, with the hand still (two
// keyframes with the same hand pose), so that the simulation grasps the
// tool exactly where the script expects it.
//
// Between keyframes the sample interpolates linearly: the hand's position
// and (by slerp) its rotation, each fingertip in the hand frame, each joint
// angle. One exception: while a grip's squeeze changes (same tool pose in
// the hand, same thumb distance), the thumb's angle about the pivot is
// interpolated, so the thumb moves on the arc the arm's face sweeps.
//
// The grasp starts when the fingertips come within the contact tolerance
// of the arms, so the last fraction of a millimetre of a closing approach
// already counts as squeeze (effort_pos in the trace runs that much ahead).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "model.h"
#include "spec.h"
#include "yaml_reader.h"

namespace afford {

// A fingertip centre this far inside a face it grips: touching for certain.
inline constexpr double kGripPress = 1e-4;  // m

// Where fingers not used by a grip sit: curled into the palm (hand frame, m).
// [0] and [1] are used for the thumb and an index given as `none`.
extern const std::array<Eigen::Vector3d, kFingers> kCurledFingertip;

using JointAngles = std::array<std::array<double, kJoints>, kFingers>;  // rad, [finger][joint]

// ------------------------------------------------------------ spec

// What a grip's `squeeze:` gives: a distance, or a force it squeezes until.
enum class SqueezeBy { distance, actee_force, effort };

struct GripSpec {
  double thumb = 0;       // m, signed distance along the moving arm
  bool has_index = true;  // false: `index: none`
  double index = 0;       // m, signed distance along the fixed arm
  double squeeze = 0;     // m, >= 0, the thumb's advance past the rest angle (SqueezeBy::distance)
  SqueezeBy squeeze_by = SqueezeBy::distance;
  double until = 0;       // N, the actee's force or the effort squeezed until (the others)
  SourceLoc thumb_loc, index_loc, squeeze_loc;
};

enum class FingerSource { carried, grip, fingertips };
enum class PostureSource { carried, named, angles };

struct KeyframeSpec {
  double t = 0;  // s
  SourceLoc loc, t_loc;
  bool has_hand = false;
  PoseSpec hand;  // world
  FingerSource fingers = FingerSource::carried;
  GripSpec grip;
  FingerPoints fingertip = finger_origins();  // m, hand frame (fingertips)
  PostureSource posture = PostureSource::carried;
  std::string posture_name;
  JointAngles joint{};  // rad (angles)
  SourceLoc posture_loc;
  std::array<std::array<SourceLoc, kJoints>, kFingers> joint_loc{};
  std::string actee;         // `actee:` the session's actee taken from this keyframe on ("" none)
  SourceLoc actee_loc;
  int actee_index = -1;      // its index in the session's `actees:` (set by the session)
};

struct ScriptSpec {
  SourceLoc loc;
  std::vector<KeyframeSpec> keyframes;
};

// The longest script (s): a session longer than this is a mistake.
inline constexpr double kMaxScriptDuration = 600;

// Reads a `script:` sequence of keyframes. Throws DataError at the value
// that is wrong (an unknown key, a missing first-keyframe key, a time not
// after the one before, a negative squeeze, ...).
ScriptSpec read_script(const Node& sequence);
const MapSchema& keyframe_schema();        // the keys of one keyframe
const MapSchema& first_keyframe_schema();  // the same, hand, posture and grip or fingertips required

// ------------------------------------------------------------ compiled

struct Keyframe {
  double t = 0;                                                  // s
  Eigen::Vector3d hand_position = Eigen::Vector3d::Zero();       // m, world
  Eigen::Quaterniond hand_rotation = Eigen::Quaterniond::Identity();  // world from hand, unit
  FingerPoints fingertip = finger_origins();             // m, hand frame
  JointAngles joint{};                                           // rad

  // When the fingers come from a grip: the thumb is the point thumb_rest
  // of the moving arm's frame turned to thumb_angle, in the tool placed at
  // object_in_hand. Between two grip keyframes with the same tool pose and
  // the same thumb point the thumb turns about the pivot (thumb_angle is
  // interpolated) instead of cutting the chord, so that a long squeeze keeps
  // it on the arm's face.
  bool grip = false;
  bool grasps = false;  // the grip holds the tool: a finger on the fixed arm, in a grasp posture
  Eigen::Isometry3d object_in_hand = Eigen::Isometry3d::Identity();  // the tool in the hand frame
  Eigen::Vector3d thumb_rest = Eigen::Vector3d::Zero();  // m, moving arm frame
  double thumb_angle = 0;                                // rad, about the pivot (+z)
};

// The thumb of a grip keyframe in the hand frame: object_in_hand * Rz(angle) * thumb_rest.
Eigen::Vector3d grip_thumb(const Keyframe& k, double angle_rad);

struct Script {
  std::vector<Keyframe> keyframes;  // t strictly increasing, at least one
  double duration() const { return keyframes.empty() ? 0.0 : keyframes.back().t; }  // s
};

// Load-time check of a compiled script (session.cpp; reach.h): every keyframe's
// fingertips within the fingers' reach of its hand pose; a grip's thumb
// taken where the arm can follow it (its angle within the arm's limits:
// squeezing past them is the hand impedance's force, not a place).
// Throws DataError at the keyframe's hand position (script_node: the
// session's `script:` sequence) with the finger and the distance short.
// Does nothing when the model has no reach.
void check_script_reach(const Node& script_node, const Script& script, const Model& m);

// Resolves grips against the model (which must have its agent) and
// posture names against the model's grasp taxonomy. Throws DataError: a
// grip distance off its arm, an unknown posture name (with "did you
// mean"), a joint angle outside the agent's range.
// `actee_models`: a session's actees, one model each (the same tool and
// hand), indexed by KeyframeSpec::actee_index: a squeeze until an actee's
// force is computed with the actee on the tool then.
Script compile_script(const ScriptSpec& spec, const Model& model, std::span<const Model> actee_models = {});

// The posture that stands for grasp type `type` of the model's taxonomy:
// each joint the type constrains at the middle of the type's range within
// the agent's, each free joint at the middle of the agent's range. False
// when a range of the type lies outside the agent's (`why` says which).
bool grasp_posture(const Model& model, int type, JointAngles* out, std::string* why);

// The outer face of an arm at signed distance r along it: the y of the
// face in the arm's frame and the z of the middle of the part there.
// False when no part of that arm covers r.
bool arm_outer_face(const Model& model, Arm arm, double r, double* face_y, double* mid_z);

// Where a grip puts the thumb and the index: the thumb's point on the
// moving arm at rest (moving arm frame) and the angle it is turned to, the
// index in the object frame (only if the grip has one). Throws DataError at
// the grip's values.
void grip_points(const Model& model, const GripSpec& grip, Eigen::Vector3d* thumb_rest, double* thumb_angle,
                 Eigen::Vector3d* index);

}  // namespace afford
