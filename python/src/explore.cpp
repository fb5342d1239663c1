// afford.explore: one tool over actees, placements, thumbs, grasp types and
// efforts (explore/explore.h), on every core with the GIL released, as a
// table: a dict of NumPy columns, one row per point, the columns of
// points.csv (explore/reports.cpp) with NaN where the CSV leaves a cell empty.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <string>
#include <vector>

#include "arrays.h"
#include "bindings.h"
#include "effort_axes.h"
#include "parallel.h"
#include "reports.h"
#include "results.h"

namespace afford::python {
namespace {

constexpr double kNever = std::numeric_limits<double>::quiet_NaN();

double or_never(double t) { return t >= 0 ? t : kNever; }

// A column of text as a NumPy object array (pandas' own kind of text column).
py::array strings(const std::vector<std::string>& values) {
  py::list cells;
  for (const std::string& v : values) cells.append(py::str(v));
  return py::module_::import("numpy").attr("array")(cells, py::arg("dtype") = "object");
}

py::dict points_table(const GridInfo& g, const ExploreResult& r) {
  std::vector<std::string> actee, grasp, outcome_of;
  std::vector<double> placement, thumb, effort, applied_effort_n, applied_s, peak_effort, peak_actee_force, broke;
  std::vector<std::vector<double>> first(g.functions.size());
  for (const SeriesResult& s : r.series) {
    const GridActee& a = g.actees[static_cast<size_t>(s.key.actee)];
    for (size_t i = 0; i < s.points.size(); ++i) {
      const PointResult& p = s.points[i];
      actee.push_back(a.name);
      placement.push_back(a.placements[static_cast<size_t>(s.key.placement)]);
      thumb.push_back(g.thumbs[static_cast<size_t>(s.key.thumb)]);
      grasp.push_back(g.grasps[static_cast<size_t>(s.key.grasp)]);
      effort.push_back(a.efforts[i]);
      applied_effort_n.push_back(applied_effort(g, s.key.grasp, a.efforts[i]));
      outcome_of.push_back(outcome_name(g, outcome(p)));
      applied_s.push_back(or_never(p.applied_from));
      for (size_t f = 0; f < first.size(); ++f) first[f].push_back(or_never(p.first[f]));
      peak_effort.push_back(p.peak_effort);
      peak_actee_force.push_back(p.peak_actee_force);
      broke.push_back(or_never(p.broke_at));
    }
  }
  py::dict d;
  d["actee"] = strings(actee);
  d["placement_m"] = as_array(std::move(placement));
  d["thumb_m"] = as_array(std::move(thumb));
  d["grasp"] = strings(grasp);
  d["effort_N"] = as_array(std::move(effort));
  d["applied_effort_N"] = as_array(std::move(applied_effort_n));
  d["outcome"] = strings(outcome_of);
  d["applied_s"] = as_array(std::move(applied_s));
  for (size_t f = 0; f < first.size(); ++f) d[py::str(g.functions[f] + "_s")] = as_array(std::move(first[f]));
  d["peak_effort_N"] = as_array(std::move(peak_effort));
  d["peak_actee_force_N"] = as_array(std::move(peak_actee_force));
  d["broke_s"] = as_array(std::move(broke));
  return d;
}

py::dict run_explore(const std::string& object, const std::vector<std::string>& actees, const std::string& agent,
                     const std::string& rules, const std::string& taxonomy, const GridOptions& grid, int threads) {
  ExploreFiles files{object, agent, rules, taxonomy, actees};
  Explorer e;
  ExploreResult result;
  {
    py::gil_scoped_release unlocked;  // every core works; other Python threads go on meanwhile
    e = make_explorer(files, grid);  // DataError, GridError (ValueError)
    const int n = threads > 0 ? threads : default_threads();
    if (grid.scale_efforts) fit_effort_axes(e, n);
    result = explore(e, Shard{}, n);
  }
  return points_table(e.grid, result);
}

}  // namespace

void bind_explore(py::module_& m) {
  m.def(
      "explore",
      [](const std::string& object, const std::vector<std::string>& actees, const std::string& agent,
         const std::string& rules, const std::string& taxonomy, int placements, int thumbs, int efforts,
         double max_effort, bool fixed_efforts, const std::vector<std::string>& grasps, double tolerance, int threads) {
        GridOptions grid;
        grid.placements = placements;
        grid.thumbs = thumbs;
        grid.efforts = efforts;
        grid.max_effort = max_effort;
        grid.scale_efforts = !fixed_efforts;
        grid.grasps = grasps;
        grid.tolerance = tolerance;
        return run_explore(object, actees, agent, rules, taxonomy, grid, threads);
      },
      py::arg("object"), py::arg("actees"), py::arg("agent"), py::arg("rules"), py::arg("taxonomy"),
      py::arg("placements"), py::arg("thumbs"), py::arg("efforts"), py::arg("max_effort"), py::arg("fixed_efforts"),
      py::arg("grasps"), py::arg("tolerance"), py::arg("threads"));
}

}  // namespace afford::python
