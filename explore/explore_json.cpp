#include "explore_json.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "files.h"

namespace afford {
namespace {

using Json = nlohmann::ordered_json;

// A shard's file of the largest grid (kMaxPoints) stays well below this.
constexpr size_t kMaxExploreJsonBytes = size_t{4} << 30;

// -1 (none) as null, else the function's index by name.
Json outcome_json(const GridInfo& g, int o) { return o < 0 ? Json(nullptr) : Json(g.functions[static_cast<size_t>(o)]); }

Json point_json(const GridInfo& g, const PointResult& p) {
  Json first = Json::object();
  for (size_t f = 0; f < g.functions.size(); ++f) first[g.functions[f]] = p.first[f] >= 0 ? Json(p.first[f]) : Json(nullptr);
  return {{"outcome", outcome_json(g, p.outcome)},
          {"applied_s", p.applied_from >= 0 ? Json(p.applied_from) : Json(nullptr)},
          {"first_s", first}, {"peak_effort_N", p.peak_effort}, {"peak_actee_force_N", p.peak_actee_force},
          {"broke_s", p.broke_at >= 0 ? Json(p.broke_at) : Json(nullptr)}};
}

// Reading back: each value checked for its type and range, so that a
// damaged file is an error, never an index out of bounds.
struct Reader {
  const std::string& path;
  [[noreturn]] void bad(const std::string& what) const {
    throw std::runtime_error(path + ": not an explore.json of this grid: " + what);
  }
  const Json& at(const Json& j, const char* key) const {
    if (!j.is_object() || !j.contains(key)) bad(std::string("expected the key '") + key + "'");
    return j[key];
  }
  double number(const Json& j, const char* key) const {
    const Json& v = at(j, key);
    if (!v.is_number()) bad(std::string("'") + key + "' is not a number");
    return v.get<double>();
  }
  int index(const Json& j, const char* key, size_t size) const {
    const Json& v = at(j, key);
    if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() >= static_cast<long long>(size)) {
      bad(std::string("'") + key + "' is not an index below " + std::to_string(size));
    }
    return v.get<int>();
  }
  std::string text(const Json& j, const char* key) const {
    const Json& v = at(j, key);
    if (!v.is_string()) bad(std::string("'") + key + "' is not a string");
    return v.get<std::string>();
  }
  bool flag(const Json& j, const char* key) const {
    const Json& v = at(j, key);
    if (!v.is_boolean()) bad(std::string("'") + key + "' is not true or false");
    return v.get<bool>();
  }
  const Json& array(const Json& j, const char* key) const {
    const Json& v = at(j, key);
    if (!v.is_array()) bad(std::string("'") + key + "' is not a list");
    return v;
  }
  std::vector<double> numbers(const Json& j, const char* key) const {
    std::vector<double> out;
    for (const Json& v : array(j, key)) {
      if (!v.is_number()) bad(std::string("'") + key + "' holds a value that is not a number");
      out.push_back(v.get<double>());
    }
    return out;
  }
  int outcome(const GridInfo& g, const Json& j, const char* key) const {
    const Json& v = at(j, key);
    if (v.is_null()) return -1;
    if (v.is_string()) {
      const auto it = std::find(g.functions.begin(), g.functions.end(), v.get<std::string>());
      if (it != g.functions.end()) return static_cast<int>(it - g.functions.begin());
    }
    bad(std::string("'") + key + "' is not a function of the grid or null");
  }
  // A time or null (-1).
  double time(const Json& j, const char* key) const {
    const Json& v = at(j, key);
    if (!v.is_null() && !v.is_number()) bad(std::string("'") + key + "' is neither a number nor null");
    return v.is_null() ? -1.0 : v.get<double>();
  }
  PointResult point(const GridInfo& g, const Json& j) const {
    PointResult p;
    p.outcome = outcome(g, j, "outcome");
    p.applied_from = time(j, "applied_s");
    const Json& first = at(j, "first_s");
    for (const std::string& f : g.functions) {
      const Json& t = at(first, f.c_str());
      if (!t.is_null() && !t.is_number()) bad("a time in 'first_s' is neither a number nor null");
      p.first.push_back(t.is_null() ? -1.0 : t.get<double>());
    }
    p.peak_effort = number(j, "peak_effort_N");
    p.peak_actee_force = number(j, "peak_actee_force_N");
    p.broke_at = time(j, "broke_s");
    return p;
  }
};

}  // namespace

