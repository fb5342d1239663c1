// agents/*.yaml -> AgentSpec.
#include "load.h"

namespace afford {

const std::array<const char*, kFingers> kFingerNames = {"thumb", "index", "middle", "ring", "little"};
const std::array<const char*, kJoints> kJointNames = {"distal", "proximal", "metacarpal"};

namespace {

FingerSpec read_finger(const Node& node, const std::string& name) {
  MapReader m(node, "the " + name, {"tip_radius", kJointNames[0], kJointNames[1], kJointNames[2]});
  FingerSpec f;
  f.tip_radius = read_positive(m.required("tip_radius"), dim::length);
  for (int j = 0; j < kJoints; ++j) {
    const Node range = m.required(kJointNames[j]);
    if (!range.is_sequence() || range.size() != 2) range.fail("a pair [min, max] of angles");
    f.joint_min[j] = read_quantity(range[0], dim::angle);
    f.joint_max[j] = read_quantity(range[1], dim::angle);
    if (!(f.joint_max[j] > f.joint_min[j])) range[1].fail("a maximum above the minimum");
  }
  return f;
}

}  // namespace

AgentSpec read_agent(const Node& root) {
  MapReader m(root, "an agent file", {"agent", "description", "force_gain", "max_force", "damping", "fingers"});
  AgentSpec a;
  a.loc = root.loc();
  a.file = root.loc().file;
  a.name = read_name(m.required("agent"));
  a.description = read_string(m.required("description"));
  a.force_gain = read_positive(m.required("force_gain"), dim::stiffness);
  a.max_force = read_positive(m.required("max_force"), dim::force);
  if (std::optional<Node> damping = m.optional("damping")) a.damping = read_non_negative(*damping, dim::damping);
  MapReader fingers(m.required("fingers"), "the fingers", {kFingerNames.begin(), kFingerNames.end()});
  for (int i = 0; i < kFingers; ++i) {
    a.fingers[static_cast<size_t>(i)] = read_finger(fingers.required(kFingerNames[i]), kFingerNames[i]);
  }
  return a;
}

AgentSpec load_agent(const std::string& path) { return read_agent(load_yaml_file(path)); }

}  // namespace afford
