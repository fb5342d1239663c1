// Session files: what to simulate (a tool, an actee, a hand, the function
// models, the grasp taxonomy) and the agent's script, compiled into
// everything a run needs.
//
//   session: paper-tongs           name (first key: the kind of file)
//   description: ...               one line
//   object: ../objects/tongs.yaml  a path, or an object file's content in place
//   actee:                         optional: a session may have no actee
//     file: ../actees/egg.yaml     a path, or an actee file's content in place
//     at: 212 mm                   resting on the fixed jaw at this signed
//                                  distance from the fulcrum, or instead:
//     position: [x, y, z]          a pose in the world (rotation optional,
//     rotation: [rx, ry, rz]       three angles about x, y, z as elsewhere)
//   agent: ../agents/hand.yaml     a path, or an agent file's content in place
//   rules: ../rules/functions.yaml the function models (a path)
//   grasps: ../rules/grasps.yaml   the grasp taxonomy (a path)
//   timestep: 1 ms                 optional, default 1 ms (the haptic rate)
//   contact_tolerance: 0.5 mm      optional, default 0.5 mm
//   camera:                        optional, for `afford render` (world frame):
//     position: [x, y, z]          the eye
//     target: [x, y, z]            the point looked at
//     up: [0, 0, 1]                optional, default +z
//     fov: 40 deg                  optional, vertical field of view, default 40 deg
//   script:                        the agent's keyframes (engine/script.h)
//     - {t: 0 s, hand: ..., grip: ..., posture: ...}
//
// Paths are relative to the session file's folder. Every mistake is a
// DataError naming file:line:col: in the session file, or in the file it
// names (a file that is missing or unreadable is reported at the key that
// names it).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "model.h"
#include "rules.h"
#include "script.h"
#include "setup_warnings.h"
#include "yaml_reader.h"

namespace afford {

// The view `afford render` uses; without `camera:` it frames the scene itself.
struct SessionCamera {
  bool set = false;                                   // the session gives `camera:`
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m, world: the eye
  Eigen::Vector3d target = Eigen::Vector3d::Zero();    // m, world: looked at
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();       // unit, world
  double fov = 0.6981317007977318;                     // rad, vertical field of view (40 deg)
};

struct CompiledSession {
  std::string file;         // the session file as named
  std::string name;         // `session:`
  std::string description;
  Model model;              // with its agent, and the actee if the session has one
  std::shared_ptr<const RuleSet> rules;
  Script script;
  SessionCamera camera;     // `camera:`, optional
  std::vector<std::string> files;  // every file read, the session first (for --watch)
  std::vector<Warning> warnings;   // what the hand can never do (setup_warnings.h)
};

CompiledSession load_session(const std::string& path);

// The same from a parsed document (tests): relative paths are resolved
// against the folder of the document's name.
CompiledSession read_session(const Node& root);
const MapSchema& session_schema();  // the keys of a session file

}  // namespace afford
