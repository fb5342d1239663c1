#include "reports.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>

#include "explore_json.h"
#include "files.h"
#include "maps.h"
#include "units.h"

namespace afford {
namespace {

// The shortest text that reads back as the same double (the grid's values
// and times are tidy, grid_axis.h: 0.04125, not 0.041249999999999995).
std::string exact(double v) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  return std::string(buf, end);
}

std::string q(double si, const Dimension& d) { return format_quantity(si, d); }

// "1 grasp", "3 grasps".
std::string count(size_t n, const std::string& what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

std::string first_times(const PointResult& p) {
  std::string row;
  for (double t : p.first) row += "," + (t >= 0 ? exact(t) : std::string());
  return row;
}

// Where a series sits, in words: "the thumb at 180 mm with the walnut at 55 mm (medium_wrap)".
std::string where(const GridInfo& g, const GridPoint& k) {
  std::string s = "the thumb at " + q(g.thumbs[static_cast<size_t>(k.thumb)], dim::length) + " with the " +
                  g.actees[static_cast<size_t>(k.actee)].name + " at " +
                  q(g.actees[static_cast<size_t>(k.actee)].placements[static_cast<size_t>(k.placement)], dim::length);
  if (g.grasps[static_cast<size_t>(k.grasp)] != "-") s += " (" + g.grasps[static_cast<size_t>(k.grasp)] + ")";
  return s;
}

// One outcome of one actee over the whole grid: the efforts where it was
// seen, the series of the lowest, the grasps that reached it.
struct Seen {
  bool any = false;
  double low = std::numeric_limits<double>::infinity(), high = 0;  // N
  const SeriesResult* lowest = nullptr;
  std::vector<bool> by_grasp;
  void add(double effort, const SeriesResult& s) {
    any = true;
    if (effort < low) {
      low = effort;
      lowest = &s;
    }
    high = std::max(high, effort);
    by_grasp[static_cast<size_t>(s.key.grasp)] = true;
  }
};

void summarise_actee(const GridInfo& g, const ExploreResult& r, int actee, std::string* out) {
  const GridActee& a = g.actees[static_cast<size_t>(actee)];
  if (!a.fits) {
    *out += a.name + ": does not fit the " + g.object + ": " + a.why + "\n";
    return;
  }
  const std::string span = a.placements.size() == 1 ? "at " + q(a.placements.front(), dim::length)
                                                     : "from " + q(a.placements.front(), dim::length) + " to " +
                                                           q(a.placements.back(), dim::length);
  *out += a.name + " (limit " + q(a.limit, dim::force) + (a.breaks ? ", breaks" : ", gives way") + "): tried " + span +
          " along the jaws\n";
  const std::vector<double>& efforts = a.efforts;
  *out += "  efforts " + q(efforts.front(), dim::force) + " to " + q(efforts.back(), dim::force);
  if (g.efforts_scaled && efforts != g.efforts) {
    *out += ", scaled to where it turns (on the common axis, up to " + q(g.efforts.back(), dim::force) +
            ", no turn lies above it)";
  } else if (g.efforts_scaled) {
    *out += ": no turn to scale to";
  }
  *out += "\n";
  for (size_t k = 0; k < g.grasps.size(); ++k) {
    if (g.grasp_limit[k] < efforts.back()) {
      *out += "  " + g.grasps[k] + " pushes at most " + q(g.grasp_limit[k], dim::force) +
              ": efforts above it are pushed at it (beyond the grasp's cap)\n";
    }
  }
  for (const std::vector<int>& group : alike_grasps(g, r, actee)) {
    if (group.size() < 2) continue;
    std::string names;
    for (int k : group) names += (names.empty() ? "" : ", ") + g.grasps[static_cast<size_t>(k)];
    *out += "  alike everywhere (one row of the map): " + names + "\n";
  }
  // Index 0 stands for no function, then each function in file order.
  std::vector<Seen> seen(g.functions.size() + 1);
  for (Seen& s : seen) s.by_grasp.assign(g.grasps.size(), false);
  std::vector<bool> inferred(g.functions.size(), false);  // anywhere, at any time
  const SeriesResult* explained = nullptr;  // the series whose actee reaches its limit with the least effort
  for (const SeriesResult& s : r.series) {
    if (s.key.actee != actee) continue;
    if (explained == nullptr || s.lever_effort_at_limit < explained->lever_effort_at_limit) explained = &s;
    // Past its grasp's limit the hand pushes with the limit: that is the effort.
    const double limit = g.grasp_limit[static_cast<size_t>(s.key.grasp)];
    for (size_t i = 0; i < s.points.size(); ++i) {
      seen[static_cast<size_t>(outcome(s.points[i]) + 1)].add(std::min(a.efforts[i], limit), s);
      for (size_t f = 0; f < g.functions.size(); ++f) inferred[f] = inferred[f] || s.points[i].first[f] >= 0;
    }
    for (const Threshold& t : s.thresholds) {
      for (size_t f = 0; f < g.functions.size(); ++f) inferred[f] = inferred[f] || t.at.first[f] >= 0;
      seen[static_cast<size_t>(t.to + 1)].add(std::min(t.effort, limit), s);
      seen[static_cast<size_t>(t.from + 1)].add(std::min(t.below, limit), s);
    }
  }
  if (explained != nullptr) {
    *out += "  the lever: " + q(a.limit, dim::force) + " at the " + a.name + " needs " +
            q(explained->lever_effort_at_limit, dim::force) + " at best, with " + where(g, explained->key) +
            " (mechanical advantage " + format_quantity(explained->mechanical_advantage, dim::none) +
            ", the spring included)\n";
  }
  for (int o : outcomes_by_strength(g)) {
    const Seen& s = seen[static_cast<size_t>(o + 1)];
    if (!s.any) continue;
    *out += "  ends in " + outcome_name(g, o) + ": from " + q(s.low, dim::force) + " (" + where(g, s.lowest->key) +
            ") to " + q(s.high, dim::force);
    std::string missing;
    for (size_t k = 0; k < g.grasps.size(); ++k) {
      if (!s.by_grasp[k]) missing += (missing.empty() ? "" : ", ") + g.grasps[k];
    }
    if (!missing.empty()) *out += "; never with " + missing;
    *out += "\n";
  }
  std::string never;
  for (size_t f = 0; f < g.functions.size(); ++f) {
    if (!inferred[f]) never += (never.empty() ? "" : ", ") + g.functions[f];
  }
  if (!never.empty()) *out += "  never inferred: " + never + "\n";
}

}  // namespace

std::vector<TurnSpan> turn_spans(const GridInfo& g, const ExploreResult& r) {
  std::vector<TurnSpan> spans;
  for (const SeriesResult& s : r.series) {
    for (const Threshold& t : s.thresholds) {
      const std::string actee = g.actees[static_cast<size_t>(s.key.actee)].name;
      const std::string from = outcome_name(g, t.from), to = outcome_name(g, t.to);
      auto same = [&](const TurnSpan& x) { return x.actee == actee && x.from == from && x.to == to; };
      auto it = std::find_if(spans.begin(), spans.end(), same);
      if (it == spans.end()) {
        spans.push_back({actee, from, to, t.effort, t.effort, &s, &s});
        continue;
      }
      if (t.effort < it->low) {
        it->low = t.effort;
        it->at_low = &s;
      }
      if (t.effort > it->high) {
        it->high = t.effort;
        it->at_high = &s;
      }
    }
  }
  return spans;
}

std::string turn_span_text(const GridInfo& g, const TurnSpan& t) {
  auto at = [&](const SeriesResult& s) {
    return where(g, s.key) + ", mechanical advantage " + format_quantity(s.mechanical_advantage, dim::none);
  };
  std::string text = t.actee + ": " + t.from + " turns to " + t.to + " from " + q(t.low, dim::force) + " (" + at(*t.at_low) + ")";
  if (t.at_high != t.at_low) text += " to " + q(t.high, dim::force) + " (" + at(*t.at_high) + ")";
  return text;
}

std::vector<int> outcomes_by_strength(const GridInfo& g) {
  std::vector<int> order = {-1};
  for (size_t rank = 0; rank < g.strength.size(); ++rank) {
    for (size_t f = 0; f < g.strength.size(); ++f) {
      if (g.strength[f] == static_cast<int>(rank)) order.push_back(static_cast<int>(f));
    }
  }
  return order;
}

std::string outcome_name(const GridInfo& g, int outcome) {
  return outcome < 0 ? std::string("none") : g.functions[static_cast<size_t>(outcome)];
}

std::string points_csv(const GridInfo& g, const ExploreResult& r) {
  std::string csv = "actee,placement_m,thumb_m,grasp,effort_N,applied_effort_N,outcome,applied_s";
  for (const std::string& f : g.functions) csv += "," + f + "_s";
  csv += ",peak_effort_N,peak_actee_force_N,broke_s\n";
  for (const SeriesResult& s : r.series) {
    const GridActee& a = g.actees[static_cast<size_t>(s.key.actee)];
    const std::string key = a.name + "," + exact(a.placements[static_cast<size_t>(s.key.placement)]) + "," +
                            exact(g.thumbs[static_cast<size_t>(s.key.thumb)]) + "," +
                            g.grasps[static_cast<size_t>(s.key.grasp)];
    for (size_t i = 0; i < s.points.size(); ++i) {
      const PointResult& p = s.points[i];
      const double effort = a.efforts[i];
      csv += key + "," + exact(effort) + "," + exact(applied_effort(g, s.key.grasp, effort)) + "," +
             outcome_name(g, outcome(p)) + "," + (p.applied_from >= 0 ? exact(p.applied_from) : std::string()) +
             first_times(p) + "," +
             exact(p.peak_effort) + "," + exact(p.peak_actee_force) + "," +
             (p.broke_at >= 0 ? exact(p.broke_at) : std::string()) + "\n";
    }
  }
  return csv;
}

std::string thresholds_csv(const GridInfo& g, const ExploreResult& r) {
  std::string csv =
      "actee,placement_m,thumb_m,grasp,from,to,effort_N,below_N,tolerance_N,mechanical_advantage,"
      "lever_effort_at_limit_N\n";
  for (const SeriesResult& s : r.series) {
    const GridActee& a = g.actees[static_cast<size_t>(s.key.actee)];
    for (const Threshold& t : s.thresholds) {
      csv += a.name + "," + exact(a.placements[static_cast<size_t>(s.key.placement)]) + "," +
             exact(g.thumbs[static_cast<size_t>(s.key.thumb)]) + "," + g.grasps[static_cast<size_t>(s.key.grasp)] +
             "," + outcome_name(g, t.from) + "," + outcome_name(g, t.to) + "," + exact(t.effort) + "," +
             exact(t.below) + "," + exact(g.tolerance) + "," + exact(s.mechanical_advantage) + "," +
             exact(s.lever_effort_at_limit) + "\n";
    }
  }
  return csv;
}

std::string summary_text(const GridInfo& g, const ExploreResult& r) {
  std::string out = "explored the " + g.object + ": " + count(g.actees.size(), "actee") + ", " +
                    count(g.thumbs.size(), "thumb position") + ", " + count(g.grasps.size(), "grasp") + ", " +
                    count(g.efforts.size(), "effort") + " up to " + q(g.efforts.back(), dim::force) +
                    (g.efforts_scaled ? " (each actee's scaled to where it turns)" : "") + "; thresholds to " +
                    q(g.tolerance, dim::force) + "\n" +
                    "  a point ends in the strongest function it reached while the hand applied the effort\n";
  for (size_t a = 0; a < g.actees.size(); ++a) summarise_actee(g, r, static_cast<int>(a), &out);
  return out;
}

std::vector<std::string> write_explore(const std::string& dir, const GridInfo& g, const ExploreResult& r) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path d(dir);
  std::vector<std::string> written;
  auto write = [&](const std::string& name, const std::string& text) {
    const std::string path = (d / name).string();
    write_file_checked(path, text);
    written.push_back(path);
  };
  write("points.csv", points_csv(g, r));
  write("thresholds.csv", thresholds_csv(g, r));
  write("summary.txt", summary_text(g, r));
  write("explore.json", explore_json(g, r));
  for (const std::string& path : write_maps((d / "maps").string(), g, r)) written.push_back(path);
  return written;
}

}  // namespace afford
