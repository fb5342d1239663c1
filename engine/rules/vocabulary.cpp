#include "vocabulary.h"

#include "lever.h"

namespace afford {
namespace {

using E = Entity;

double flag(bool b) { return b ? 1.0 : 0.0; }

double moved(const Eigen::Vector3d& now, const Eigen::Vector3d& anchor, bool picked_up) {
  return picked_up ? (now - anchor).norm() : 0.0;
}

}  // namespace

const std::vector<Signal>& signal_registry() {
  static const std::vector<Signal> kSignals = {
      {"time", {}, false, false, dim::time, "time since the session started",
       [](const Model&, const State& s) { return s.t; }},
      {"grasping", {E::agent, E::object}, false, true, dim::none,
       "the agent grasps the tool: the thumb on the moving arm, a finger on the fixed arm, and a posture "
       "of the grasp taxonomy (Sec. 4.3.1)",
       [](const Model&, const State& s) { return flag(s.grasped); }},
      {"pushing", {E::agent, E::object}, false, true, dim::none,
       "the agent grasps the tool and pushes it closed: the thumb advances along the rotation direction, or "
       "presses on past a stopped arm (F_ag > F_agr, Sec. 4.3.1)",
       [](const Model&, const State& s) { return flag(s.grasped && (s.thumb_speed > 0 || s.effort_excess > 0)); }},
      {"touching", {E::agent, E::object}, true, true, dim::none, "any fingertip touches the tool",
       [](const Model&, const State& s) { return flag(s.agent_object.count > 0); }},
      {"touching", {E::object, E::actee}, true, true, dim::none, "the tool touches the actee",
       [](const Model&, const State& s) { return flag(s.object_actee.count > 0); }},
      {"touching", {E::agent, E::actee}, true, true, dim::none, "any fingertip touches the actee",
       [](const Model&, const State& s) { return flag(s.agent_actee.count > 0); }},
      {"gripping", {E::object, E::actee}, true, true, dim::none,
       "both arms of the tool touch the actee: a jaw on each side",
       [](const Model&, const State& s) { return flag(s.actee_arms == 3); }},
      {"contacts", {E::agent, E::object}, true, false, dim::none,
       "contact points between fingertips and the tool's parts (one per touching pair)",
       [](const Model&, const State& s) { return static_cast<double>(s.agent_object.count); }},
      {"contacts", {E::object, E::actee}, true, false, dim::none,
       "contact points between the tool's parts and the actee (one per touching part)",
       [](const Model&, const State& s) { return static_cast<double>(s.object_actee.count); }},
      {"contacts", {E::agent, E::actee}, true, false, dim::none, "fingertips touching the actee",
       [](const Model&, const State& s) { return static_cast<double>(s.agent_actee.count); }},
      {"force", {E::agent, E::object}, false, false, dim::force,
       "F_ag: the agent's force at the emphasis point, along the rotation direction",
       [](const Model&, const State& s) { return s.effort_force; }},
      {"force", {E::object, E::actee}, false, false, dim::force, "F_acr: the force between the jaws and the actee",
       [](const Model&, const State& s) { return s.actee_force; }},
      {"load", {E::actee}, false, false, dim::force,
       "the jaws' force along the actee's force direction A_d: what its limit is compared with",
       [](const Model&, const State& s) { return s.actee_load; }},
      {"peak_load", {E::actee}, false, false, dim::force, "the largest load so far",
       [](const Model&, const State& s) { return s.peak_actee_load; }},
      {"limit", {E::actee}, false, false, dim::force, "A_pv: the actee's force limit",
       [](const Model& m, const State&) { return m.actee_limit; }},
      {"compression", {E::actee}, false, false, dim::length, "how far the jaws have pressed into the actee",
       [](const Model&, const State& s) { return s.actee_compression; }},
      {"broken", {E::actee}, false, true, dim::none, "the actee has broken",
       [](const Model&, const State& s) { return flag(s.condition == ActeeCondition::broken); }},
      {"squeezed", {E::actee}, false, true, dim::none, "the jaws press on the actee (it is not broken)",
       [](const Model&, const State& s) { return flag(s.condition == ActeeCondition::squeezed); }},
      {"intact", {E::actee}, false, true, dim::none, "the actee is neither squeezed nor broken",
       [](const Model&, const State& s) { return flag(s.condition == ActeeCondition::intact); }},
      {"held", {E::actee}, false, true, dim::none,
       "the jaws grip the actee and their friction carries its weight (grip_margin >= 0), so it moves with them",
       [](const Model&, const State& s) { return flag(s.held); }},
      {"grip_margin", {E::actee}, false, false, dim::force,
       "2 * mu * F_acr - m * g: how much more weight the jaws' friction could carry than the actee's",
       [](const Model&, const State& s) { return s.grip_margin; }},
      {"between_jaws", {E::actee}, false, true, dim::none, "the actee sits where the jaws can close on it",
       [](const Model&, const State& s) { return flag(s.between_jaws); }},
      {"angle", {E::object}, false, false, dim::angle, "the lever's opening angle",
       [](const Model&, const State& s) { return s.theta; }},
      {"angular_speed", {E::object}, false, false, dim::angular_speed, "d angle / dt (closing is negative)",
       [](const Model&, const State& s) { return s.omega; }},
      {"at_limit", {E::object}, false, true, dim::none, "the lever rests on theta_min or theta_max",
       [](const Model&, const State& s) { return flag(s.at_limit); }},
      {"blocked", {E::object}, false, true, dim::none, "the actee stops the closing arm",
       [](const Model&, const State& s) { return flag(s.blocked); }},
      {"advantage", {E::object}, false, false, dim::none,
       "mechanical advantage as the effort and load sit now: |D_ag| / |D_ac| (0 without a load)",
       [](const Model&, const State& s) {
         return s.effort_distance != 0 && s.load_distance != 0
                    ? mechanical_advantage(s.effort_distance, s.load_distance)
                    : 0.0;
       }},
      {"thumb_speed", {E::agent}, false, false, dim::speed,
       "v of eq. 2: the thumb's speed along the rotation direction, closing positive",
       [](const Model&, const State& s) { return s.thumb_speed; }},
      {"speed", {E::agent}, false, false, dim::speed, "the hand's speed",
       [](const Model&, const State& s) { return s.hand_speed; }},
      {"speed", {E::object}, false, false, dim::speed, "the tool's speed",
       [](const Model&, const State& s) { return s.object_speed; }},
      {"speed", {E::actee}, false, false, dim::speed, "the actee's speed",
       [](const Model&, const State& s) { return s.actee_speed; }},
      {"moved", {E::object}, false, false, dim::length,
       "how far the tool has moved since the agent grasped it (0 when not grasped)",
       [](const Model&, const State& s) { return moved(s.object_pose.translation(), s.object_anchor, s.grasped); }},
      {"moved", {E::actee}, false, false, dim::length,
       "how far the actee has moved since it was last picked up by the jaws (0 when not held)",
       [](const Model&, const State& s) { return moved(s.actee_pose.translation(), s.actee_anchor, s.held); }},
  };
  return kSignals;
}

bool parse_entity(const std::string& text, Entity* out) {
  if (text == "agent") *out = Entity::agent;
  else if (text == "object") *out = Entity::object;
  else if (text == "actee") *out = Entity::actee;
  else return false;
  return true;
}

const char* entity_name(Entity e) {
  switch (e) {
    case Entity::agent: return "agent";
    case Entity::object: return "object";
    case Entity::actee: return "actee";
  }
  return "?";
}

const Signal* find_signal(const std::string& name, const std::vector<Entity>& args) {
  for (const Signal& s : signal_registry()) {
    if (name != s.name || args.size() != s.args.size()) continue;
    if (args == s.args) return &s;
    if (s.symmetric && args.size() == 2 && args[0] == s.args[1] && args[1] == s.args[0]) return &s;
  }
  return nullptr;
}

const Signal* explaining_signal(const Signal& condition) {
  if (std::string(condition.name) == "held") return find_signal("grip_margin", condition.args);
  return nullptr;
}

std::vector<std::string> signal_names() {
  std::vector<std::string> names;
  for (const Signal& s : signal_registry()) {
    bool seen = false;
    for (const std::string& n : names) seen = seen || n == s.name;
    if (!seen) names.emplace_back(s.name);
  }
  return names;
}

std::string signature(const Signal& s) {
  if (s.args.empty()) return s.name;
  std::string out = std::string(s.name) + "(";
  for (size_t i = 0; i < s.args.size(); ++i) out += (i ? ", " : "") + std::string(entity_name(s.args[i]));
  return out + ")";
}

}  // namespace afford
