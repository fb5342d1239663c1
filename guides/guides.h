// The four guides of the paper (Sec. 4.4, Fig. 16) as data: which guides
// exist, what each shows and how it is computed is read from
// rules/guides.yaml (schema in rules/README.md); everything is computed from
// the Model (and, for the actee guide, from actee files). Nothing here knows
// a particular tool.
//
// The result, `Guides`, is plain geometry a renderer can draw without knowing
// what a guide means (rectangles, triangle meshes, coloured segments, text
// labels), plus the textual facts `afford guide` prints. All lengths in m,
// colours in 0..1.
//
// Frames. Every primitive carries the arm whose frame it is written in:
// Arm::fixed means the object frame (spec.h: fulcrum at the origin, pivot
// axis +z, fixed arm along +x); Arm::moving means the moving arm's frame,
// which sits in the object frame at moving_arm_pose(theta) (model.h), so a
// guide on the moving arm follows the arm as it turns. posed_guides() does
// that product for one angle and returns everything in the object frame.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "derive.h"
#include "errors.h"
#include "spec.h"

namespace afford {

class Node;
struct MapSchema;
struct Model;

// ---------------------------------------------------------------- the guide file

enum class GuideKind {
  symmetry_plane,     // stable orientation: the plane of symmetry, the functional pose
  interaction_space,  // the actee guide: L_is, and which actees fit in it
  emphasis,           // the faces where the agent can push (L_cp, P_emphasis)
  advantage,          // amplify or decline the agent's force along the arms
};
const char* guide_kind_name(GuideKind k);  // "symmetry_plane", ...

struct GuideColour {
  double r = 0, g = 0, b = 0;  // 0..1
  double a = 1;                // 0..1, opacity (the guide's alpha)
};

// Which faces of an arm the emphasis guide marks, by the direction of the
// push: `closing` the face the agent presses to close the jaws (the paper's
// emphasis), `opening` the face it presses to open them.
enum class GuideFaces { closing, opening, both };

// Where the load sits for the advantage map: the near end, the middle or
// the far end of the application region.
enum class GuideLoadAt { from, middle, to };

// One guide of rules/guides.yaml. The kind decides which of the
// kind-specific fields are read; the others keep their defaults.
struct GuideSpec {
  std::string name;         // unique in the file
  GuideKind kind = GuideKind::symmetry_plane;
  std::string description;  // one line, shown to the agent
  GuideColour colour;       // colour and alpha of the guide's main geometry
  double lift = 0;          // m, >= 0: drawn this far off the surface it marks
  // symmetry_plane
  double margin = 0;        // m, >= 0: the plane's rectangle exceeds the object by this
  Eigen::Vector3d gravity = -Eigen::Vector3d::UnitZ();  // unit, world frame
  // interaction_space
  GuideColour fit_colour, misfit_colour;  // labels of actees that fit / do not
  // emphasis
  GuideFaces faces = GuideFaces::closing;
  // advantage
  double step = 0;          // m, > 0: segment length along the arm
  GuideLoadAt load_at = GuideLoadAt::middle;
  double saturate = 2;      // > 1: MA at which the ramp reaches `amplify` (1/saturate: `decline`)
  GuideColour decline, neutral, amplify;  // the colour ramp: MA < 1, = 1, > 1
  SourceLoc loc;            // the guide's mapping
};

// Loads a guide file; throws DataError naming file:line:col on the first
// mistake (unknown keys with "did you mean", a wrong kind, a colour outside
// 0..1, duplicate names, ...).
std::vector<GuideSpec> load_guides(const std::string& path);
std::vector<GuideSpec> read_guides(const Node& root);
const MapSchema& guides_schema();  // the keys of a guides file

// ---------------------------------------------------------------- computed geometry

// A flat rectangle: centre + s*u*half_u + t*v*half_v for s, t in [-1, 1].
struct GuideRect {
  int guide = 0;           // index into Guides::guides
  Arm frame = Arm::fixed;  // see "Frames" above
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // m
  Eigen::Vector3d u = Eigen::Vector3d::UnitX();      // unit, in the plane
  Eigen::Vector3d v = Eigen::Vector3d::UnitY();      // unit, in the plane, orthogonal to u
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // unit, u x v (the side it faces)
  double half_u = 0, half_v = 0;                     // m
  GuideColour colour;
};

// A closed triangle mesh (the interaction space's prism). Triangles wind
// counter-clockwise seen from outside.
struct GuideMesh {
  int guide = 0;
  Arm frame = Arm::fixed;
  std::vector<Eigen::Vector3d> vertices;    // m
  std::vector<std::array<int, 3>> triangles;  // indices into vertices
  GuideColour colour;
};

// A straight segment with its own colour (the advantage map: one per step
// along an arm; a polyline is consecutive segments sharing ends).
struct GuideSegment {
  int guide = 0;
  Arm frame = Arm::fixed;
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();  // m
  GuideColour colour;
  double value = 0;     // what the colour encodes (advantage: MA at the middle, force at the load per unit effort)
  double distance = 0;  // m, signed distance along the arm of the segment's middle (advantage); 0 otherwise
};

// Text anchored at a point.
struct GuideLabel {
  int guide = 0;
  Arm frame = Arm::fixed;
  std::string text;
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();  // m
  GuideColour colour;
};

// The facts behind the geometry, for text and JSON.
struct GuideFacts {
  // stable orientation
  LeverPattern pattern = LeverPattern::type2;
  Eigen::Vector3d symmetry_point = Eigen::Vector3d::Zero();  // m, object frame
  Eigen::Vector3d symmetry_normal = Eigen::Vector3d::UnitZ();  // unit, object frame
  Eigen::Isometry3d functional_pose = Eigen::Isometry3d::Identity();  // object frame in the world
  double plane_to_gravity = 0;  // rad, angle between the symmetry plane at the functional pose and gravity (0: parallel)
  // The tool turned about its length (its x axis) from the functional pose
  // until the plane is parallel to gravity, the paper's stable orientation
  // (Sec. 4.4): the torques about the pivot at rest (N*m, opening
  // positive) with the moving arm above the fixed one and below it. Where
  // the weight above closes the arm harder than the spring and the
  // pivot's friction hold it open, the tool cannot rest open that way up.
  bool stable_turn_found = false;  // false: no turn about x makes the plane parallel to gravity
  double stable_turn = 0;          // rad, about x, the moving arm above
  double weight_above = 0, weight_below = 0;  // N*m, the moving arm's weight about the pivot at rest
  double spring_at_rest = 0;       // N*m, the spring's preload about the pivot
  double friction_at_rest = 0;     // N*m, the pivot's friction (holds either way)
  // actee guide
  InteractionSpace space;
  std::vector<ActeeFit> actees;  // in the order given (file name order for a folder)
  // emphasis
  double emphasis_from = 0, emphasis_to = 0;  // m, signed, along each arm
  // advantage
  double load_at = 0;             // m, signed: where the load sits for the map
  double ma_min = 0, ma_max = 0;  // mechanical advantage over the emphasis region for that load
  double ma_arm_min = 0, ma_arm_max = 0;  // the same over the sampled arm
};

struct Guides {
  std::string object;              // the object's name
  std::vector<GuideSpec> guides;   // the guides computed, file order; primitives index it
  std::vector<GuideRect> rects;
  std::vector<GuideMesh> meshes;
  std::vector<GuideSegment> segments;
  std::vector<GuideLabel> labels;
  GuideFacts facts;

