#include "tools.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "jaw_contact.h"
#include "load.h"

namespace fs = std::filesystem;

namespace gapcheck {
namespace {

// A heavy lever press: the nutcracker's pattern, longer and heavier, with
// a stiffer spring and a tighter pivot.
constexpr const char* kPress = R"(# A heavy lever press, derived from objects/nutcracker.yaml by changing
# its numbers (the withheld check's new geometry): 300 mm arms, a stiff
# return spring, a tight pivot.
object: press
description: Heavy lever press, 300 mm, jaws near the hinge, stiff return spring.
mass: 600 g
centre_of_gravity: [140 mm, 25 mm, 0 mm]
functional_pose:
  position: [0 mm, 0 mm, 100 mm]
  rotation: [0 deg, 0 deg, 0 deg]
symmetry_plane:
  point: [0 mm, 0 mm, 0 mm]
  normal: [0, 0, 1]
lever:
  pattern: type2
  arm: {from: 0 mm, to: 300 mm}
  theta_min: 0 deg
  theta_max: 28 deg
  rest: 28 deg
spring:
  constant: 6000 N/m
  position: 15 mm
  preload: 4 N
emphasis: {from: 200 mm, to: 290 mm}
application: {from: 30 mm, to: 140 mm}
parts:
  - name: fixed_arm
    arm: fixed
    shape: {box: {size: [300 mm, 16 mm, 20 mm]}}
    position: [150 mm, -8 mm, 0 mm]
  - name: moving_arm
    arm: moving
    shape: {box: {size: [300 mm, 16 mm, 20 mm]}}
    position: [150 mm, 8 mm, 0 mm]
effects:
  pivot_friction: {torque: 0.03 N*m}
)";

// Long-handled snips: the pliers' type 1 pattern with longer handles,
// longer jaws, a stiffer opening spring.
constexpr const char* kSnips = R"(# Long-handled snips, derived from objects/pliers.yaml by changing its
# numbers (the withheld check's new geometry): 180 mm handles, 48 mm jaws,
# a stiffer opening spring.
object: snips
description: Long-handled snips, 228 mm, riveted joint, opening spring.
mass: 320 g
centre_of_gravity: [-35 mm, -9 mm, 0 mm]
functional_pose:
  position: [0 mm, 0 mm, 100 mm]
  rotation: [0 deg, 0 deg, 0 deg]
symmetry_plane:
  point: [0 mm, 0 mm, 0 mm]
  normal: [0, 0, 1]
lever:
  pattern: type1-power
  arm: {from: -180 mm, to: 48 mm}
  theta_min: 0 deg
  theta_max: 30 deg
  rest: 30 deg
spring:
  constant: 300 N/m
  position: -40 mm
  preload: 3 N
emphasis: {from: -170 mm, to: -90 mm}
application: {from: 5 mm, to: 45 mm}
parts:
  - name: fixed_jaw
    arm: fixed
    shape: {box: {size: [46 mm, 10 mm, 11 mm]}}
    position: [25 mm, -5 mm, 0 mm]
  - name: fixed_handle
    arm: fixed
    shape: {box: {size: [163 mm, 14 mm, 12 mm]}}
    position: [-96.5 mm, 7 mm, 0 mm]
  - name: moving_jaw
    arm: moving
    shape: {box: {size: [46 mm, 10 mm, 11 mm]}}
    position: [25 mm, 5 mm, 0 mm]
  - name: moving_handle
    arm: moving
    shape: {box: {size: [163 mm, 14 mm, 12 mm]}}
    position: [-96.5 mm, -7 mm, 0 mm]
effects:
  pivot_friction: {torque: 0.03 N*m}
)";

}  // namespace

const std::vector<std::string>& tool_names() {
  static const std::vector<std::string> names = {"nutcracker", "tongs", "pliers", "press", "snips"};
  return names;
}

