// afford describe FILE: what the model derives from an object file (lever
// pattern, mechanical advantage along the arm, interaction space, which
// actees fit, spring force at each limit), from a session file (where the
// jaws touch its actee as placed, what each grip of its script squeezes),
// or from an agent file (each finger's ranges and reach); `--effects`
// lists the optional torque terms. The actees are the shipped ones (data_dir.h) unless
// --actees names a folder.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <tuple>

#include "commands.h"
#include "data_dir.h"
#include "option_checks.h"
#include "quantity_text.h"
#include "derive.h"
#include "effects.h"
#include "lever.h"
#include "load.h"
#include "model.h"
#include "grasps.h"
#include "session.h"
#include "squeeze.h"

namespace afford::cli {
namespace {

void describe_effects() {
  std::cout << "optional effects (key 'effects' of the file named; a measurement file may switch on any):\n";
  for (const EffectManifest& e : effect_registry()) {
    std::cout << "  " << e.name << " (" << home_name(e.home) << " file): " << e.doc << "\n";
    for (const EffectParam& p : e.params) {
      std::cout << "      " << p.key << ": " << p.doc << ", " << (p.min_included ? "from " : "above ")
                << q(p.min, p.dimension) << " to " << q(p.max, p.dimension) << "\n";
    }
    std::cout << "      enabled: true|false (optional, default true)\n";
  }
}

// "pivot_friction: torque 0.01 N*m" for an effect a file switched on.
std::string effect_line(const ModelEffect& e) {
  std::string line = e.name + ":";
  const EffectManifest& manifest = manifest_of(e.kind);
  for (size_t i = 0; i < manifest.params.size(); ++i) {
    line += " " + std::string(manifest.params[i].key) + " " + q(e.param[i], manifest.params[i].dimension);
  }
  return line + (e.enabled ? "" : " (disabled)");
}

void describe_object(const ObjectSpec& o, const std::string& actee_dir) {
  const Model m = compile(o, nullptr, nullptr, ModelOptions{});
  std::cout << "object " << o.name << ": " << o.description << "\n";
  std::cout << "lever: " << pattern_name(o.lever.pattern) << ", arms from " << q(m.arm_from, dim::length)
            << " to " << q(m.arm_to, dim::length) << ", opening " << q(m.theta_min, dim::angle) << " to "
            << q(m.theta_max, dim::angle) << ", rest " << q(m.theta_rest, dim::angle) << "\n";

  std::cout << "mechanical advantage (force at the load per unit effort):\n      effort at";
  constexpr int kLoads = 3, kEfforts = 5;
  for (int j = 0; j < kLoads; ++j) {
    const double a = m.application_from + (m.application_to - m.application_from) * j / (kLoads - 1);
    std::printf("   load %9s", q(a, dim::length).c_str());
  }
  std::cout << "\n";
  for (int i = 0; i < kEfforts; ++i) {
    const double e = m.emphasis_from + (m.emphasis_to - m.emphasis_from) * i / (kEfforts - 1);
    std::printf("  %10s", q(e, dim::length).c_str());
    for (int j = 0; j < kLoads; ++j) {
      const double a = m.application_from + (m.application_to - m.application_from) * j / (kLoads - 1);
      std::printf("   %5.2f %-9s", mechanical_advantage(e, a), pattern_name(pattern_at(e, a)));
    }
    std::cout << "\n";
  }

  const InteractionSpace s = interaction_space(m);
  std::cout << "interaction space: from " << q(s.from, dim::length) << " to " << q(s.to, dim::length)
            << " along the arm, jaw opening at theta_max " << q(s.gap_from, dim::length) << " to "
            << q(s.gap_to, dim::length) << "\n";

  std::cout << "spring: " << q(m.spring_constant, dim::stiffness) << " at " << q(m.spring_position, dim::length)
            << "; force at theta_min " << q(spring_force(m, m.theta_min), dim::force) << ", at rest "
            << q(spring_force(m, m.theta_rest), dim::force) << ", at theta_max "
            << q(spring_force(m, m.theta_max), dim::force) << "\n";
  const double far = std::abs(m.emphasis_to) > std::abs(m.emphasis_from) ? m.emphasis_to : m.emphasis_from;
  std::cout << "effort to close against the spring alone, at " << q(far, dim::length) << ": "
            << q(effort_for_load(m, m.theta_min, far, m.application_from, 0), dim::force) << "\n";
  for (const ModelEffect& e : m.effects) std::cout << "effect " << effect_line(e) << "\n";

  if (actee_dir.empty() || !std::filesystem::is_directory(actee_dir)) return;
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(actee_dir)) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  std::cout << "actees in " << actee_dir << ":\n";
  for (const std::string& file : files) {
    const ActeeSpec a = load_actee(file);
    ModelOptions options;
    options.actee.in_jaws = false;  // fit_actee places it itself
    const Model with = compile(o, &a, nullptr, options);
    const ActeeFit fit = fit_actee(with);
    if (fit.fits) {
      std::printf("  %-12s fits from %s to %s; jaws touch at %s; limit %s needs %s at the handle end\n",
                  a.name.c_str(), q(fit.from, dim::length).c_str(), q(fit.to, dim::length).c_str(),
                  q(fit.contact_angle, dim::angle).c_str(), q(a.limit, dim::force).c_str(),
                  q(fit.effort_to_limit, dim::force).c_str());
    } else {
      std::printf("  %-12s does not fit: %s\n", a.name.c_str(), fit.why.c_str());
    }
  }
}

// The largest effort of a keyframe's hand: the agent's, or its grasp's if less.
double effort_cap(const Model& m, const Keyframe& k, std::string* grasp) {
  const int type = m.grasp_name.empty() ? -1 : classify_grasp(m, k.joint);
  *grasp = type >= 0 ? m.grasp_name[static_cast<size_t>(type)] : "no grasp type";
  return grasp_force_cap(m, type);
}

// A session as placed: where the jaws touch its actee, and what each grip
// of its script squeezes (the numbers a script is written with).
// Where the jaws touch an actee as placed.
void describe_actee(const Model& m, const ForcedLever& lever) {
  if (!m.has_actee) {
    std::cout << "no actee\n";
  } else if (!lever.actee) {
    std::cout << "actee " << m.actee_name << ": not between the jaws as placed\n";
  } else {
    std::cout << "actee " << m.actee_name << " as placed: the jaws touch it at " << q(lever.contact_angle, dim::angle)
              << ", its load's arm " << q(lever.load_distance, dim::length) << ", " << q(lever.thickness, dim::length)
              << " across the jaws; limit " << q(m.actee_limit, dim::force) << (m.actee_breaks ? " (it breaks)" : "")
              << "\n";
  }
}

void describe_session(const CompiledSession& s) {
  std::cout << "session " << s.name << ": " << s.description << "\n";
  const Model& hand = s.model;  // the tool and the hand are every actee's model's
  std::cout << "object " << hand.object_name << ", rest " << q(hand.theta_rest, dim::angle) << ", hand "
            << hand.agent_name << " (force_gain " << q(hand.force_gain, dim::stiffness) << ", at most "
            << q(hand.max_force, dim::force) << ")\n";
  // Each actee's model and lever: the one of `actee:`, or each of `actees:`.
  std::vector<const Model*> models;
  if (s.actee_models.empty()) models.push_back(&s.model);
  for (const Model& m : s.actee_models) models.push_back(&m);
  std::vector<ForcedLever> levers;
  for (size_t i = 0; i < models.size(); ++i) {
    levers.push_back(lever_at_start(*models[i]));
    if (!s.actee_names.empty()) std::cout << "'" << s.actee_names[i] << "': ";
    describe_actee(*models[i], levers.back());
  }
  std::cout << "grips of the script (in the lever's static balance; engine/model/squeeze.h):\n";
  // Which actee is on the tool at a keyframe: the last one taken by then.
  size_t in_play = s.first_actee;
  size_t next_change = 0;
  // Each thumb distance, cap and actee once: where the jaws touch, and the limit.
  std::vector<std::tuple<double, double, size_t>> told;  // (thumb m, cap N, actee)
  for (const Keyframe& k : s.script.keyframes) {
    for (; next_change < s.actee_changes.size() && s.actee_changes[next_change].t <= k.t; ++next_change) {
      in_play = s.actee_changes[next_change].actee;
    }
    if (!k.grip) continue;
    const Model& m = *models[in_play];
    const ForcedLever& lever = levers[in_play];
    const double r = k.thumb_rest.x();  // m, the thumb's distance along the moving arm
    const double squeeze = std::abs(r) * (m.theta_rest - k.thumb_angle);
    std::string grasp;
    const double cap = effort_cap(m, k, &grasp);
    const double effort = effort_for_squeeze(m, lever, r, squeeze, cap);
    std::printf("  t %s: squeeze %s at %s, %s: effort %s", q(k.t, dim::time).c_str(), q(squeeze, dim::length).c_str(),
                q(r, dim::length).c_str(), grasp.c_str(), q(effort, dim::force).c_str());
    if (lever.actee) {
      const double force = settle_under_effort(m, lever, r, effort).actee_force;
      const std::string name = s.actee_names.empty() ? std::string("the actee") : "'" + s.actee_names[in_play] + "'";
      if (m.actee_breaks && force > m.actee_limit) {
        std::printf(", %s past its limit (it breaks)", name.c_str());
      } else {
        std::printf(", %s %s", name.c_str(), q(force, dim::force).c_str());
      }
    }
    std::printf("\n");
    const auto key = std::make_tuple(r, cap, in_play);
    if (!lever.actee || std::find(told.begin(), told.end(), key) != told.end()) continue;
    told.push_back(key);
    std::printf("    with the thumb at %s the jaws touch at a squeeze of %s", q(r, dim::length).c_str(),
                q(std::max(0.0, std::abs(r) * (m.theta_rest - lever.contact_angle)), dim::length).c_str());
    double to_limit = 0;
    std::string why;
    if (effort_for_actee_force(m, lever, r, m.actee_limit, cap, &to_limit, &why)) {
      std::printf("; the limit needs a squeeze of %s (effort %s)\n",
                  q(squeeze_for_effort(m, lever, r, to_limit), dim::length).c_str(), q(to_limit, dim::force).c_str());
    } else {
      std::printf("; the limit is out of reach: %s\n", why.c_str());
    }
  }
}

// The hand: its impedance and force, and each finger's joint ranges (Fig.
// 8) and how far its tip reaches from the wrist (reach.h).
void describe_agent(const AgentSpec& a) {
  const Model m = compile_agent_only(a);
  std::cout << "agent " << a.name << ": " << a.description << "\n";
  std::cout << "force_gain " << q(m.force_gain, dim::stiffness) << ", at most " << q(m.max_force, dim::force);
  if (m.hand_damping > 0) std::cout << ", damping " << q(m.hand_damping, dim::damping);
  std::cout << "\n";
  for (size_t f = 0; f < kFingers; ++f) {
    std::cout << "  " << kFingerNames[f] << ": tip radius " << q(m.tip_radius[f], dim::length);
    for (size_t j = 0; j < kJoints; ++j) {
      std::cout << ", " << kJointNames[j] << " " << q(m.joint_min[f][j], dim::angle) << " to "
                << q(m.joint_max[f][j], dim::angle);
    }
    if (m.has_reach) {
      std::cout << "; the tip reaches " << q(m.reach_min[f], dim::length) << " to " << q(m.reach_max[f], dim::length)
                << " from the wrist";
    }
    std::cout << "\n";
  }
  if (!m.has_reach) std::cout << "no reach: the file gives no chains, so the fingertips go wherever they are put\n";
}

struct DescribeOptions {
  std::string file, actee_dir;
  bool effects = false;
};

int describe(const DescribeOptions& o) {
  if (o.effects) {
    describe_effects();
    return 0;
  }
  const std::string& file = o.file;
  std::string actee_dir = o.actee_dir;
  const bool actees_given = !actee_dir.empty();
  if (file.empty()) return usage_error("describe needs a FILE (or --effects)");
  const Node root = load_yaml_file(file);
  const std::string kind = file_kind(root);
  if (kind == "session") {
    describe_session(load_session(file));
    return 0;
  }
  if (kind == "agent") {
    describe_agent(read_agent(root));
    return 0;
  }
  if (kind != "object") {
    return usage_error("describe reads object, session and agent files; " + file + " is a " + kind + " file");
  }
  if (actees_given && !std::filesystem::is_directory(actee_dir)) {
    // Asked for by name: an empty list would hide the typo.
    throw std::runtime_error("--actees " + actee_dir + ": not a readable directory");
  }
  if (!actees_given) {
    actee_dir = shipped_path("actees");  // data_dir.h, wherever the object is
  }
  describe_object(read_object(root), actee_dir);
  return 0;
}

}  // namespace

void add_describe(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "describe",
      "what the model derives from an object file (lever, advantage, interaction space, fits), a session (its "
      "grips) or an agent (its reach)");
  auto o = std::make_shared<DescribeOptions>();
  CLI::Option* file =
      cmd->add_option("FILE", o->file, "an object (objects/*.yaml), session (sessions/*.yaml) or agent (agents/*.yaml) file")
          ->type_name(kFile);
  cmd->add_option("--actees", o->actee_dir, "the folder of actees to fit (default: the shipped actees)")
      ->type_name(kDir);
  cmd->add_flag("--effects", o->effects, "list the optional effects a file can switch on, instead of a FILE")
      ->excludes(file);
  cmd->callback([run, o] { *run = [o] { return describe(*o); }; });
}

}  // namespace afford::cli