  // The index of the guide named `name`, or -1.
  int find(const std::string& name) const;
};

// Computes every guide of `specs` for the model (the model's actee and agent
// are not used). `fits` are the actee fits to report and label (fit_actees
// below, or fit_actee() of a model compiled with its actee); may be empty.
Guides compute_guides(const Model& m, const std::vector<GuideSpec>& specs, const std::vector<ActeeFit>& fits = {});

// How each actee fits the object's jaws (derive.h's fit_actee per actee).
std::vector<ActeeFit> fit_actees(const ObjectSpec& object, const std::vector<ActeeSpec>& actees);
// Every *.yaml actee file of a folder, in file name order (none: empty).
std::vector<ActeeSpec> load_actee_folder(const std::string& dir);

// The guides with every primitive moved into one frame: the moving arm's at
// opening angle theta (rad), then everything by `object_in_world` (identity:
// the object frame; a State's object_pose: the world). Every frame becomes
// Arm::fixed. A renderer: posed_guides(g, state.theta, state.object_pose).
Guides posed_guides(const Guides& g, double theta_rad,
                    const Eigen::Isometry3d& object_in_world = Eigen::Isometry3d::Identity());

// The colour of the advantage ramp for a mechanical advantage `ma` (> 0):
// log-linear from `decline` at 1/saturate through `neutral` at 1 to
// `amplify` at saturate, clamped beyond.
GuideColour advantage_colour(const GuideSpec& spec, double ma);

}  // namespace afford