std::string explore_json(const GridInfo& g, const ExploreResult& r) {
  Json actees = Json::array();
  for (const GridActee& a : g.actees) {
    actees.push_back({{"name", a.name}, {"file", a.file}, {"fits", a.fits}, {"why", a.why}, {"limit_N", a.limit},
                      {"breaks", a.breaks}, {"placements_m", a.placements}, {"efforts_N", a.efforts}});
  }
  Json grasps = Json::array();
  for (size_t k = 0; k < g.grasps.size(); ++k) grasps.push_back({{"name", g.grasps[k]}, {"limit_N", g.grasp_limit[k]}});
  Json series = Json::array();
  for (const SeriesResult& s : r.series) {
    Json points = Json::array();
    for (const PointResult& p : s.points) points.push_back(point_json(g, p));
    Json thresholds = Json::array();
    for (const Threshold& t : s.thresholds) {
      thresholds.push_back({{"from", outcome_json(g, t.from)}, {"to", outcome_json(g, t.to)}, {"below_N", t.below},
                            {"effort_N", t.effort}, {"at", point_json(g, t.at)}});
    }
    series.push_back({{"index", s.index}, {"actee", s.key.actee}, {"placement", s.key.placement},
                      {"thumb", s.key.thumb}, {"grasp", s.key.grasp},
                      {"mechanical_advantage", s.mechanical_advantage},
                      {"lever_effort_at_limit_N", s.lever_effort_at_limit}, {"points", points},
                      {"thresholds", thresholds}});
  }
  Json strength = Json::array();  // weakest first
  for (size_t rank = 0; rank < g.strength.size(); ++rank) {
    for (size_t f = 0; f < g.strength.size(); ++f) {
      if (g.strength[f] == static_cast<int>(rank)) strength.push_back(g.functions[f]);
    }
  }
  Json j = {{"object", g.object}, {"functions", g.functions}, {"strength", strength}, {"tolerance_N", g.tolerance},
            {"thumbs_m", g.thumbs}, {"efforts_N", g.efforts}, {"efforts_scaled", g.efforts_scaled},
            {"grasps", grasps}, {"actees", actees}};
  if (!r.shard.whole()) j["shard"] = {{"part", r.shard.part}, {"count", r.shard.count}};
  j["series"] = series;
  return j.dump(1) + "\n";
}

void read_explore_json(const std::string& path, GridInfo* g, ExploreResult* r) {
  parse_explore_json(read_regular_file(path, kMaxExploreJsonBytes), path, g, r);
}

