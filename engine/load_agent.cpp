// agents/*.yaml -> AgentSpec.
#include "load.h"

namespace afford {

const std::array<const char*, kFingers> kFingerNames = {"thumb", "index", "middle", "ring", "little"};
const std::array<const char*, kJoints> kJointNames = {"distal", "proximal", "metacarpal"};

namespace {

const MapSchema& finger_schema() {
  using namespace schema;
  static const MapSchema kFinger = [] {
    MapSchema m{"a finger: its tip and the ranges of its joints",
                {required_key("tip_radius", quantity(dim::length), "the radius of the fingertip")}};
    for (const char* joint : kJointNames) {
      m.keys.push_back(required_key(joint, sequence(quantity(dim::angle), 2, 2),
                                    std::string("the range [min, max] of the ") + joint + " joint"));
    }
    return m;
  }();
  return kFinger;
}

const MapSchema& fingers_schema() {
  using namespace schema;
  static const MapSchema kFingers = [] {
    MapSchema m{"every finger of the hand"};
    for (const char* finger : kFingerNames) {
      m.keys.push_back(required_key(finger, mapping(finger_schema()), std::string("the ") + finger));
    }
    return m;
  }();
  return kFingers;
}

FingerSpec read_finger(const Node& node, const std::string& name) {
  MapReader m(node, "the " + name, finger_schema());
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

const MapSchema& agent_schema() {
  using namespace schema;
  static const MapSchema kAgent{
      "an agent file: a hand (agents/README.md)",
      {required_key("agent", name(), "the agent's name"),
       required_key("description", text(), "what it is, in a sentence"),
       required_key("force_gain", quantity(dim::stiffness),
                    "f_a of eq. 3: the hand's stiffness between the tracked thumb and the arm"),
       required_key("max_force", quantity(dim::force), "the largest effort force the hand can exert at the emphasis"),
       optional_key("damping", quantity(dim::damping),
                    "the hand's damping, in parallel with force_gain (default none)"),
       required_key("fingers", mapping(fingers_schema()), "every finger's tip and joint ranges")}};
  return kAgent;
}

AgentSpec read_agent(const Node& root) {
  MapReader m(root, "an agent file", agent_schema());
  AgentSpec a;
  a.loc = root.loc();
  a.file = root.loc().file;
  a.name = read_name(m.required("agent"));
  a.description = read_string(m.required("description"));
  a.force_gain = read_positive(m.required("force_gain"), dim::stiffness);
  a.max_force = read_positive(m.required("max_force"), dim::force);
  if (std::optional<Node> damping = m.optional("damping")) a.damping = read_non_negative(*damping, dim::damping);
  MapReader fingers(m.required("fingers"), "the fingers", fingers_schema());
  for (int i = 0; i < kFingers; ++i) {
    a.fingers[static_cast<size_t>(i)] = read_finger(fingers.required(kFingerNames[i]), kFingerNames[i]);
  }
  return a;
}

AgentSpec load_agent(const std::string& path) { return read_agent(load_yaml_file(path)); }

}  // namespace afford
