// The same grid in afford and in MuJoCo, to check the physics (issue 11,
// item 5): every point of a grid of the nutcracker (explore.h) run through
// the engine and, exported with afford export's scene (mjcf/), through
// MuJoCo 2.2.2 with the harness (mujoco_harness.h). Prints the agreement of
// the crash / no-crash verdicts, the difference of the crack times, and
// every point where the two disagree with what explains it.
//
//   afford_crosscheck SOURCE_DIR [THREADS]   (cmake --build build --target crosscheck)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "explore.h"
#include "mujoco_harness.h"
#include "observer.h"
#include "parallel.h"
#include "results.h"
#include "run.h"
#include "scripted_agent.h"

namespace afford {
namespace {

// MuJoCo's actee against the tool in one frame.
struct MujocoPush {
  double arm = 0;  // m, the force-weighted lever arm about the hinge of its contacts with the moving arm
  int fixed_contacts = 0, moving_contacts = 0;
};

struct Outcome {
  double afford_break = -1, mujoco_break = -1;  // s, -1: it did not break
  double afford_load = 0, mujoco_load = 0;      // N, the actee's largest load before it broke
  std::vector<double> afford_loads, mujoco_loads;  // N, the actee's load each frame
  // MuJoCo's actee is a free body (afford's stays where it was placed):
  // how far it moved and turned from its start by its crack or the end.
  double mujoco_moved = 0, mujoco_turned = 0;  // m, rad
  // Where the load acts: afford's lever arm of the actee's push (D_ac),
  // and MuJoCo's in the last frame before its crack or the end.
  double afford_arm = 0;  // m
  MujocoPush mujoco_push;
};

// An afford run's side of the outcome: the actee's load each frame, its
// largest before the break, and when it broke.
class LoadTrace : public Observer {
 public:
  explicit LoadTrace(Outcome* out) : out_(out) {}
  void on_frame(const Model&, const State& s, const RuleSet&, const RuleState&) override {
    out_->afford_loads.push_back(s.actee_force);
    if (s.actee_force > 0) out_->afford_arm = std::abs(s.load_distance);
    out_->afford_load = std::max(out_->afford_load, s.actee_force);
    if (out_->afford_break < 0 && s.condition == ActeeCondition::broken) out_->afford_break = s.t;
  }

 private:
  Outcome* out_;
};

// MuJoCo's actee against the tool now; the ids of the actee's and the
// moving arm's bodies and of the hinge.
MujocoPush mujoco_push(MujocoScene& scene, int actee, int moving, int hinge) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  const Eigen::Vector3d anchor(d->xanchor + 3 * hinge), axis(d->xaxis + 3 * hinge);
  MujocoPush push;
  double force = 0, moment = 0;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const int b1 = m->geom_bodyid[c.geom1], b2 = m->geom_bodyid[c.geom2];
    if (b1 != actee && b2 != actee) continue;
    if (b1 != moving && b2 != moving) {
      ++push.fixed_contacts;
      continue;
    }
    ++push.moving_contacts;
    mjtNum f[6];
    mj_contactForce(m, d, i, f);
    const Eigen::Vector3d p(c.pos), n(c.frame);
    force += f[0];
    moment += f[0] * std::abs((p - anchor).cross(n).dot(axis));
  }
  push.arm = force > 0 ? moment / force : 0.0;
  return push;
}

// When a load trace first passes `force` (s; -1: never), frames of `step` s.
double first_past(const std::vector<double>& loads, double force, double step) {
  for (size_t k = 0; k < loads.size(); ++k) {
    if (loads[k] > force) return static_cast<double>(k + 1) * step;
  }
  return -1;
}

// A load trace at time t (s), frames of `step` s from the first at `step`.
double load_at(const std::vector<double>& loads, double t, double step) {
  if (loads.empty()) return 0;
  const auto k = static_cast<size_t>(std::clamp(std::lround(t / step) - 1, 0L, static_cast<long>(loads.size()) - 1));
  return loads[k];
}

// A grid point as a session MuJoCo's scene is exported from: the point's
// model and script (named uniquely: the harness's file is named after it).
CompiledSession point_session(const Explorer& e, const GridPoint& p, size_t index) {
  CompiledSession s;
  s.name = "crosscheck-" + std::to_string(index);
  s.file = s.name;
  s.description = "a point of afford_crosscheck's grid";
  s.model = *e.models[static_cast<size_t>(p.actee)][static_cast<size_t>(p.placement)];
  s.rules = e.rules;
  PointDrive drive;
  drive.thumb = e.grid.thumbs[static_cast<size_t>(p.thumb)];
  drive.grasp = e.grasp_types[static_cast<size_t>(p.grasp)];
  drive.effort = e.grid.efforts[static_cast<size_t>(p.effort)];
  s.script = point_script(s.model, e.jaws[static_cast<size_t>(p.actee)][static_cast<size_t>(p.placement)], drive,
                          e.timing);
  return s;
}

