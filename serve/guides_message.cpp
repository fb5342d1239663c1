// The guides as JSON for the page (guides_message.h).
#include "guides_message.h"

namespace afford::serve {

using Json = nlohmann::json;

namespace {

Json vec3(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }
Json colour(const GuideColour& c) { return Json::array({c.r, c.g, c.b, c.a}); }
Json head(int guide, Arm frame) { return Json{{"guide", guide}, {"frame", frame == Arm::moving ? "moving" : "fixed"}}; }

template <typename T, typename F>
Json list(const std::vector<T>& items, F item) {
  Json j = Json::array();
  for (const T& x : items) j.push_back(item(x));
  return j;
}

}  // namespace

Json guides_json(const Guides& g) {
  const GuideFacts& f = g.facts;
  Json j;
  j["guides"] = list(g.guides, [](const GuideSpec& s) {
    return Json{{"name", s.name}, {"kind", guide_kind_name(s.kind)}, {"description", s.description},
                {"colour", colour(s.colour)}};
  });
  j["rects"] = list(g.rects, [](const GuideRect& x) {
    Json e = head(x.guide, x.frame);
    e.update(Json{{"centre", vec3(x.centre)}, {"u", vec3(x.u)}, {"v", vec3(x.v)}, {"half_u", x.half_u},
                  {"half_v", x.half_v}, {"colour", colour(x.colour)}});
    return e;
  });
  j["meshes"] = list(g.meshes, [](const GuideMesh& x) {
    Json e = head(x.guide, x.frame);
    e.update(Json{{"vertices", list(x.vertices, vec3)}, {"triangles", x.triangles}, {"colour", colour(x.colour)}});
    return e;
  });
  j["segments"] = list(g.segments, [](const GuideSegment& x) {
    Json e = head(x.guide, x.frame);
    e.update(Json{{"a", vec3(x.a)}, {"b", vec3(x.b)}, {"colour", colour(x.colour)}, {"value", x.value}});
    return e;
  });
  j["labels"] = list(g.labels, [](const GuideLabel& x) {
    Json e = head(x.guide, x.frame);
    e.update(Json{{"text", x.text}, {"anchor", vec3(x.anchor)}, {"colour", colour(x.colour)}});
    return e;
  });
  j["facts"] = {
      {"pattern", pattern_name(f.pattern)},
      {"symmetry_plane", {{"point", vec3(f.symmetry_point)}, {"normal", vec3(f.symmetry_normal)}}},
      {"interaction_space",
       {{"from", f.space.from}, {"to", f.space.to}, {"gap_from", f.space.gap_from}, {"gap_to", f.space.gap_to}}},
      {"emphasis", {{"from", f.emphasis_from}, {"to", f.emphasis_to}}},
      {"advantage",
       {{"load_at", f.load_at}, {"ma_min", f.ma_min}, {"ma_max", f.ma_max}, {"ma_arm_min", f.ma_arm_min},
        {"ma_arm_max", f.ma_arm_max}}}};
  return j;
}

}  // namespace afford::serve
