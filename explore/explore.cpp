#include "explore.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "derive.h"
#include "grid_axis.h"
#include "outcome.h"
#include "did_you_mean.h"
#include "errors.h"
#include "grasps.h"
#include "load.h"
#include "observer.h"
#include "run.h"
#include "scripted_agent.h"
#include "units.h"

namespace afford {
namespace {

void check_count(int n, const char* what) {
  if (n < 1 || n > kMaxPerAxis) {
    throw GridError(std::string(what) + ": expected a count from 1 to " + std::to_string(kMaxPerAxis) + ", found " +
                     std::to_string(n));
  }
}

// Watches a point's session: the peaks, whether the actee broke, when each
// function was first inferred and which were reached while the effort was
// applied (from the frame's events, without the explanations).
class PointObserver : public Observer {
 public:
  PointObserver(PointResult* r, std::vector<int> strength, double applied_at)
      : r_(r), watch_(std::move(strength), applied_at) {}
  void on_frame(const Model&, const State& s, const RuleSet&, const RuleState& rs) override {
    r_->peak_effort = std::max(r_->peak_effort, s.effort_force);
    r_->peak_actee_force = std::max(r_->peak_actee_force, s.actee_force);
    const bool broken = s.condition == ActeeCondition::broken;
    if (r_->broke_at < 0 && broken) r_->broke_at = s.t;
    for (const Event* ev = events_begin(rs); ev != events_end(rs); ++ev) {
      double& first = r_->first[static_cast<size_t>(ev->function)];
      if (ev->kind == EventKind::inferred && first < 0) first = tidy(ev->t);
    }
    watch_.frame(s.t, events_begin(rs), events_end(rs), broken, s.grasped);
  }
  const OutcomeWatch& watch() const { return watch_; }

