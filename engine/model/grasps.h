// The grasp taxonomy (paper Sec. 4.2.3, Fig. 7; Cutkosky 1989): grasp types
// as ranges of the fingers' joint angles (Fig. 8), read from
// rules/grasps.yaml (schema in rules/README.md). A posture is classified as
// the first type, in file order, whose every listed range contains it.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "errors.h"
#include "spec.h"

namespace afford {

class Node;
struct MapSchema;
struct Model;

enum class GraspKind { power, precision };
const char* grasp_kind_name(GraspKind k);  // "power", "precision"

struct JointRange {
  double min = 0;  // rad, min < max
  double max = 0;  // rad
};

struct GraspTypeSpec {
  std::string name;
  GraspKind kind = GraspKind::power;
  std::string description;
  double max_force = 0;  // N, > 0: the largest effort force the hand exerts in this grasp
  // Per finger (thumb, index, middle, ring, little) and joint (distal,
  // proximal, metacarpal), flexion positive as in agents/README.md;
  // nullopt: the joint is free (any angle).
  std::array<std::array<std::optional<JointRange>, kJoints>, kFingers> range{};
  SourceLoc loc;  // the type's mapping
};

// Loads a grasp taxonomy file; throws DataError naming file:line:col on the
// first mistake (unknown keys, duplicate names, min >= max, wrong units, ...).
std::vector<GraspTypeSpec> load_grasps(const std::string& path);
std::vector<GraspTypeSpec> read_grasps(const Node& root);
const MapSchema& grasps_schema();  // the keys of a grasps file

// Compiler pass: the taxonomy into the model's flat per-type arrays.
void compile_grasps(const std::vector<GraspTypeSpec>& grasps, Model& m);

// The index of the first grasp type (file order) whose every listed range
// contains the posture (rad, [finger][joint]), or -1 when none does or the
// model has no taxonomy. Allocates nothing.
int classify_grasp(const Model& m, const std::array<std::array<double, kJoints>, kFingers>& joints);

// The largest effort force (N) a hand in grasp type `type` (-1: none) can
// push with: the agent's max_force, capped by the type's.
double grasp_force_cap(const Model& m, int type);

}  // namespace afford
