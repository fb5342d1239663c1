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

// `reach:` per finger: the chain's base and its links (agents/README.md).
const MapSchema& links_schema() {
  using namespace schema;
  static const MapSchema kLinks = [] {
    MapSchema m{"the length of the link each joint turns: to the next joint, the distal one's to the tip's centre"};
    for (const char* joint : kJointNames) {
      m.keys.push_back(required_key(joint, quantity(dim::length), std::string("the link the ") + joint + " joint turns"));
    }
    return m;
  }();
  return kLinks;
}

const MapSchema& finger_reach_schema() {
  using namespace schema;
  static const MapSchema kFinger{
      "a finger's chain: where it starts and how long its links are",
      {required_key("base", vector(dim::length),
                    "where the finger's metacarpal joint sits in the hand frame (origin at the wrist)"),
       required_key("links", mapping(links_schema()), "the length of the link each joint turns")}};
  return kFinger;
}

const MapSchema& reach_schema() {
  using namespace schema;
  static const MapSchema kReach = [] {
    MapSchema m{"every finger's chain, which limits where its tip can be"};
    for (const char* finger : kFingerNames) {
      m.keys.push_back(required_key(finger, mapping(finger_reach_schema()), std::string("the ") + finger));
    }
    return m;
  }();
  return kReach;
}

// No finger's base lies further from the wrist than this, nor is a link longer.
constexpr double kMaxHandSize = 0.5;  // m

void read_finger_reach(const Node& node, const std::string& name, FingerSpec& f) {
  MapReader m(node, "the reach of the " + name, finger_reach_schema());
  const Node base = m.required("base");
  f.base = read_vector(base, dim::length);
  if (!(f.base.norm() <= kMaxHandSize)) {
    base.fail("a base within " + format_quantity(kMaxHandSize, dim::length) + " of the wrist");
  }
  MapReader links(m.required("links"), "the links of the " + name, links_schema());
  for (int j = 0; j < kJoints; ++j) {
    const Node link = links.required(kJointNames[j]);
    f.link[static_cast<size_t>(j)] = read_positive(link, dim::length);
    if (f.link[static_cast<size_t>(j)] > kMaxHandSize) {
      link.fail("a link of at most " + format_quantity(kMaxHandSize, dim::length));
    }
  }
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
       required_key("fingers", mapping(fingers_schema()), "every finger's tip and joint ranges"),
       optional_key("reach", mapping(reach_schema()),
                    "every finger's chain (base and links), which limits where its tip can be; absent: not limited")}};
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
  if (std::optional<Node> reach = m.optional("reach")) {
    a.has_reach = true;
    MapReader chains(*reach, "the reach", reach_schema());
    for (int i = 0; i < kFingers; ++i) {
      read_finger_reach(chains.required(kFingerNames[i]), kFingerNames[i], a.fingers[static_cast<size_t>(i)]);
    }
  }
  return a;
}

AgentSpec load_agent(const std::string& path) { return read_agent(load_yaml_file(path)); }

}  // namespace afford
