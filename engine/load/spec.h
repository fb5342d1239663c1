// Specs: what the YAML files say, validated, in SI units, with the location
// of every element so that an error found later still names the line.
// A spec is editable and compiled into an immutable Model (model.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "actee_look.h"
#include "effects.h"
#include "errors.h"

namespace afford {

// ---------------------------------------------------------------- shapes

enum class ShapeKind { sphere, box, capsule, cylinder, ellipsoid, convex };

struct ShapeSpec {
  ShapeKind kind = ShapeKind::sphere;
  double radius = 0;                      // m: sphere, capsule, cylinder
  double length = 0;                      // m: capsule, cylinder, along the part's x axis
  Eigen::Vector3d size = Eigen::Vector3d::Zero();   // m: box, full edge lengths
  Eigen::Vector3d radii = Eigen::Vector3d::Zero();  // m: ellipsoid semi-axes
  std::vector<Eigen::Vector3d> vertices;  // m: convex, the hull of these points
  SourceLoc loc;
};

// A rigid placement: x_parent = rotation * x_local + position.
struct PoseSpec {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};

// ---------------------------------------------------------------- acting object
//
// Object frame: the fulcrum is the origin and the pivot axis is +z. The fixed
// arm lies along +x with its inner (gripping) face in the plane y = 0; the
// moving arm is the fixed arm turned by the opening angle theta about +z.
// Positions along an arm are signed distances from the fulcrum along the
// arm's x axis: type 1 levers have handles at negative distances.

enum class LeverPattern {
  type1_power,     // Fig. 2(a): fulcrum between, effort arm longer (pliers)
  type1_distance,  // Fig. 2(b): fulcrum between, effort arm shorter
  type1_balance,   // Fig. 2(c): fulcrum between, arms equal (scissors)
  type2,           // load between fulcrum and effort (nutcracker)
  type3,           // effort between fulcrum and load (tongs)
};
const char* pattern_name(LeverPattern p);  // "type1-power", ...

enum class Arm { fixed = 0, moving = 1 };

struct RangeSpec {
  double from = 0;  // m, signed distance from the fulcrum along the arm
  double to = 0;    // m, from < to
  SourceLoc loc;
  double middle() const { return 0.5 * (from + to); }
};

struct LeverSpec {
  LeverPattern pattern = LeverPattern::type2;
  RangeSpec arm;           // the extent of each arm along its axis
  double theta_min = 0;    // rad, fully closed
  double theta_max = 0;    // rad, fully open
  double theta_rest = 0;   // rad, where the untouched tool sits
  SourceLoc loc, pattern_loc;
};

struct SpringSpec {
  double constant = 0;     // N/m, S_k of eq. 4
  double position = 0;     // m, signed distance S_p of the spring from the fulcrum
  // N, the spring's push at the rest angle: from `preload`, or from
  // `rest_length` as constant * (rest_length - gap at the rest angle). It
  // becomes the spring_preload effect; without it the spring is free at rest.
  double preload = 0;
  SourceLoc loc, preload_loc;
};

// An optional effect, switched on as data (effects.h lists them).
struct EffectSpec {
  std::string name;                // "pivot_friction", ...
  EffectKind kind = EffectKind::pivot_friction;
  bool enabled = true;
  std::array<double, 2> param{};   // SI, in the order of the manifest's parameters
  SourceLoc loc;
};

struct PartSpec {
  std::string name;
  Arm arm = Arm::fixed;
  ShapeSpec shape;
  PoseSpec pose;  // in the arm's frame
  double friction = 0;          // mu of any actee on its surface; 0: the actee's own coefficient
  std::string friction_source;  // where that coefficient was published
  SourceLoc loc;
};

struct PlaneSpec {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // m, object frame
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit
};

// The interaction space L_is as the real shape gives it (the optional key
// `interaction_space`, written by afford model): how far apart the jaws are
// fully open (theta_max) at distances along the fixed arm, measured from the
// fixed jaw's face (y = 0). Without it L_is is the wedge of flat jaw faces
// through the pivot (engine/model/derive.h).
struct InteractionSpaceSpec {
  std::vector<double> distances;  // m, signed, increasing, within the application region; empty: the wedge
  std::vector<double> gaps;       // m, >= 0, the gap at theta_max at each distance
  SourceLoc loc;
};

struct ObjectSpec {
  std::string file;
  std::string name;
  std::string description;
  double mass = 0;                                         // kg
  Eigen::Vector3d centre_of_gravity = Eigen::Vector3d::Zero();  // m, object frame, at rest
  PoseSpec functional_pose;   // the object frame in the world at the start (Fig. 3)
  PlaneSpec symmetry_plane;   // O_sp, object frame
  LeverSpec lever;
  SpringSpec spring;
  RangeSpec emphasis;         // where the agent pushes (P_emphasis, L_cp)
  RangeSpec application;      // where an actee can sit: the interaction space
  InteractionSpaceSpec interaction_space;  // optional: L_is from the shape
  std::vector<PartSpec> parts;
  std::vector<EffectSpec> effects;
  SourceLoc loc;
};

// ---------------------------------------------------------------- actee

struct ActeeSpec {
  std::string file;
  std::string name;
  std::string description;
  ShapeSpec shape;
  double mass = 0;                      // kg
  Eigen::Vector3d force_direction = Eigen::Vector3d::UnitY();  // A_d, unit, actee frame
  double limit = 0;                     // N, A_pv: breaks (or counts as squeezed) above it
  double stiffness = 0;                 // N/m, contact stiffness up to the limit
  bool breaks = true;                   // brittle; false: deforms and never breaks
  double friction = 0;                  // its coefficient of static friction on the jaws (mu, > 0)
  std::string friction_source;          // where the coefficient was published
  std::vector<EffectSpec> effects;      // actee_compliance
  ActeeLook look;                       // how it is drawn (renderer only)
  SourceLoc loc, limit_loc;
};

// ---------------------------------------------------------------- agent

inline constexpr int kFingers = 5;  // thumb, index, middle, ring, little
inline constexpr int kJoints = 3;   // distal, proximal, metacarpal (Fig. 8)

// A point per finger, each at the origin. Eigen's vectors are not zeroed
// by `{}` (their default constructor leaves the memory as it was), so an
// array of them is given its zeros by this.
using FingerPoints = std::array<Eigen::Vector3d, kFingers>;
inline FingerPoints finger_origins() {
  FingerPoints points;
  points.fill(Eigen::Vector3d::Zero());
  return points;
}
extern const std::array<const char*, kFingers> kFingerNames;
extern const std::array<const char*, kJoints> kJointNames;

struct FingerSpec {
  double tip_radius = 0;                   // m
  std::array<double, kJoints> joint_min{};  // rad
  std::array<double, kJoints> joint_max{};  // rad
  // Its chain (agents/README.md, `reach`): where it starts, in the hand
  // frame, and the link each joint turns, [distal, proximal, metacarpal].
  Eigen::Vector3d base = Eigen::Vector3d::Zero();  // m
  std::array<double, kJoints> link{};              // m, > 0 (has_reach)
};

struct AgentSpec {
  std::string file;
  std::string name;
  std::string description;
  double force_gain = 0;  // N/m: f_a of eq. 3, force added per metre the thumb advances
  double max_force = 0;   // N: the largest effort force the hand can exert
  double damping = 0;     // N*s/m: the hand impedance's damping (optional key; 0: none)
  std::array<FingerSpec, kFingers> fingers;
  bool has_reach = false;  // the file gives `reach`: each finger's base and links
  SourceLoc loc;
};

}  // namespace afford
