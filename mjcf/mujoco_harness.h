// An exported scene (mjcf_scene.h) run in MuJoCo as its header comment
// asks: the hand's commanded angle from the schedule, the progressive
// spring and gravity's extra torque applied to the hinge, the actee's
// contacts as stiff as its law's secant at their deflection, the actee
// broken (its contacts dropped) past its limit. The tests and the benchmark use
// it; built only where CMake finds MuJoCo (afford_mjcf_mujoco).
#pragma once

#include <mujoco/mujoco.h>

#include <string>

#include "session.h"

namespace afford {

class MujocoScene {
 public:
  // Exports the session's scene and loads it (through a temporary file:
  // MuJoCo 2.2.2 reads XML from files); at key 'start'. Throws
  // std::runtime_error with MuJoCo's message if it does not load.
  explicit MujocoScene(const CompiledSession& session);
  ~MujocoScene();
  MujocoScene(const MujocoScene&) = delete;
  MujocoScene& operator=(const MujocoScene&) = delete;

  mjModel* model() { return m_; }
  mjData* data() { return d_; }

  // Back to key 'start', the actee whole.
  void restart();

  bool has_hand() const { return hand_ >= 0; }
  void command(double theta_rad);        // the hand's commanded angle
  double scheduled(double t_s) const;    // the script's commanded angle at t, interpolated
  int substeps() const { return substeps_; }  // mj_step calls a frame
  double duration() const;               // s, the script's last keyframe (0 without a hand)

  // One mj_step with what MJCF cannot say: the progressive spring and
  // gravity's extra torque on the hinge, and the actee's law (terms.h
  // actee_force_law) as its contacts' stiffness.
  void step();
  // One frame: the schedule's command, `substeps` steps, then the actee
  // breaks if its load passed its limit (and it breaks). True when it
  // broke in this frame.
  bool frame();

  double theta() const;        // rad, the hinge
  double hand_torque() const;  // N*m, the servo's, closing negative
  double actee_load() const;   // N, normal force of the actee's contacts with the moving arm
  void drop_actee();           // no more contacts for the actee
  int warnings() const;        // MuJoCo's warnings so far (instability, bad accelerations, ...)

 private:
  double numeric(const char* name) const;
  void actee_law();  // the actee's contacts' stiffness for the deflection they have

  mjModel* m_ = nullptr;
  mjData* d_ = nullptr;
  int hinge_ = -1, hand_ = -1, arm_ = -1, actee_geom_ = -1, actee_ = -1;
  int affinity_ = 0;  // the actee geom's contact bits, whole
  const mjtNum* schedule_ = nullptr;
  int pairs_ = 0, substeps_ = 1;
  double springref_ = 0, spring_arm_ = 0, spring_cubic_ = 0, gravity_extra_ = 0;
  double limit_ = 0;
  bool breaks_ = false;
  // The actee's law: F = K d_r (d / d_r)^n h / (h - d) at a deflection d
  // across the jaws; its contacts' direct solref (-k, -b) at K.
  double thickness_ = 0, exponent_ = 1, reference_ = 0, stiffness_ = 0, damping_ = 0;
};

}  // namespace afford
