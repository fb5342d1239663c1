// Test rig: inline tools of every lever pattern (simple boxes whose geometry
// the tests know exactly), and a thumb that pushes along the rotation
// direction L_d the way eq. (1) reads it.
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "load.h"
#include "model.h"
#include "state.h"
#include "test_util.h"

namespace afford::test {

inline constexpr double kThickness = 0.010;  // m, every arm of the inline tools

struct Tool {
  const char* name;
  const char* yaml;
  double effort;  // m, signed distance where the rig's thumb pushes
  double load;    // m, signed distance where the rig places the actee
};

// Parts of a tool whose arms are 10 mm thick boxes: jaws at x > 0, and for
// type 1 levers handles at x < 0 on the other side of the inner face.
inline std::string arms(double from_mm, double to_mm) {
  auto box = [](const char* name, const char* arm, double x0, double x1, double y) {
    return std::string("  - name: ") + name + "\n    arm: " + arm + "\n    shape: {box: {size: [" +
           std::to_string(x1 - x0) + " mm, 10 mm, 16 mm]}}\n    position: [" + std::to_string(0.5 * (x0 + x1)) +
           " mm, " + std::to_string(y) + " mm, 0 mm]\n";
  };
  std::string s = "parts:\n";
  if (to_mm > 0) s += box("fixed_jaw", "fixed", std::max(from_mm, 0.0), to_mm, -5) + box("moving_jaw", "moving", std::max(from_mm, 0.0), to_mm, 5);
  if (from_mm < 0) s += box("fixed_handle", "fixed", from_mm, 0, 5) + box("moving_handle", "moving", from_mm, 0, -5);
  return s;
}

inline std::string tool_yaml(const char* name, const char* pattern, double from_mm, double to_mm,
                             double theta_max_deg, double spring_k, double spring_at_mm, double preload_n,
                             double em_from, double em_to, double ap_from, double ap_to,
                             const std::string& effects = "") {
  char head[1024];
  std::snprintf(head, sizeof head,
                "object: %s\ndescription: test tool\nmass: 100 g\ncentre_of_gravity: [50 mm, 0 mm, 0 mm]\n"
                "functional_pose: {position: [0 mm, 0 mm, 0 mm]}\n"
                "symmetry_plane: {point: [0 mm, 0 mm, 0 mm], normal: [0, 0, 1]}\n"
                "lever:\n  pattern: %s\n  arm: {from: %g mm, to: %g mm}\n  theta_min: 0 deg\n"
                "  theta_max: %g deg\n  rest: %g deg\n"
                "spring: {constant: %g N/m, position: %g mm, preload: %g N}\n"
                "emphasis: {from: %g mm, to: %g mm}\napplication: {from: %g mm, to: %g mm}\n",
                name, pattern, from_mm, to_mm, theta_max_deg, theta_max_deg, spring_k, spring_at_mm, preload_n,
                em_from, em_to, ap_from, ap_to);
  return head + arms(from_mm, to_mm) + effects;
}

// One tool per lever pattern of Fig. 2.
inline std::vector<Tool> tools_of_every_pattern() {
  static const std::string type2 = tool_yaml("t2", "type2", 0, 180, 50, 500, 30, 2, 110, 170, 20, 70);
  static const std::string type3 = tool_yaml("t3", "type3", 0, 240, 30, 800, 20, 3, 60, 110, 170, 230);
  static const std::string power = tool_yaml("t1p", "type1-power", -150, 40, 40, 300, -60, 1, -140, -80, 5, 35);
  static const std::string distance = tool_yaml("t1d", "type1-distance", -60, 150, 40, 300, -30, 1, -50, -20, 60, 140);
  static const std::string balance = tool_yaml("t1b", "type1-balance", -100, 100, 40, 300, -40, 1, -90, -60, 60, 90);
  return {{"type2", type2.c_str(), 0.150, 0.040},
          {"type3", type3.c_str(), 0.090, 0.200},
          {"type1-power", power.c_str(), -0.120, 0.030},
          {"type1-distance", distance.c_str(), -0.040, 0.100},
          {"type1-balance", balance.c_str(), -0.075, 0.075}};
}

inline const char* kHandYaml = R"(agent: test_hand
description: test hand
force_gain: 20000 N/m
max_force: 400 N
fingers:
  thumb:  {tip_radius: 9 mm, distal: [0 deg, 80 deg], proximal: [0 deg, 60 deg], metacarpal: [0 deg, 50 deg]}
  index:  {tip_radius: 8 mm, distal: [0 deg, 80 deg], proximal: [0 deg, 100 deg], metacarpal: [0 deg, 90 deg]}
  middle: {tip_radius: 8 mm, distal: [0 deg, 80 deg], proximal: [0 deg, 100 deg], metacarpal: [0 deg, 90 deg]}
  ring:   {tip_radius: 8 mm, distal: [0 deg, 80 deg], proximal: [0 deg, 100 deg], metacarpal: [0 deg, 90 deg]}
  little: {tip_radius: 7 mm, distal: [0 deg, 80 deg], proximal: [0 deg, 100 deg], metacarpal: [0 deg, 90 deg]}
)";

