// Loading user files: YAML -> validated Spec. Every function throws a
// DataError naming file:line:col on the first mistake it finds.
#pragma once

#include <string>

#include "spec.h"
#include "yaml_reader.h"

namespace afford {

ObjectSpec load_object(const std::string& path);
ActeeSpec load_actee(const std::string& path);
AgentSpec load_agent(const std::string& path);

// The same from an already parsed document (tests, inline session files).
ObjectSpec read_object(const Node& root);
ActeeSpec read_actee(const Node& root);
AgentSpec read_agent(const Node& root);

// Pieces shared by the loaders.
ShapeSpec read_shape(const Node& node);
PoseSpec read_pose(MapReader& map);     // keys position (required), rotation (optional)
RangeSpec read_range(const Node& node, const std::string& what);  // {from, to}
Eigen::Vector3d read_direction(const Node& node);  // three numbers, made unit
// `{coefficient: mu, source: text}`: a coefficient of static friction above
// 0 and at most 3, and where it was published (actees, and tool parts).
double read_friction(const Node& node, std::string* source);
// The `effects:` mapping of a file of kind `home` (load_effects.cpp).
std::vector<EffectSpec> read_effects(const Node& node, EffectHome home);

// The keys of each mapping (schema.h): the loaders read with them and
// json_schema.cpp writes them out.
const MapSchema& object_schema();
const MapSchema& actee_schema();
const MapSchema& agent_schema();
const MapSchema& shape_schema();
const MapSchema& range_schema();
const MapSchema& friction_schema();
std::vector<KeySchema> pose_keys(const std::string& what);  // position, rotation
const MapSchema& effects_schema(EffectHome home);

// Which kind a file is, from its first key (object, actee, agent, ...).
std::string file_kind(const Node& root);

}  // namespace afford