int crosscheck(const std::string& source, int threads) {
  ExploreFiles f;
  f.object = source + "/objects/nutcracker.yaml";
  f.agent = source + "/agents/hand.yaml";
  f.rules = source + "/rules/functions.yaml";
  f.grasps = source + "/rules/grasps.yaml";
  for (const char* a : {"walnut", "hazelnut", "peanut"}) f.actees.push_back(source + "/actees/" + a + ".yaml");
  GridOptions grid;
  grid.placements = 2;
  grid.thumbs = 2;
  grid.efforts = 6;
  grid.grasps = {"medium_wrap"};
  const Explorer e = make_explorer(f, grid);
  // afford's own thresholds, to say how close a point that disagrees is to one.
  const ExploreResult thresholds = explore(e, Shard{}, threads);

  const std::vector<GridPoint> points = grid_points(e.grid);
  std::vector<Outcome> out(points.size());
  std::mutex loading;  // MuJoCo's XML loader is not documented as thread-safe
  parallel_for(points.size(), threads, [&](size_t i) {
    const CompiledSession session = point_session(e, points[i], i);
    {  // the point as run_point runs it, its load kept frame by frame
      ScriptedAgent agent(session.script);
      LoadTrace trace(&out[i]);
      Observer* observers[] = {&trace};
      run_session(session, *e.rules, agent, observers);
    }
    std::unique_lock<std::mutex> lock(loading);
    MujocoScene scene(session);
    lock.unlock();
    const int frames = static_cast<int>(std::floor(scene.duration() / session.model.timestep + 1e-9));
    // The actee's free joint: position, then orientation (w, x, y, z).
    const mjtNum* q = scene.data()->qpos + scene.model()->jnt_qposadr[mj_name2id(scene.model(), mjOBJ_JOINT, "actee")];
    const Eigen::Vector3d start_pos(q[0], q[1], q[2]);
    const Eigen::Quaterniond start_quat(q[3], q[4], q[5], q[6]);
    const int actee_body = mj_name2id(scene.model(), mjOBJ_BODY, "actee");
    const int moving_body = mj_name2id(scene.model(), mjOBJ_BODY, "moving_arm");
    const int hinge = mj_name2id(scene.model(), mjOBJ_JOINT, "hinge");
    for (int k = 1; k <= frames; ++k) {
      const double load = scene.actee_load();
      const bool broke = scene.frame();
      out[i].mujoco_moved = (Eigen::Vector3d(q[0], q[1], q[2]) - start_pos).norm();
      out[i].mujoco_turned = start_quat.angularDistance(Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized());
      if (broke) {
        out[i].mujoco_break = scene.data()->time;
        break;
      }
      out[i].mujoco_load = std::max(out[i].mujoco_load, std::max(load, scene.actee_load()));
      out[i].mujoco_loads.push_back(scene.actee_load());
      out[i].mujoco_push = mujoco_push(scene, actee_body, moving_body, hinge);
    }
  });

  // afford's cracking threshold of a point's series, N (-1: none).
  auto threshold_of = [&](const GridPoint& p) {
    for (const SeriesResult& s : thresholds.series) {
      if (s.key.actee != p.actee || s.key.placement != p.placement || s.key.thumb != p.thumb) continue;
      for (const Threshold& t : s.thresholds) {
        if (t.at.broke_at >= 0) return t.effort;
      }
    }
    return -1.0;
  };
  auto where = [&](const GridPoint& p) {
    const GridActee& actee = e.grid.actees[static_cast<size_t>(p.actee)];
    const double effort = e.grid.efforts[static_cast<size_t>(p.effort)];
    const double threshold = threshold_of(p);
    char text[200];
    std::snprintf(text, sizeof text, "%s at %.0f mm, thumb %.0f mm, %.0f N (%+.1f %% from afford's threshold %.1f N)",
                  actee.name.c_str(), 1e3 * actee.placements[static_cast<size_t>(p.placement)],
                  1e3 * e.grid.thumbs[static_cast<size_t>(p.thumb)], effort,
                  threshold > 0 ? 100 * (effort / threshold - 1) : 0.0, threshold);
    return std::string(text);
  };

  int agree = 0, both = 0;
  std::vector<double> dt_ms;
  std::printf("afford_crosscheck: %zu points of the nutcracker (walnut, hazelnut, peanut; 2 placements, 2 thumbs,\n"
              "medium_wrap, %zu efforts from 0 to %.0f N), afford and MuJoCo 2.2.2\n\n",
              points.size(), e.grid.efforts.size(), e.grid.efforts.back());
  std::printf("disagreements:\n");
  for (size_t i = 0; i < points.size(); ++i) {
    const Outcome& o = out[i];
    const bool a = o.afford_break >= 0, m = o.mujoco_break >= 0;
    if (a && m) {
      ++both;
      dt_ms.push_back(1e3 * (o.mujoco_break - o.afford_break));
    }
    if (a == m) {
      ++agree;
      continue;
    }
    std::printf("  %s: afford %s, MuJoCo %s; the largest load before a break: afford %.1f N, MuJoCo %.1f N (%+.1f %%)\n",
                where(points[i]).c_str(), a ? "cracks" : "does not crack", m ? "cracks" : "does not crack",
                o.afford_load, o.mujoco_load, o.afford_load > 0 ? 100 * (o.mujoco_load / o.afford_load - 1) : 0.0);
  }
  if (agree == static_cast<int>(points.size())) std::printf("  none\n");
  // A crack time is the time the load takes to reach the limit: where it
  // nears the limit slowly, a small difference of load is a long time.
  // At the first engine's crack, how far the other's load is from the
  // limit, and how fast it was rising before its own crack.
  std::printf("cracks more than 20 ms apart, with the other engine's load at the first crack:\n");
  double largest_shortfall = 0;  // of the limit, at the first crack
  for (size_t i = 0; i < points.size(); ++i) {
    const Outcome& o = out[i];
    if (o.afford_break < 0 || o.mujoco_break < 0 || std::abs(o.mujoco_break - o.afford_break) <= 0.020) continue;
    const Model& model = *e.models[static_cast<size_t>(points[i].actee)][static_cast<size_t>(points[i].placement)];
    const double step = model.timestep, limit = model.actee_limit;
    const bool afford_first = o.afford_break < o.mujoco_break;
    const std::vector<double>& later = afford_first ? o.mujoco_loads : o.afford_loads;
    const double first = afford_first ? o.afford_break : o.mujoco_break;
    const double last = afford_first ? o.mujoco_break : o.afford_break;
    const double load = load_at(later, first, step);
    const double rate = (load_at(later, last - step, step) - load_at(later, last - 0.020, step)) / (0.020 - step);  // N/s
    largest_shortfall = std::max(largest_shortfall, 1 - load / limit);
    const MujocoPush& push = o.mujoco_push;
    // Where the loads part: when each first passes a tenth and a half of the limit.
    const double tenth_a = first_past(o.afford_loads, 0.1 * limit, step), tenth_m = first_past(o.mujoco_loads, 0.1 * limit, step);
    const double half_a = first_past(o.afford_loads, 0.5 * limit, step), half_m = first_past(o.mujoco_loads, 0.5 * limit, step);
    std::printf("  %s: afford %.3f s, MuJoCo %.3f s; at %s's crack %s's load is %.1f N, %.1f %% below the %.0f N "
                "limit, rising at %.0f N/s; a tenth of the limit at %.3f and %.3f s, half at %.3f and %.3f s; MuJoCo's "
                "actee moved %.2f mm and turned %.1f deg; the load's lever arm: afford %.1f mm, MuJoCo %.1f mm; MuJoCo's actee "
                "has %d contacts with the fixed arm and %d with the moving arm\n",
                where(points[i]).c_str(), o.afford_break, o.mujoco_break, afford_first ? "afford" : "MuJoCo",
                afford_first ? "MuJoCo" : "afford", load, 100 * (1 - load / limit), limit, rate, tenth_a, tenth_m,
                half_a, half_m, 1e3 * o.mujoco_moved, o.mujoco_turned * 180 / 3.14159265358979323846,
                1e3 * o.afford_arm, 1e3 * push.arm, push.fixed_contacts, push.moving_contacts);
  }
  std::sort(dt_ms.begin(), dt_ms.end());
  const double median = dt_ms.empty() ? 0 : dt_ms[dt_ms.size() / 2];
  double worst = 0;
  for (double d : dt_ms) worst = std::max(worst, std::abs(d));
  std::printf("\nverdicts agree: %d of %zu (%.1f %%; goal 99 %%)\n", agree, points.size(),
              100.0 * agree / static_cast<double>(points.size()));
  std::printf("crack time, MuJoCo - afford, where both crack (%d points): median %+.1f ms, largest |%.1f| ms (goal 20 ms)\n",
              both, median, worst);
  std::printf("where they crack more than 20 ms apart, the later engine's load at the first crack is at most %.1f %% "
              "below the limit\n", 100 * largest_shortfall);
  return 0;
}

}  // namespace
}  // namespace afford

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: afford_crosscheck SOURCE_DIR [THREADS]\n");
    return 2;
  }
  try {
    return afford::crosscheck(argv[1], argc > 2 ? std::max(1, std::atoi(argv[2])) : afford::default_threads());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "afford_crosscheck: %s\n", e.what());
    return 1;
  }
}
