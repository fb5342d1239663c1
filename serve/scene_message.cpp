// The scene a page draws (scene_message.h).
#include "scene_message.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "guides_message.h"
#include "mesh.h"

namespace afford::serve {

using Json = nlohmann::json;

namespace {

// 0.01 mm is finer than any pixel the page draws, and keeps the message small.
double rounded(double v) { return std::round(v * 1e5) / 1e5; }

Json mesh_json(const Geometry& g) {
  render::Mesh mesh;
  render::add_shape(mesh, g);
  Json pos = Json::array(), nrm = Json::array();
  for (float v : mesh.pos) pos.push_back(rounded(v));
  for (float v : mesh.nrm) nrm.push_back(std::round(v * 1e3) / 1e3);
  return Json{{"positions", std::move(pos)}, {"normals", std::move(nrm)}};
}

Json matrix(const Eigen::Isometry3d& pose) {
  Json m = Json::array();
  for (int i = 0; i < 16; ++i) m.push_back(pose.matrix().data()[i]);
  return m;
}

Json vec(const std::array<double, 3>& v) { return Json::array({v[0], v[1], v[2]}); }

}  // namespace

std::string scene_message(const CompiledSession& session, const PageGrip& grip, const PageStart& start,
                          const CommandLimits& limits, const SceneInfo& info) {
  const Model& m = session.model;
  Json parts = Json::array();
  for (const ModelPart& p : m.parts) {
    Json part = mesh_json(p.geometry);
    part["name"] = p.name;
    part["arm"] = p.arm == Arm::moving ? "moving" : "fixed";
    part["in_arm"] = matrix(p.in_arm);
    parts.push_back(std::move(part));
  }
  Json actee = nullptr;
  if (m.has_actee) {
    actee = mesh_json(m.actee());
    char colour[8];
    const ActeeLook::Srgb& c = m.actee_look.colour;
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", c[0], c[1], c[2]);
    actee["colour"] = colour;
    actee["limit"] = m.actee_limit;
    actee["breaks"] = m.actee_breaks;
  }
  Json radii = Json::array();
  for (double r : m.tip_radius) radii.push_back(r);
  Json j{{"type", "scene"},
         {"session", session.name},
         {"description", session.description},
         {"object", m.object_name},
         {"trial", info.trial},
         {"participant", info.participant},
         {"recording", info.recording},
         {"actee_name", info.actee_name},
         {"parts", std::move(parts)},
         {"actee", std::move(actee)},
         {"fingertip_radius", std::move(radii)},
         {"theta", {{"min", m.theta_min}, {"max", m.theta_max}, {"rest", m.theta_rest}}},
         {"limits", {{"max_squeeze", limits.max_squeeze}, {"hand_min", vec(limits.hand_min)},
                     {"hand_max", vec(limits.hand_max)}}},
         {"hand_start", Json::array({start.hand_position.x(), start.hand_position.y(), start.hand_position.z()})},
         {"grip", {{"posture", grip.posture}, {"thumb_distance", grip.thumb_distance}}},
         {"shelf", info.shelf},
         {"timestep", m.timestep},
         {"guides", info.guides ? guides_json(*info.guides) : Json(nullptr)}};
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace afford::serve
