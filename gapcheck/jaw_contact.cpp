#include "jaw_contact.h"

#include <cmath>
#include <stdexcept>

#include "load.h"
#include "mujoco_harness.h"

namespace gapcheck {

namespace {

// m: a geom's extent along the world direction n (unit).
double extent(const mjModel* m, const mjData* d, int geom, const double n[3]) {
  double local[3];  // n in the geom's frame: xmat is row-major, geom to world
  for (int i = 0; i < 3; ++i) {
    local[i] = d->geom_xmat[9 * geom + 0 + i] * n[0] + d->geom_xmat[9 * geom + 3 + i] * n[1] +
               d->geom_xmat[9 * geom + 6 + i] * n[2];
  }
  const mjtNum* size = m->geom_size + 3 * geom;
  switch (m->geom_type[geom]) {
    case mjGEOM_SPHERE: return 2 * size[0];
    case mjGEOM_ELLIPSOID:
      return 2 * std::sqrt(std::pow(size[0] * local[0], 2) + std::pow(size[1] * local[1], 2) +
                           std::pow(size[2] * local[2], 2));
    case mjGEOM_BOX:
      return 2 * (std::abs(size[0] * local[0]) + std::abs(size[1] * local[1]) + std::abs(size[2] * local[2]));
    default: throw std::runtime_error("gapcheck: an actee's thickness for spheres, ellipsoids and boxes only");
  }
}

// The tool with the actee in its jaws, as a session holds it.
afford::CompiledSession session_of(const std::string& object_file, const std::string& actee_file,
                                   const std::string& agent_file, double at_m) {
  const afford::ObjectSpec object = afford::load_object(object_file);
  const afford::ActeeSpec actee = afford::load_actee(actee_file);
  const afford::AgentSpec agent = afford::load_agent(agent_file);
  afford::ModelOptions options;
  options.actee.distance = at_m;
  afford::CompiledSession session;
  session.name = "gapcheck-contact-" + object.name + "-" + actee.name;
  session.file = session.name;
  session.model = afford::compile(object, &actee, &agent, options);
  return session;
}

SceneGeom scene_geom(const mjModel* m, int geom) {
  SceneGeom g;
  g.type = m->geom_type[geom];
  for (int i = 0; i < 3; ++i) g.size[i] = m->geom_size[3 * geom + i];
  for (int i = 0; i < 3; ++i) g.pos[i] = m->geom_pos[3 * geom + i];
  for (int i = 0; i < 4; ++i) g.quat[i] = m->geom_quat[4 * geom + i];
  return g;
}

}  // namespace

JawScene jaw_scene(const std::string& object_file, const std::string& actee_file, const std::string& agent_file,
                   double at_m) {
  const afford::CompiledSession session = session_of(object_file, actee_file, agent_file, at_m);
  afford::MujocoScene scene(session);
  mjModel* m = scene.model();
  mjData* d = scene.data();
  mj_forward(m, d);
  const int arm = mj_name2id(m, mjOBJ_BODY, "moving_arm");
  const int actee_geom = mj_name2id(m, mjOBJ_GEOM, "actee");
  JawScene out;
  // The moving arm's body frame is the arm's frame (its joint's ref is
  // the rest angle, at which the body's quat puts it).
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_bodyid[g] == arm) out.moving.push_back(scene_geom(m, g));
  }
  // The actee's geom in the tool's frame: its world pose taken into it.
  const int tool = mj_name2id(m, mjOBJ_BODY, "tool");
  SceneGeom a = scene_geom(m, actee_geom);
  const double* x = d->geom_xpos + 3 * actee_geom;
  const double* origin = d->xpos + 3 * tool;
  const double offset[3] = {x[0] - origin[0], x[1] - origin[1], x[2] - origin[2]};
  mju_mulMatTVec(a.pos, d->xmat + 9 * tool, offset, 3, 3);
  double geom_quat[4], tool_inverse[4];
  mju_mat2Quat(geom_quat, d->geom_xmat + 9 * actee_geom);
  mju_negQuat(tool_inverse, d->xquat + 4 * tool);
  mju_mulQuat(a.quat, tool_inverse, geom_quat);
  out.actee = a;
  return out;
}

