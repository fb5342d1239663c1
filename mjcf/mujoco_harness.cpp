#include "mujoco_harness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include "files.h"
#include "mjcf_scene.h"

namespace afford {

namespace fs = std::filesystem;

MujocoScene::MujocoScene(const CompiledSession& session) {
  const fs::path file =
      fs::temp_directory_path() / ("afford-mjcf-" + session.name + "-" + std::to_string(::getpid()) + ".xml");
  write_file_checked(file.string(), mjcf_scene(session));
  std::array<char, 1000> error{};
  m_ = mj_loadXML(file.c_str(), nullptr, error.data(), static_cast<int>(error.size()));
  fs::remove(file);
  if (m_ == nullptr) throw std::runtime_error(session.name + ": MuJoCo: " + error.data());
  d_ = mj_makeData(m_);
  hinge_ = mj_name2id(m_, mjOBJ_JOINT, "hinge");
  hand_ = mj_name2id(m_, mjOBJ_ACTUATOR, "hand");
  arm_ = mj_name2id(m_, mjOBJ_BODY, "moving_arm");
  actee_geom_ = mj_name2id(m_, mjOBJ_GEOM, "actee");
  if (actee_geom_ >= 0) {
    actee_ = m_->geom_bodyid[actee_geom_];
    affinity_ = m_->geom_conaffinity[actee_geom_];
    limit_ = numeric("actee_limit");
    breaks_ = numeric("actee_breaks") != 0;
    thickness_ = numeric("actee_thickness");
    exponent_ = numeric("actee_exponent");
    reference_ = numeric("actee_reference");
    stiffness_ = -m_->geom_solref[mjNREF * actee_geom_];
    damping_ = -m_->geom_solref[mjNREF * actee_geom_ + 1];
  }
  if (hand_ >= 0) {
    const int id = mj_name2id(m_, mjOBJ_NUMERIC, "hand_schedule");
    schedule_ = m_->numeric_data + m_->numeric_adr[id];
    pairs_ = m_->numeric_size[id] / 2;
  }
  substeps_ = static_cast<int>(numeric("substeps"));
  springref_ = numeric("springref");
  spring_arm_ = numeric("spring_arm");
  spring_cubic_ = numeric("spring_cubic");
  gravity_extra_ = numeric("gravity_extra");
  restart();
}

MujocoScene::~MujocoScene() {
  mj_deleteData(d_);
  mj_deleteModel(m_);
}

double MujocoScene::numeric(const char* name) const {
  const int id = mj_name2id(m_, mjOBJ_NUMERIC, name);
  if (id < 0) throw std::runtime_error(std::string("the scene has no numeric ") + name);
  return m_->numeric_data[m_->numeric_adr[id]];
}

void MujocoScene::restart() {
  mj_resetDataKeyframe(m_, d_, 0);
  if (actee_geom_ >= 0) m_->geom_conaffinity[actee_geom_] = affinity_;
}

void MujocoScene::command(double theta_rad) {
  if (hand_ >= 0) d_->ctrl[hand_] = theta_rad;
}

double MujocoScene::scheduled(double t_s) const {
  const mjtNum* s = schedule_;
  if (pairs_ == 0) return 0;
  if (t_s <= s[0]) return s[1];
  for (int k = 1; k < pairs_; ++k) {
    if (t_s <= s[2 * k]) {
      const double w = (t_s - s[2 * k - 2]) / (s[2 * k] - s[2 * k - 2]);
      return (1 - w) * s[2 * k - 1] + w * s[2 * k + 1];
    }
  }
  return s[2 * pairs_ - 1];
}

double MujocoScene::duration() const { return pairs_ > 0 ? schedule_[2 * pairs_ - 2] : 0.0; }

void MujocoScene::step() {
  const double th = theta();
  const double d = spring_arm_ * (springref_ - th);  // m, the spring's compression
  const double progressive = d > 0 ? spring_cubic_ * d * d * d * spring_arm_ : 0.0;
  d_->qfrc_applied[m_->jnt_dofadr[hinge_]] = progressive - gravity_extra_ * std::cos(th);
  if (actee_geom_ >= 0) actee_law();
  mj_step(m_, d_);
}

void MujocoScene::actee_law() {
  if (!(thickness_ > 0)) return;
  // The deflection across the jaws: the two contacts' penetrations, in
  // series, at the last step.
  double deflection = 0;  // m
  for (int i = 0; i < d_->ncon; ++i) {
    const mjContact& c = d_->contact[i];
    if ((c.geom1 == actee_geom_ || c.geom2 == actee_geom_) && c.dist < 0) deflection -= c.dist;
  }
  // The law's secant stiffness over K: a contact of that stiffness pushes
  // with the law's force at this deflection. Held below the thickness.
  deflection = std::min(deflection, 0.99 * thickness_);
  double secant = thickness_ / (thickness_ - deflection);
  if (exponent_ != 1 && deflection > 0) secant *= std::pow(deflection / reference_, exponent_ - 1);
  // The tool's geoms and the actee's take the same solref, so that
  // MuJoCo's mix of the two is that one.
  for (int g = 0; g < m_->ngeom; ++g) {
    m_->geom_solref[mjNREF * g] = -stiffness_ * secant;
    m_->geom_solref[mjNREF * g + 1] = -damping_ * std::sqrt(secant);
  }
}

bool MujocoScene::frame() {
  // Each step aims where the schedule is at its end, as the engine's frame
  // solves for where its sample puts the thumb at the frame's end.
  for (int s = 0; s < substeps_; ++s) {
    if (hand_ >= 0) d_->ctrl[hand_] = scheduled(d_->time + m_->opt.timestep);
    step();
  }
  if (actee_geom_ < 0 || !breaks_ || m_->geom_conaffinity[actee_geom_] == 0) return false;
  if (actee_load() <= limit_) return false;
  drop_actee();
  return true;
}

double MujocoScene::theta() const { return d_->qpos[m_->jnt_qposadr[hinge_]]; }

double MujocoScene::hand_torque() const { return hand_ >= 0 ? d_->actuator_force[hand_] : 0.0; }

double MujocoScene::actee_load() const {
  double load = 0;
  for (int i = 0; i < d_->ncon; ++i) {
    const int b1 = m_->geom_bodyid[d_->contact[i].geom1], b2 = m_->geom_bodyid[d_->contact[i].geom2];
    if (!((b1 == arm_ && b2 == actee_) || (b1 == actee_ && b2 == arm_))) continue;
    mjtNum f[6];
    mj_contactForce(m_, d_, i, f);
    load += f[0];
  }
  return load;
}

void MujocoScene::drop_actee() {
  if (actee_geom_ >= 0) m_->geom_conaffinity[actee_geom_] = 0;
}

int MujocoScene::warnings() const {
  int n = 0;
  for (int i = 0; i < mjNWARNING; ++i) n += d_->warning[i].number;
  return n;
}

}  // namespace afford