void parse_explore_json(const std::string& text, const std::string& path, GridInfo* g, ExploreResult* r) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& e) {
    // nlohmann counts bytes; people count lines and columns.
    const size_t at = std::min(e.byte > 0 ? e.byte - 1 : 0, text.size());
    const size_t line = 1 + static_cast<size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    const size_t start = text.rfind('\n', at == 0 ? 0 : at - 1);
    const size_t column = at - (start == std::string::npos ? 0 : start + 1) + 1;
    throw std::runtime_error(path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": not JSON");
  } catch (const Json::exception& e) {
    // A number too large for a double (found by fuzz_explore_json): nlohmann
    // names the number, not where it is.
    throw std::runtime_error(path + ": not JSON: " + e.what());
  }
  const Reader in{path};
  *g = GridInfo{};
  *r = ExploreResult{};
  g->object = in.text(j, "object");
  for (const Json& f : in.array(j, "functions")) {
    if (!f.is_string()) in.bad("a function name is not a string");
    g->functions.push_back(f.get<std::string>());
  }
  // Every function once, weakest first; a file without it (written before
  // there was one) ranks them in their order, as the function models do.
  g->strength.assign(g->functions.size(), -1);
  const Json strength = j.is_object() && j.contains("strength") ? in.array(j, "strength") : Json(g->functions);
  for (size_t rank = 0; rank < strength.size(); ++rank) {
    const auto it = strength[rank].is_string()
                        ? std::find(g->functions.begin(), g->functions.end(), strength[rank].get<std::string>())
                        : g->functions.end();
    if (it == g->functions.end() || g->strength[static_cast<size_t>(it - g->functions.begin())] >= 0) {
      in.bad("'strength' is not every function once");
    }
    g->strength[static_cast<size_t>(it - g->functions.begin())] = static_cast<int>(rank);
  }
  if (strength.size() != g->functions.size()) in.bad("'strength' is not every function once");
  g->tolerance = in.number(j, "tolerance_N");
  g->thumbs = in.numbers(j, "thumbs_m");
  g->efforts = in.numbers(j, "efforts_N");
  g->efforts_scaled = j.contains("efforts_scaled") && in.flag(j, "efforts_scaled");
  for (const Json& k : in.array(j, "grasps")) {
    g->grasps.push_back(in.text(k, "name"));
    g->grasp_limit.push_back(in.number(k, "limit_N"));
  }
  // Every axis has a value: the reports index the first and the last.
  if (g->thumbs.empty() || g->efforts.empty() || g->grasps.empty()) in.bad("a grid without thumbs, efforts or grasps");
  for (const Json& a : in.array(j, "actees")) {
    GridActee actee;
    actee.name = in.text(a, "name");
    actee.file = in.text(a, "file");
    actee.fits = in.flag(a, "fits");
    actee.why = in.text(a, "why");
    actee.limit = in.number(a, "limit_N");
    actee.breaks = in.flag(a, "breaks");
    actee.placements = in.numbers(a, "placements_m");
    actee.efforts = a.is_object() && a.contains("efforts_N") ? in.numbers(a, "efforts_N") : std::vector<double>{};
    if (!a.contains("efforts_N") && actee.fits) actee.efforts = g->efforts;  // one axis for all, as before
    if (actee.fits == actee.placements.empty() || actee.fits == actee.efforts.empty()) {
      in.bad("an actee that fits without placements or efforts, or one that does not with some");
    }
    g->actees.push_back(std::move(actee));
  }
  if (j.contains("shard")) {
    r->shard.part = in.index(j["shard"], "part", 1u << 20);
    r->shard.count = in.index(j["shard"], "count", 1u << 20);
  }
  for (const Json& s : in.array(j, "series")) {
    SeriesResult out;
    out.index = in.index(s, "index", static_cast<size_t>(kMaxPoints));
    out.key.actee = in.index(s, "actee", g->actees.size());
    out.key.placement = in.index(s, "placement", g->actees[static_cast<size_t>(out.key.actee)].placements.size());
    out.key.thumb = in.index(s, "thumb", g->thumbs.size());
    out.key.grasp = in.index(s, "grasp", g->grasps.size());
    out.mechanical_advantage = in.number(s, "mechanical_advantage");
    out.lever_effort_at_limit = in.number(s, "lever_effort_at_limit_N");
    for (const Json& p : in.array(s, "points")) out.points.push_back(in.point(*g, p));
    if (out.points.size() != g->actees[static_cast<size_t>(out.key.actee)].efforts.size()) {
      in.bad("a series without one point per effort of its actee");
    }
    for (const Json& t : in.array(s, "thresholds")) {
      Threshold th;
      th.from = in.outcome(*g, t, "from");
      th.to = in.outcome(*g, t, "to");
      th.below = in.number(t, "below_N");
      th.effort = in.number(t, "effort_N");
      th.at = in.point(*g, in.at(t, "at"));
      out.thresholds.push_back(std::move(th));
    }
    r->series.push_back(std::move(out));
  }
}

}  // namespace afford