JawContact jaw_contact(const std::string& object_file, const std::string& actee_file, const std::string& agent_file,
                       double at_m) {
  const afford::CompiledSession session = session_of(object_file, actee_file, agent_file, at_m);
  afford::MujocoScene scene(session);
  mjModel* m = scene.model();
  mjData* d = scene.data();
  // MPR (the convex pairs' collider) to far below the 1e-7 rad needed: at
  // 60 mm and 250 N/mm, 1e-7 rad is 1.5 mN of the actee's force.
  m->opt.mpr_tolerance = 1e-14;
  m->opt.mpr_iterations = 1000;
  const int joint = mj_name2id(m, mjOBJ_JOINT, "hinge");
  const int hinge = m->jnt_qposadr[joint];
  const int actee_geom = mj_name2id(m, mjOBJ_GEOM, "actee");
  const int arm = mj_name2id(m, mjOBJ_BODY, "moving_arm");
  const int tool = mj_name2id(m, mjOBJ_BODY, "tool");
  auto touches = [&](double theta) {
    scene.restart();
    d->qpos[hinge] = theta;
    mj_forward(m, d);
    for (int i = 0; i < d->ncon; ++i) {
      const mjContact& c = d->contact[i];
      const int other = c.geom1 == actee_geom ? c.geom2 : c.geom2 == actee_geom ? c.geom1 : -1;
      if (other >= 0 && m->geom_bodyid[other] == arm && c.dist < 0) return true;
    }
    return false;
  };
  double closed = m->jnt_range[2 * joint], open = m->jnt_range[2 * joint + 1];
  if (!touches(closed) || touches(open)) {
    throw std::runtime_error(session.name + ": the jaws do not close on the actee within the hinge's range");
  }
  for (int i = 0; i < 100 && open - closed > 1e-13; ++i) {
    const double mid = 0.5 * (closed + open);
    (touches(mid) ? closed : open) = mid;
  }
  JawContact contact;
  contact.angle = 0.5 * (closed + open);
  // The moving jaw pushes along the contact's normal (the first row of
  // MuJoCo's contact frame) at its point: the moment arm about the hinge
  // is |((p - anchor) x n) . axis|, read at the last angle that touched.
  touches(closed);
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const int other = c.geom1 == actee_geom ? c.geom2 : c.geom2 == actee_geom ? c.geom1 : -1;
    if (other < 0 || m->geom_bodyid[other] != arm || !(c.dist < 0)) continue;
    const mjtNum* anchor = d->xanchor + 3 * joint;
    const mjtNum* axis = d->xaxis + 3 * joint;
    const double p[3] = {c.pos[0] - anchor[0], c.pos[1] - anchor[1], c.pos[2] - anchor[2]};
    const double* n = c.frame;
    const double moment[3] = {p[1] * n[2] - p[2] * n[1], p[2] * n[0] - p[0] * n[2], p[0] * n[1] - p[1] * n[0]};
    contact.lever = std::abs(moment[0] * axis[0] + moment[1] * axis[1] + moment[2] * axis[2]);
    // The normal points from geom1 to geom2; into the actee from the jaw.
    const double sign = c.geom2 == actee_geom ? 1.0 : -1.0;
    const double offset[3] = {c.pos[0] - d->xpos[3 * tool], c.pos[1] - d->xpos[3 * tool + 1], c.pos[2] - d->xpos[3 * tool + 2]};
    const double into[3] = {sign * n[0], sign * n[1], sign * n[2]};
    mju_mulMatTVec(contact.touch, d->xmat + 9 * tool, offset, 3, 3);
    mju_mulMatTVec(contact.into, d->xmat + 9 * tool, into, 3, 3);
  }
  if (!(contact.lever > 0)) throw std::runtime_error(session.name + ": MuJoCo's contact with the moving jaw was lost");
  // Across the jaws: the fixed jaw's normal is the tool body's y axis.
  const double normal[3] = {d->xmat[9 * tool + 1], d->xmat[9 * tool + 4], d->xmat[9 * tool + 7]};
  contact.thickness = extent(m, d, actee_geom, normal);
  return contact;
}

}  // namespace gapcheck