 private:
  PointResult* r_;
  OutcomeWatch watch_;
};

}  // namespace

Explorer make_explorer(const ExploreFiles& files, const GridOptions& grid) {
  check_count(grid.placements, "--placements");
  check_count(grid.thumbs, "--thumbs");
  check_count(grid.efforts, "--efforts");
  if (!(grid.tolerance > 0 && grid.tolerance <= 100)) {
    throw GridError("--tolerance: expected a force above 0 N and at most 100 N, found " +
                     format_quantity(grid.tolerance, dim::force));
  }
  Explorer e;
  GridInfo& g = e.grid;
  g.tolerance = grid.tolerance;
  const ObjectSpec object = load_object(files.object);
  const AgentSpec agent = load_agent(files.agent);
  ModelOptions options;
  options.grasps = load_grasps(files.grasps);
  e.rules = load_rules(files.rules);
  for (int f = 0; f < function_count(*e.rules); ++f) {
    g.functions.push_back(function_name(*e.rules, f));
    g.strength.push_back(function_strength(*e.rules, f));
  }

  // The tool and hand alone: the regions, the taxonomy, the hand's limits.
  const Model bare = compile(object, nullptr, &agent, options);
  g.object = bare.object_name;
  const double max_effort = grid.max_effort > 0 ? grid.max_effort : bare.max_force;
  if (!(max_effort <= bare.max_force)) {
    throw GridError("--max-effort: expected at most the hand's limit " + format_quantity(bare.max_force, dim::force) +
                     ", found " + format_quantity(max_effort, dim::force));
  }
  g.thumbs = spread(bare.emphasis_from, bare.emphasis_to, grid.thumbs);
  // From just touching (0 N) up: the thresholds' bisections then cover
  // every effort the hand can give. One effort: the largest.
  g.efforts = grid.efforts == 1 ? std::vector<double>{max_effort} : spread(0, max_effort, grid.efforts);

  if (bare.grasp_name.empty()) {
    e.grasp_types = {-1};
    g.grasps = {"-"};
    g.grasp_limit = {bare.max_force};
  }
  const std::vector<std::string> wanted = grid.grasps.empty() ? bare.grasp_name : grid.grasps;
  for (const std::string& name : bare.grasp_name.empty() ? std::vector<std::string>{} : wanted) {
    const auto it = std::find(bare.grasp_name.begin(), bare.grasp_name.end(), name);
    if (it == bare.grasp_name.end()) {
      throw GridError("--grasps: " + name + " is not a grasp type of " + files.grasps +
                       did_you_mean(name, bare.grasp_name));
    }
    const int type = static_cast<int>(it - bare.grasp_name.begin());
    JointAngles posture{};
    std::string why;
    // A type the hand cannot form is left out only when not asked for by name.
    if (!grasp_posture(bare, type, &posture, &why)) {
      if (!grid.grasps.empty()) throw GridError("--grasps: the hand cannot form " + name + ": " + why);
      continue;
    }
    e.grasp_types.push_back(type);
    g.grasps.push_back(name);
    g.grasp_limit.push_back(std::min(bare.max_force, bare.grasp_max_force[static_cast<size_t>(type)]));
  }

  if (g.grasps.empty()) throw GridError("the hand can form no grasp type of " + files.grasps);

  for (const std::string& file : files.actees) {
    const ActeeSpec a = load_actee(file);
    GridActee entry;
    entry.name = a.name;
    entry.file = file;
    entry.limit = a.limit;
    entry.breaks = a.breaks;
    ModelOptions anywhere = options;
    anywhere.actee.in_jaws = false;  // fit_actee places it itself
    const ActeeFit fit = fit_actee(compile(object, &a, &agent, anywhere));
    entry.fits = fit.fits;
    entry.why = fit.why;
    if (fit.fits) entry.efforts = g.efforts;  // until fit_effort_axes() scales it
    std::vector<std::shared_ptr<const Model>> models;
    std::vector<ForcedLever> jaws;
    if (fit.fits) {
      entry.placements = spread(fit.from, fit.to, grid.placements);
      for (double at : entry.placements) {
        ModelOptions placed = options;
        placed.actee.distance = at;
        models.push_back(std::make_shared<const Model>(compile(object, &a, &agent, placed)));
        jaws.push_back(lever_at_start(*models.back()));
      }
    }
    g.actees.push_back(std::move(entry));
    e.models.push_back(std::move(models));
    e.jaws.push_back(std::move(jaws));
  }

  long long points = 0;
  for (const GridActee& a : g.actees) points += static_cast<long long>(a.placements.size());
  points *= static_cast<long long>(g.thumbs.size() * g.grasps.size() * g.efforts.size());
  if (grid.scale_efforts) points *= 2;  // the common axis first, to find where each actee turns
  if (points > kMaxPoints) {
    throw GridError("the grid has " + std::to_string(points) + " points, more than " + std::to_string(kMaxPoints) +
                     ": fewer --placements, --thumbs, --efforts or --grasps, or run it in --shard parts");
  }
  return e;
}

double applied_effort(const GridInfo& g, int grasp, double effort_n) {
  return std::min(effort_n, g.grasp_limit[static_cast<size_t>(grasp)]);
}

PointResult run_point(const Explorer& e, const GridPoint& p) {
  return run_point(e, p, e.grid.actees[static_cast<size_t>(p.actee)].efforts[static_cast<size_t>(p.effort)]);
}

PointResult run_point(const Explorer& e, const GridPoint& p, double effort_n) {
  const Model& model = *e.models[static_cast<size_t>(p.actee)][static_cast<size_t>(p.placement)];
  PointDrive drive;
  drive.thumb = e.grid.thumbs[static_cast<size_t>(p.thumb)];
  drive.grasp = e.grasp_types[static_cast<size_t>(p.grasp)];
  drive.effort = applied_effort(e.grid, p.grasp, effort_n);
  const Script script = point_script(model, e.jaws[static_cast<size_t>(p.actee)][static_cast<size_t>(p.placement)], drive,
                                     e.timing);
  ScriptedAgent agent(script);
  PointResult r;
  r.first.assign(e.grid.functions.size(), -1.0);
  // The push reaches the effort at the end of the squeeze (point_session.h).
  PointObserver observer(&r, e.grid.strength, e.timing.close + e.timing.squeeze);
  Observer* observers[] = {&observer};
  run_session(model, *e.rules, agent, observers);
  r.outcome = observer.watch().outcome();
  r.applied_from = tidy(observer.watch().window_from());
  if (r.broke_at >= 0) r.broke_at = tidy(r.broke_at);
  return r;
}

}  // namespace afford
