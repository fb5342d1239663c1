// Session files: what to simulate (a tool, an actee, a hand, the function
// models, the grasp taxonomy) and the agent's script, compiled into
// everything a run needs.
//
//   session: paper-tongs           name (first key: the kind of file)
//   description: ...               one line
//   object: ../objects/tongs.yaml  a path, or an object file's content in place
//   actees:                        or instead several, each as `actee:` with an
//     - {file: ..., at: 60 mm, name: first}   optional name (default the file's);
//     - {file: ..., at: 60 mm}     the first is on the tool at the start, a
//                                  keyframe's `actee: NAME` takes another
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
//   script:                        the agent's keyframes (engine/session/script.h)
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
#include "run.h"
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

// When a session with several actees takes another (a keyframe's `actee:`).
struct ActeeChange {
  double t = 0;      // s, the keyframe's time
  size_t actee = 0;  // index into CompiledSession::actee_models
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
  // `actees:`, several actees: each one's model (the tool and the hand the
  // same), its name, and when the script takes it; `model` is the one on the
  // tool at the start. Empty with `actee:` or none.
  std::vector<Model> actee_models;
  std::vector<std::string> actee_names;
  std::vector<ActeeChange> actee_changes;  // in time order
  size_t first_actee = 0;                  // the one on the tool at the start
};

// Runs a compiled session: its model and rules, taking each of several
// actees when its script says (run.h's run_session otherwise).
RunResult run_session(const CompiledSession& session, const RuleSet& rules, SampleSource& source,
                      std::span<Observer* const> observers = {});

CompiledSession load_session(const std::string& path);

// The same from a parsed document (tests): relative paths are resolved
// against the folder of the document's name.
CompiledSession read_session(const Node& root);
const MapSchema& session_schema();  // the keys of a session file

}  // namespace afford