namespace {

// The rig holds a shipped tool laid flat with its own weight off, as the
// files did before the tongs and the pliers stood on edge in their
// functional pose: the realities give the arm a weight only where a case's
// truth does (a point mass along the arm), so the nominal's computed
// weight, which follows the parts' centroids, stays out of the check. A
// file already flat is copied as it is.
std::string laid_flat(const fs::path& shipped) {
  std::ifstream in(shipped);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto replace = [&](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    if (at == std::string::npos) return;
    text.replace(at, from.size(), to);
  };
  replace("  rotation: [90 deg, 0 deg, 0 deg]\n", "  rotation: [0 deg, 0 deg, 0 deg]\n");
  replace("  gravity: {extra_torque: 0 N*m}", "");
  return text;
}

}  // namespace

fs::path tool_file(const fs::path& source, const fs::path& dir, const std::string& stem, const std::string& tool) {
  const fs::path file = fs::absolute(dir / (stem + ".yaml"));
  if (tool == "press" || tool == "snips") {
    std::ofstream(file) << (tool == "press" ? kPress : kSnips);
  } else {
    std::ofstream(file) << laid_flat(source / "objects" / (tool + ".yaml"));
    // A shipped file written otherwise than laid_flat() expects would slip
    // its weight into the check unseen: refuse it.
    const afford::ObjectSpec o = afford::load_object(file.string());
    for (const afford::EffectSpec& e : o.effects) {
      if (e.kind == afford::EffectKind::gravity && e.enabled) {
        throw std::runtime_error(tool + ": the rig copy keeps the shipped file's gravity effect");
      }
    }
    if (!o.functional_pose.rotation.isIdentity(1e-12)) {
      throw std::runtime_error(tool + ": the rig copy is not laid flat");
    }
  }
  return file;
}

Tool load_tool(const fs::path& file) {
  const afford::ObjectSpec o = afford::load_object(file.string());
  Tool t;
  t.name = o.name;
  t.file = file.string();
  t.theta_min = o.lever.theta_min;
  t.theta_max = o.lever.theta_max;
  t.rest = o.lever.theta_rest;
  t.spring_position = std::abs(o.spring.position);
  t.spring_constant = o.spring.constant;
  t.torsion = o.spring.constant * t.spring_position * t.spring_position;
  t.preload_torque = o.spring.preload * t.spring_position;
  for (const afford::EffectSpec& e : o.effects) {
    if (e.kind == afford::EffectKind::pivot_friction && e.enabled) t.friction = e.param[0];
  }
  t.effort_at = std::abs(o.emphasis.middle());
  t.effort_sign = o.emphasis.middle() < 0 ? -1 : 1;
  return t;
}

// Where the jaws close on an actee well below their opening, so that free
// drives have room above it. Smooth shapes only: MuJoCo's box-box collider
// makes four contacts of a face on a plate and two of an edge under a jaw,
// each reporting its own depth (half the plate's travel on the face), so
// the sponge and the ice cube would have one law between plates and
// another in the jaws. The pliers' and the snips' jaws hold none of the
// smooth ones (the smallest nut does not fit).
std::vector<ActeePlace> actee_places(const std::string& tool) {
  if (tool == "nutcracker") return {{"hazelnut", 0.075}, {"pecan", 0.070}};
  if (tool == "tongs") return {{"egg", 0.210}};
  if (tool == "press") return {{"walnut", 0.110}, {"hazelnut", 0.090}};
  return {};
}

Tool with_actee(Tool tool, const fs::path& source, const ActeePlace& place) {
  const fs::path file = fs::absolute(source / "actees" / (place.actee + ".yaml"));
  const afford::ActeeSpec spec = afford::load_actee(file.string());
  const JawContact contact = jaw_contact(tool.file, file.string(), (source / "agents" / "hand.yaml").string(), place.at);
  ToolActee a;
  a.file = file.string();
  a.at = place.at;
  a.contact_angle = contact.angle;
  for (int i = 0; i < 3; ++i) {
    a.touch[i] = contact.touch[i];
    a.into[i] = contact.into[i];
  }
  a.thickness = contact.thickness;
  a.lever = contact.lever;
  a.stiffness = spec.stiffness;
  a.limit = spec.limit;
  a.breaks = spec.breaks;
  tool.actee = a;
  return tool;
}

}  // namespace gapcheck