// A rigid nut (radius 10 mm) and a sponge (radius 15 mm).
inline std::string nut_yaml(double limit_n = 300, double stiffness = 3e5) {
  return "actee: nut\ndescription: test nut\nshape: {sphere: {radius: 10 mm}}\nmass: 5 g\n"
         "force_direction: [0, 1, 0]\nlimit: " + std::to_string(limit_n) + " N\nstiffness: " +
         std::to_string(stiffness) + " N/m\nbreaks: true\n"
         "friction: {coefficient: 0.4, source: test}\n";
}
inline const char* kSpongeYaml =
    "actee: sponge\ndescription: test sponge\nshape: {sphere: {radius: 15 mm}}\nmass: 5 g\n"
    "force_direction: [0, 1, 0]\nlimit: 5 N\nstiffness: 800 N/m\nbreaks: false\n"
    "friction: {coefficient: 0.5, source: test}\n";

inline ObjectSpec object_from(const std::string& yaml) {
  return read_object(load_yaml_string(yaml, "tool.yaml"));
}
inline ActeeSpec actee_from(const std::string& yaml) { return read_actee(load_yaml_string(yaml, "actee.yaml")); }
inline AgentSpec hand() { return read_agent(load_yaml_string(kHandYaml, "hand.yaml")); }

// A model with the actee (if any) resting on the fixed jaw at `load` m.
inline Model model_of(const std::string& tool, const std::string* actee, double load) {
  const ObjectSpec o = object_from(tool);
  const AgentSpec h = hand();
  ModelOptions options;
  options.actee.distance = load;
  if (actee == nullptr) return compile(o, nullptr, &h, options);
  const ActeeSpec a = actee_from(*actee);
  return compile(o, &a, &h, options);
}

// Drives one session: the thumb on the moving arm's outer face at `effort`,
// the index finger on the fixed arm's outer face, the other fingers away.
class Rig {
 public:
  Rig(const Model& model, double effort)
      : model_(model), effort_(effort), state_(make_state(model)), angle_(state_->theta) {
    const double side = effort > 0 ? 1.0 : -1.0;
    reach_ = side * (kThickness + model.tip_radius[0] - 1e-4);  // just touching
    place_thumb();
    sample_.fingertip[1] = Eigen::Vector3d(effort, -side * (kThickness + model.tip_radius[1] - 1e-4), 0);
    for (size_t f = 2; f < kFingers; ++f) sample_.fingertip[f] = Eigen::Vector3d(0, 0, 1.0 + 0.1 * static_cast<double>(f));
    frame();  // the fingers touch
    frame();  // the grasp starts
  }

  // Advances the thumb by `metres` (negative: backs off) as a point fixed on
  // the moving arm's outer face would move, in steps of at most `step` per
  // frame. Past a stop the thumb goes on into the arm, as a tracked finger
  // does in a virtual scene.
  void push(double metres, double step = 2e-5) {
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(metres) / step)));
    for (int i = 0; i < n; ++i) {
      angle_ -= metres / n / std::abs(effort_);
      place_thumb();
      frame();
    }
  }

  // Pushes until the thumb's command reaches theta (free motion only).
  void close_to(double theta, double step = 2e-5) {
    while (state_->theta_command > theta + 1e-12) {
      push(std::min(step, (state_->theta_command - theta) * std::abs(effort_)), step);
    }
  }

  void frame() {
    sample_.t += model_.timestep;
    step(model_, *state_, sample_);
  }

  const State& state() const { return *state_; }
  Sample& sample() { return sample_; }

 private:
  void place_thumb() {
    const double c = std::cos(angle_), s = std::sin(angle_);
    sample_.fingertip[0] = Eigen::Vector3d(c * effort_ - s * reach_, s * effort_ + c * reach_, 0);
  }
  const Model& model_;
  double effort_;
  std::unique_ptr<State> state_;
  double angle_;   // rad, where the thumb's point on the arm would put the arm
  double reach_ = 0;  // m, signed offset of the thumb's centre from the arm's axis
  Sample sample_;
};

}  // namespace afford::test

namespace afford::test {

// t2 with every effect switched on, a nut with a power law, and a sensor
// delay: the frame's every path at once.
inline Model model_with_every_effect() {
  const std::string tool = tool_yaml("t2", "type2", 0, 180, 50, 500, 30, 2, 110, 170, 20, 70,
                                     "effects:\n  pivot_friction: {torque: 0.02 N*m}\n"
                                     "  viscous_damping: {coefficient: 0.002 N*m*s/rad}\n"
                                     "  progressive_spring: {cubic: 1e7 N/m^3}\n"
                                     "  arm_inertia: {inertia: 2e-4 kg*m^2}\n"
                                     "  gravity: {extra_torque: 0.05 N*m}\n");
  const std::string nut = nut_yaml(150) + "effects:\n  actee_compliance: {exponent: 1.5, reference: 0.5 mm}\n";
  const ObjectSpec o = object_from(tool);
  const ActeeSpec a = actee_from(nut);
  const AgentSpec h = hand();
  ModelOptions options;
  options.actee.distance = 0.040;
  EffectSpec latency;
  latency.name = "sensor_latency";
  latency.kind = EffectKind::sensor_latency;
  latency.param[0] = 0.0035;
  options.effects.push_back(latency);
  return compile(o, &a, &h, options);
}

}  // namespace afford::test
