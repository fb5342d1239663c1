// afford guide OBJECT [--actees DIR] [--guides FILE] [--explored DIR] [--json]:
// the guides of the paper (Sec. 4.4) for an object, computed as
// rules/guides.yaml says: as text, or as one JSON object (SI units, the
// object frame) holding the facts and the geometry a renderer draws. The
// actees and the guides are the shipped ones (data_dir.h) unless --actees
// or --guides names others. Where afford explore has run on the object
// (--explored DIR, or out/explore-OBJECT), the efforts at which its outcomes
// turn make "amplify or decline" concrete.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "data_dir.h"
#include "explore_json.h"
#include "reports.h"
#include "option_checks.h"
#include "quantity_text.h"
#include "guides.h"
#include "json_output.h"
#include "lever.h"
#include "load.h"
#include "model.h"

namespace afford::cli {
namespace {

std::string plain(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", std::abs(v) < 5e-13 ? 0.0 : v);
  return buf;
}

std::string fixed2(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

// ---------------------------------------------------------------- text

std::string rotation_text(const Eigen::Matrix3d& r) {
  const Eigen::AngleAxisd aa(r);
  if (std::abs(aa.angle()) < 1e-9) return "not turned";
  const Eigen::Vector3d& a = aa.axis();
  return "turned " + q(aa.angle(), dim::angle) + " about [" + plain(a.x()) + ", " + plain(a.y()) + ", " +
         plain(a.z()) + "]";
}

// Where along the arm pushing magnifies force and where distance: the runs
// of the advantage map's segments on the fixed arm.
void print_runs(const Guides& g, int index) {
  bool open = false, force = false;
  double from = 0, to = 0;
  auto flush = [&] {
    if (!open) return;
    std::cout << "    " << (force ? "magnifies force    " : "magnifies distance") << " from " << q(from, dim::length)
              << " to " << q(to, dim::length) << "\n";
  };
  for (const GuideSegment& s : g.segments) {
    if (s.guide != index || s.frame != Arm::fixed) continue;
    const double r0 = std::min(s.a.x(), s.b.x()), r1 = std::max(s.a.x(), s.b.x());
    const bool f = s.value >= 1;
    if (open && f == force && std::abs(r0 - to) < 1e-9) {
      to = r1;
      continue;
    }
    flush();
    open = true;
    force = f;
    from = r0;
    to = r1;
  }
  flush();
}

// The stable orientation's torques at rest, and what they mean for the
// tool left alone that way up; where the functional pose is not that
// orientation, why the file may have laid it otherwise.
void print_stable_turn(const GuideFacts& f) {
  const double hold = f.spring_at_rest + f.friction_at_rest;  // N*m, what keeps the arm open against a closing weight
  const bool parallel = f.plane_to_gravity == 0;
  if (parallel) {
    std::cout << "  as it stands (the moving arm " << (f.stable_turn == 0 ? "above" : "below")
              << ") and turned over:\n";
  } else {
    std::cout << "  turned " << q(f.stable_turn, dim::angle) << " about its length, the plane parallel to gravity:\n";
  }
  auto way = [&](const char* where, double weight) {
    std::cout << "    the moving arm " << where << ": its weight " << q(std::abs(weight), dim::torque)
              << (weight < 0 ? " closing" : " opening") << " at rest";
    if (weight >= 0) {
      std::cout << ", the arm rests open\n";
    } else if (-weight <= hold) {
      std::cout << ", against the spring's " << q(f.spring_at_rest, dim::torque) << " and the pivot's "
                << q(f.friction_at_rest, dim::torque) << ": the arm rests open\n";
    } else {
      std::cout << ", more than the spring's " << q(f.spring_at_rest, dim::torque) << " and the pivot's "
                << q(f.friction_at_rest, dim::torque) << ": the arm falls closed unless held\n";
    }
  };
  way("above", f.weight_above);
  way("below", f.weight_below);
  if (parallel) return;
  // Why the file's pose may not be the stable one: a weight that outdoes
  // the spring sets the arm's rest on edge, whichever way up.
  const double weight = std::max(std::abs(f.weight_above), std::abs(f.weight_below));
  if (weight > hold) {
    std::cout << "  why not on edge: the arm's weight is " << plain(weight / f.spring_at_rest)
              << " times the spring's torque at rest; on edge the weight, not the spring, sets where the arm rests "
                 "(shut with the moving arm above, hanging open below), so the functional pose lays the plane level, "
                 "where only the spring acts\n";
  } else {
    std::cout << "  the spring holds the arm open either way up: the functional pose could stand the tool on edge\n";
  }
}

void print_text(const Guides& g, const std::string& guides_file, const std::string& actee_dir) {
  const GuideFacts& f = g.facts;
  std::cout << "guides for " << g.object << " (" << guides_file << "), lever " << pattern_name(f.pattern) << "\n";
  for (size_t i = 0; i < g.guides.size(); ++i) {
    const GuideSpec& s = g.guides[i];
    std::cout << s.name << " (" << guide_kind_name(s.kind) << "): " << s.description << "\n";
    switch (s.kind) {
      case GuideKind::symmetry_plane:
        std::cout << "  plane of symmetry through " << qv(f.symmetry_point, dim::length) << ", normal ["
                  << plain(f.symmetry_normal.x()) << ", " << plain(f.symmetry_normal.y()) << ", "
                  << plain(f.symmetry_normal.z()) << "] (object frame)\n";
        std::cout << "  functional pose: object frame at " << qv(f.functional_pose.translation(), dim::length)
                  << " in the world, " << rotation_text(f.functional_pose.linear()) << "\n";
        std::cout << "  at the functional pose the plane is " << q(f.plane_to_gravity, dim::angle)
                  << " from gravity ("
                  << (f.plane_to_gravity < 0.1 ? "parallel: the stable orientation of Sec. 4.4"
                                               : "Sec. 4.4: most stable with the plane parallel to gravity")
                  << ")\n";
        if (f.stable_turn_found) print_stable_turn(f);
        break;
      case GuideKind::interaction_space:
        std::cout << "  interaction space: from " << q(f.space.from, dim::length) << " to "
                  << q(f.space.to, dim::length) << " along the arm, jaw opening at theta_max "
                  << q(f.space.gap_from, dim::length) << " to " << q(f.space.gap_to, dim::length) << "\n";
        if (f.space.from_shape) {
          std::cout << "  from the tool's shape (interaction_space), the gap fully open:";
          for (size_t k = 0; k < f.space.distances.size(); ++k) {
            std::cout << (k > 0 ? "," : "") << " " << q(f.space.gaps[k], dim::length) << " at "
                      << q(f.space.distances[k], dim::length);
          }
          std::cout << "\n";
        }
        if (f.actees.empty()) {
          std::cout << "  no actees in " << actee_dir << "\n";
          break;
        }
        std::cout << "  actees in " << actee_dir << ":\n";
        for (const ActeeFit& fit : f.actees) {
          if (fit.fits) {
            std::printf("    %-12s fits from %s to %s; jaws touch at %s; its limit needs %s at the emphasis end\n",
                        fit.name.c_str(), q(fit.from, dim::length).c_str(), q(fit.to, dim::length).c_str(),
                        q(fit.contact_angle, dim::angle).c_str(), q(fit.effort_to_limit, dim::force).c_str());
          } else {
            std::printf("    %-12s does not fit: %s\n", fit.name.c_str(), fit.why.c_str());
          }
        }
        break;
      case GuideKind::emphasis: {
        int faces = 0;
        for (const GuideRect& r : g.rects) faces += r.guide == static_cast<int>(i);
        std::cout << "  push from " << q(f.emphasis_from, dim::length) << " to " << q(f.emphasis_to, dim::length)
                  << " along the arms, " << faces << " face" << (faces == 1 ? "" : "s") << ":\n";
        for (const GuideRect& r : g.rects) {
          if (r.guide != static_cast<int>(i)) continue;
          std::cout << "    " << (r.frame == Arm::fixed ? "fixed arm " : "moving arm") << " face at "
                    << qv(r.centre, dim::length) << ", facing [" << plain(r.normal.x()) << ", "
                    << plain(r.normal.y()) << ", " << plain(r.normal.z()) << "], " << q(2 * r.half_u, dim::length)
                    << " by " << q(2 * r.half_v, dim::length) << "\n";
        }
        break;
      }
      case GuideKind::advantage:
        std::cout << "  load at " << q(f.load_at, dim::length) << "; mechanical advantage over the emphasis "
                  << fixed2(f.ma_min) << " to " << fixed2(f.ma_max) << " ("
                  << (f.ma_min >= 1 ? "amplifies force" : f.ma_max <= 1 ? "amplifies distance" : "both")
                  << "), along the arm " << fixed2(f.ma_arm_min) << " to " << fixed2(f.ma_arm_max) << "\n";
        std::cout << "  along the arm, pushing there:\n";
        print_runs(g, static_cast<int>(i));
        break;
    }
  }
  auto count = [](size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  std::cout << "geometry: " << count(g.rects.size(), "rectangle", "rectangles") << ", "
            << count(g.meshes.size(), "mesh", "meshes") << ", " << count(g.segments.size(), "segment", "segments")
            << ", " << count(g.labels.size(), "label", "labels")
            << " (afford guide --json)\n";
}

// ---------------------------------------------------------------- JSON

// Rounding noise below 1e-15 is printed as 0.
Json num(double v) { return json_number(std::abs(v) < 1e-15 ? 0.0 : v); }

Json vec(const Eigen::Vector3d& v) { return {num(v.x()), num(v.y()), num(v.z())}; }

Json colour(const GuideColour& c) { return {num(c.r), num(c.g), num(c.b), num(c.a)}; }

// The fields every drawn element starts with.
Json head(int guide, Arm frame) { return {{"guide", guide}, {"frame", frame == Arm::fixed ? "fixed" : "moving"}}; }

template <typename T, typename F>
Json list(const std::vector<T>& items, F item) {
  Json j = Json::array();
  for (const T& x : items) j.push_back(item(x));
  return j;
}

void print_json(const Guides& g, const Json& thresholds) {
  const GuideFacts& f = g.facts;
  const Eigen::Matrix3d r = f.functional_pose.linear();
  Json facts = {
      {"pattern", pattern_name(f.pattern)},
      {"symmetry_plane", {{"point", vec(f.symmetry_point)}, {"normal", vec(f.symmetry_normal)}}},
      {"functional_pose",
       {{"position", vec(f.functional_pose.translation())}, {"rotation", {vec(r.row(0)), vec(r.row(1)), vec(r.row(2))}}}},
      {"plane_to_gravity", num(f.plane_to_gravity)},
      {"stable_orientation",
       f.stable_turn_found ? Json{{"turn", num(f.stable_turn)},
                                  {"weight_above", num(f.weight_above)},
                                  {"weight_below", num(f.weight_below)},
                                  {"spring_at_rest", num(f.spring_at_rest)},
                                  {"friction_at_rest", num(f.friction_at_rest)}}
                           : Json(nullptr)},
      {"interaction_space",
       {{"from", num(f.space.from)}, {"to", num(f.space.to)}, {"gap_from", num(f.space.gap_from)},
        {"gap_to", num(f.space.gap_to)}}},
      {"actees", list(f.actees,
                      [](const ActeeFit& a) {
                        return Json{{"name", a.name},
                                    {"fits", a.fits},
                                    {"from", num(a.from)},
                                    {"to", num(a.to)},
                                    {"contact_angle", num(a.contact_angle)},
                                    {"effort_to_limit", num(a.effort_to_limit)},
                                    {"why", a.why}};
                      })},
      {"emphasis", {{"from", num(f.emphasis_from)}, {"to", num(f.emphasis_to)}}},
      {"advantage",
       {{"load_at", num(f.load_at)}, {"ma_min", num(f.ma_min)}, {"ma_max", num(f.ma_max)},
        {"ma_arm_min", num(f.ma_arm_min)}, {"ma_arm_max", num(f.ma_arm_max)}}}};
  Json j = {{"object", g.object},
            {"guides", list(g.guides,
                            [](const GuideSpec& s) {
                              return Json{{"name", s.name},
                                          {"kind", guide_kind_name(s.kind)},
                                          {"description", s.description},
                                          {"colour", colour(s.colour)}};
                            })},
            {"facts", facts}};
  j["rects"] = list(g.rects, [](const GuideRect& x) {
    Json e = head(x.guide, x.frame);
    e.update(Json{{"centre", vec(x.centre)}, {"u", vec(x.u)}, {"v", vec(x.v)}, {"normal", vec(x.normal)},
                  {"half_u", num(x.half_u)}, {"half_v", num(x.half_v)}, {"colour", colour(x.colour)}});
    return e;
  });
  j["meshes"] = list(g.meshes, [](const GuideMesh& x) {
    Json e = head(x.guide, x.frame);
    e.update(Json{{"vertices", list(x.vertices, vec)}, {"triangles", x.triangles}, {"colour", colour(x.colour)}});
    return e;
  });
  j["segments"] = list(g.segments, [](const GuideSegment& x) {
    Json e = head(x.guide, x.frame);
    e.update(Json{{"a", vec(x.a)}, {"b", vec(x.b)}, {"colour", colour(x.colour)}, {"value", num(x.value)},
                  {"distance", num(x.distance)}});
    return e;
  });
  j["labels"] = list(g.labels, [](const GuideLabel& x) {
    Json e = head(x.guide, x.frame);
    e.update(Json{{"text", x.text}, {"anchor", vec(x.anchor)}, {"colour", colour(x.colour)}});
    return e;
  });
  if (!thresholds.is_null()) j["thresholds"] = thresholds;  // where afford explore ran on the object
  std::cout << j.dump() << "\n";
}

struct GuideOptions {
  std::string file, actee_dir, guides_file, explored;
  bool json = false;
};

// The thresholds of a grid run on this object (afford explore), if there is
// one: --explored DIR, else out/explore-OBJECT where present. A grid of
// another object is an error, not silently shown.
bool load_explored(const GuideOptions& o, const std::string& object, GridInfo* g, ExploreResult* r,
                   std::string* file) {
  const std::string dir = o.explored.empty() ? "out/explore-" + object : o.explored;
  *file = (std::filesystem::path(dir) / "explore.json").string();
  if (o.explored.empty() && !std::filesystem::exists(*file)) return false;
  read_explore_json(*file, g, r);
  if (g->object != object) throw std::runtime_error(*file + ": a grid of the " + g->object + ", not of the " + object);
  if (!r->shard.whole()) throw std::runtime_error(*file + ": one shard of a grid; join them with afford explore --merge");
  return true;
}

int guide(GuideOptions o) {
  const std::string& file = o.file;
  std::string& actee_dir = o.actee_dir;
  std::string& guides_file = o.guides_file;
  const bool json = o.json;
  const Node root = load_yaml_file(file);
  const std::string kind = file_kind(root);
  if (kind != "object") return usage_error("guide reads object files; " + file + " is a " + kind + " file");
  // Unless named, the shipped ones (data_dir.h), wherever the object is.
  if (actee_dir.empty()) actee_dir = shipped_path("actees");
  if (guides_file.empty()) guides_file = shipped_path("rules/guides.yaml");
  if (!actee_dir.empty() && !std::filesystem::is_directory(actee_dir)) {
    return usage_error("--actees: '" + actee_dir + "' is not a directory");
  }

  const ObjectSpec object = read_object(root);
  const std::vector<GuideSpec> specs = load_guides(guides_file);
  const std::vector<ActeeFit> fits = fit_actees(object, load_actee_folder(actee_dir));
  const Model model = compile(object, nullptr, nullptr, ModelOptions{});
  const Guides guides = compute_guides(model, specs, fits);
  GridInfo grid;
  ExploreResult explored;
  std::string explored_file;
  const bool has_grid = load_explored(o, model.object_name, &grid, &explored, &explored_file);
  const std::vector<TurnSpan> turns = has_grid ? turn_spans(grid, explored) : std::vector<TurnSpan>{};
  if (json) {
    Json thresholds = Json::array();
    for (const TurnSpan& t : turns) {
      thresholds.push_back({{"actee", t.actee}, {"from", t.from}, {"to", t.to}, {"low_N", json_number(t.low)},
                            {"high_N", json_number(t.high)}, {"text", turn_span_text(grid, t)}});
    }
    print_json(guides, has_grid ? Json{{"file", explored_file}, {"turns", thresholds}} : Json(nullptr));
  } else {
    print_text(guides, guides_file, actee_dir);
    if (has_grid) {
      std::cout << "amplify or decline, as simulated by afford explore (" << explored_file << "):\n";
      if (turns.empty()) std::cout << "  no effort of the grid changed how a point ends\n";
      for (const TurnSpan& t : turns) std::cout << "  " << turn_span_text(grid, t) << "\n";
    }
  }
  return 0;
}

}  // namespace

void add_guide(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "guide", "the four guides (symmetry, actee, emphasis, amplify/decline) of an object, as text or JSON");
  auto o = std::make_shared<GuideOptions>();
  cmd->add_option("OBJECT", o->file, "an object file (objects/*.yaml)")->required()->type_name(kFile);
  cmd->add_option("--actees", o->actee_dir, "the folder of actees to fit (default: the shipped actees)")
      ->type_name(kDir);
  cmd->add_option("--guides", o->guides_file, "the guides file (default: the shipped rules/guides.yaml)")
      ->type_name(kFile);
  cmd->add_option("--explored", o->explored,
                  "the output of afford explore on this object, for its thresholds (default: out/explore-OBJECT where present)")
      ->type_name(kDir);
  cmd->add_flag("--json", o->json, "print the guides as JSON");
  cmd->callback([run, o] { *run = [o] { return guide(*o); }; });
}

}  // namespace afford::cli
