// afford_gapcheck SOURCE OUT [FIRST_SEED [SIZE]]: makes the withheld set with MuJoCo (cases under
// OUT/cases, labels apart under OUT/labels), the tools alone and with an
// actee in their jaws, then runs afford's gap
// diagnosis on every case and, only then, reads the labels and scores it:
// the confusion of true against named effects, effects named right,
// effect-free cases kept as `none`, the median held-out shrink, and
// `unexplained` when the true effect is taken out of the library.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <tuple>

#include <mujoco/mujoco.h>

#include "diagnose.h"
#include "jaw_contact.h"
#include "load.h"
#include "truth.h"

namespace fs = std::filesystem;
using namespace gapcheck;

namespace {

Tool tool_from(const std::string& file) {
  const afford::ObjectSpec o = afford::load_object(file);
  Tool t;
  t.name = o.name;
  t.file = file;
  t.theta_min = o.lever.theta_min;
  t.theta_max = o.lever.theta_max;
  t.rest = o.lever.theta_rest;
  t.spring_position = std::abs(o.spring.position);
  t.spring_constant = o.spring.constant;
  t.torsion = o.spring.constant * t.spring_position * t.spring_position;
  t.preload_torque = o.spring.preload * t.spring_position;
  for (const afford::EffectSpec& e : o.effects) {
    if (e.kind == afford::EffectKind::pivot_friction && e.enabled) t.friction = e.param[0];
  }
  t.effort_at = std::abs(o.emphasis.middle());
  t.effort_sign = o.emphasis.middle() < 0 ? -1 : 1;
  return t;
}

// The same tool with an actee in its jaws, as its sessions hold it.
Tool with_actee(Tool tool, const fs::path& source, const std::string& actee, double at_m) {
  const fs::path file = source / "actees" / (actee + ".yaml");
  const afford::ActeeSpec spec = afford::load_actee(file.string());
  ToolActee a;
  a.file = fs::absolute(file).string();
  a.at = at_m;
  const JawContact contact = jaw_contact(tool.file, file.string(), (source / "agents" / "hand.yaml").string(), at_m);
  a.contact_angle = contact.angle;
  a.thickness = contact.thickness;
  a.lever = contact.lever;
  a.stiffness = spec.stiffness;
  a.limit = spec.limit;
  a.breaks = spec.breaks;
  tool.actee = a;
  return tool;
}

// Two drives with the tool turned on its side and upside down, as an
// experimenter tells the arm's weight from the spring's preload: the
// weight's torque turns with the tool, the preload's does not. With an
// actee, the same four stay clear of it, and two more squeeze it from just
// clear of it: to 0.6 of its limit's deflection (it holds), and to 1.3 (it
// cracks, if it can).
constexpr double kQuarterTurn = 1.57079632679489662;
const std::vector<Profile> kProfiles = {{"sine-slow", 2.0, false, 4.0, 0},
                                        {"triangle-fast", 0.5, true, 4.0, 0},
                                        {"sine-fast", 0.5, false, 4.0, kQuarterTurn},
                                        {"triangle-slow", 2.0, true, 4.0, 2 * kQuarterTurn}};
const std::vector<Profile> kSqueezes = {{"squeeze", 2.0, false, 4.0, 0, 0.6}, {"crack", 2.0, false, 4.0, 0, 1.3}};

// Hidden effects sized at `fraction` of the spring's torque swing over the
// drive (latency: 15 ms at a fifth, in proportion otherwise).
std::vector<std::pair<std::string, Truth>> truths(const Tool& tool, double fraction) {
  const double amp = 0.4 * (tool.theta_max - tool.theta_min);
  const double swing = tool.torsion * 2 * amp;  // N*m
  const double size = fraction * swing;
  const double omega_fast = amp * 2 * 3.14159265358979 / 0.5;
  const double alpha_fast = omega_fast * 2 * 3.14159265358979 / 0.5;
  const double deepest = tool.spring_position * (tool.rest - (tool.theta_min + 0.1 * (tool.theta_max - tool.theta_min))) +
                         tool.preload_torque / tool.torsion * tool.spring_position;
  Truth friction, damping, preload, cubic, inertia, weight, latency;
  friction.friction = size;
  damping.damping = size / omega_fast;
  preload.preload = size;
  cubic.cubic = size / (tool.spring_position * deepest * deepest * deepest);
  inertia.inertia = size / alpha_fast;
  weight.weight = size;
  latency.latency = 0.015 * fraction / 0.2;
  auto both = [](Truth a, const Truth& b) {
    a.friction += b.friction; a.damping += b.damping; a.preload += b.preload; a.cubic += b.cubic;
    a.inertia += b.inertia; a.weight += b.weight; a.latency += b.latency; a.actee_exponent += b.actee_exponent;
    return a;
  };
  if (tool.actee) {
    // The actee's law a power of its deflection: Hertz's 1.5 at a fifth.
    Truth actee;
    actee.actee_exponent = 1 + 2.5 * fraction;
    return {{"none", Truth{}}, {"actee", actee}, {"friction", friction}, {"damping", damping},
            {"inertia", inertia}, {"latency", latency}, {"actee+friction", both(actee, friction)},
            {"actee+latency", both(actee, latency)}};
  }
  return {{"none", Truth{}}, {"friction", friction}, {"damping", damping}, {"preload", preload},
          {"cubic", cubic}, {"inertia", inertia}, {"weight", weight}, {"latency", latency},
          {"friction+inertia", both(friction, inertia)}, {"damping+preload", both(damping, preload)},
          {"friction+latency", both(friction, latency)}, {"cubic+weight", both(cubic, weight)}};
}

// The scorer's tallies, over a group of cases.
struct Score {
  int effect_cases = 0, named_right = 0, free_cases = 0, free_none = 0, withheld = 0, withheld_unexplained = 0;
  std::vector<double> shrinks;  // held out, of the cases with an effect

  void print(const char* group) {
    std::sort(shrinks.begin(), shrinks.end());
    const double median = shrinks.empty() ? 0 : shrinks[shrinks.size() / 2];
    std::printf("\n%s:\n", group);
    std::printf("  right effect named: %d of %d (%.0f %%; goal 95 %%)\n", named_right, effect_cases,
                100.0 * named_right / std::max(1, effect_cases));
    std::printf("  effect-free kept as none: %d of %d (%.0f %%; goal 95 %%)\n", free_none, free_cases,
                100.0 * free_none / std::max(1, free_cases));
    std::printf("  median held-out shrink: %.3f (goal 0.8)\n", median);
    std::printf("  unexplained with the true effect withheld: %d of %d (%.0f %%; goal 90 %%)\n", withheld_unexplained,
                withheld, 100.0 * withheld_unexplained / std::max(1, withheld));
  }
};

std::string joined(std::vector<std::string> names) {
  std::sort(names.begin(), names.end());
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : "+") + n;
  return s.empty() ? "none" : s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 5) {
    std::fprintf(stderr, "usage: afford_gapcheck SOURCE_DIR OUT_DIR [FIRST_SEED [SIZE]]\n"
                         "  SIZE: the hidden effects' size, a fraction of the spring's torque swing (default 0.2)\n");
    return 2;
  }
  const fs::path source = argv[1], out = argv[2];
  fs::remove_all(out);
  fs::create_directories(out / "cases");
  fs::create_directories(out / "labels");

  // 1. Make the set: traces and measurement files; the labels apart.
  std::vector<std::string> cases;
  std::set<std::string> actee_cases;  // the cases measured with an actee in the jaws
  // The noise's seeds: the development set used 1; report on another.
  unsigned seed = argc >= 4 ? static_cast<unsigned>(std::stoul(argv[3])) : 1001;
  const double fraction = argc == 5 ? std::stod(argv[4]) : 0.2;
  if (!(fraction > 0 && fraction <= 1)) {
    std::fprintf(stderr, "afford_gapcheck: SIZE must be above 0 and at most 1\n");
    return 2;
  }
  auto make_case = [&](const Tool& tool, const Truth& truth) {
    const std::string name = tool.name + "-" + std::to_string(cases.size());
    std::vector<Profile> profiles = kProfiles;
    if (tool.actee) profiles.insert(profiles.end(), kSqueezes.begin(), kSqueezes.end());
    std::string traces;
    for (const Profile& p : profiles) {
      const std::string trace = name + "-" + p.name + ".csv";
      std::ofstream csv(out / "cases" / trace);
      csv << (tool.actee ? "t,angle,effort_force,actee_force,broken\n" : "t,angle,effort_force,actee_force\n");
      for (const Sample& s : simulate(tool, truth, p, seed++)) {
        char row[128];
        if (tool.actee) {
          std::snprintf(row, sizeof row, "%.3f,%.6f,%.4f,%.2f,%d\n", s.t, s.angle, s.effort, s.actee, s.broken ? 1 : 0);
        } else {
          std::snprintf(row, sizeof row, "%.3f,%.6f,%.4f,%.1f\n", s.t, s.angle, s.effort, s.actee);
        }
        csv << row;
      }
      char entry[256];
      std::snprintf(entry, sizeof entry, "{file: %s, turned: %.6g deg}", trace.c_str(), p.turned * 90 / kQuarterTurn);
      traces += (traces.empty() ? "" : ", ") + std::string(entry);
    }
    char effort_at[64];
    std::snprintf(effort_at, sizeof effort_at, "%.6g mm", tool.effort_sign * tool.effort_at * 1000);
    std::ofstream yaml(out / "cases" / (name + ".yaml"));
    yaml << "measurement: " << name << "\nobject: " << fs::absolute(tool.file).string() << "\neffort_at: " << effort_at;
    if (tool.actee) {
      char at[64];
      std::snprintf(at, sizeof at, "%.9g mm", tool.actee->at * 1000);
      yaml << "\nactee: {file: " << tool.actee->file << ", at: " << at << "}";
    }
    yaml << "\ntraces: [" << traces << "]\n";
    std::ofstream(out / "labels" / (name + ".txt")) << joined(truth.names()) << "\n";
    cases.push_back(name);
    if (tool.actee) actee_cases.insert(name);
  };
  for (const char* object : {"nutcracker", "tongs", "pliers"}) {
    const Tool tool = tool_from((source / "objects" / (std::string(object) + ".yaml")).string());
    for (const auto& [label, truth] : truths(tool, fraction)) make_case(tool, truth);
  }
  // With an actee placed where the jaws close on it well below their
  // opening, so that the free drives have room above it: a hazelnut at the
  // nutcracker's tip (touched at about 17 deg of 30; the walnut at 60 mm at
  // 27), the egg where the paper's tongs hold it (12 deg of 18). Not the
  // pliers: the smallest shipped actee that fits them, a peanut at 40 mm,
  // is touched at 36.7 deg of their 40.
  const std::vector<std::tuple<std::string, std::string, double>> pairs = {{"nutcracker", "hazelnut", 0.075},
                                                                           {"tongs", "egg", 0.210}};
  for (const auto& [object, actee, at] : pairs) {
    const Tool tool = with_actee(tool_from((source / "objects" / (object + ".yaml")).string()), source, actee, at);
    std::printf("%s with the %s at %.0f mm: the jaws touch it at %.9f rad; %.6f mm across them\n", object.c_str(),
                actee.c_str(), at * 1000, tool.actee->contact_angle, tool.actee->thickness * 1000);
    for (const auto& [label, truth] : truths(tool, fraction)) make_case(tool, truth);
  }
  std::printf("%zu cases made with MuJoCo %d, %zu traces each (%zu more with an actee)\n", cases.size(), mj_version(),
              kProfiles.size(), kSqueezes.size());

  // 2. Diagnose every case, labels unseen.
  struct Result {
    std::string named;
    afford::Verdict verdict;
    double shrink;
  };
  std::map<std::string, Result> results;
  for (const std::string& name : cases) {
    const afford::Diagnosis d = afford::diagnose(afford::load_measurement((out / "cases" / (name + ".yaml")).string()));
    std::vector<std::string> named;
    for (const afford::EffectFit& e : d.effects) named.emplace_back(afford::manifest_of(e.kind).name);
    results[name] = {d.verdict == afford::Verdict::explained ? joined(named)
                                                              : std::string(afford::verdict_name(d.verdict)),
                     d.verdict, d.shrink};
  }

  // 3. Only now the labels.
  std::map<std::string, std::map<std::string, int>> confusion;
  Score all, alone, actee;
  for (const std::string& name : cases) {
    std::string truth;
    std::ifstream(out / "labels" / (name + ".txt")) >> truth;
    const Result& r = results[name];
    ++confusion[truth][r.named];
    Score& group = actee_cases.count(name) != 0 ? actee : alone;
    if (truth == "none") {
      for (Score* g : {&all, &group}) {
        ++g->free_cases;
        g->free_none += r.verdict == afford::Verdict::none ? 1 : 0;
      }
      continue;
    }
    for (Score* g : {&all, &group}) {
      ++g->effect_cases;
      g->named_right += r.named == truth ? 1 : 0;
      g->shrinks.push_back(r.shrink);
    }
    // The true effect taken out of the library: it must say unexplained.
    if (truth.find('+') == std::string::npos) {
      afford::DiagnoseOptions options;
      for (const afford::EffectManifest& e : afford::effect_registry()) {
        if (truth != e.name) options.library.push_back(e.kind);
      }
      const afford::Diagnosis d =
          afford::diagnose(afford::load_measurement((out / "cases" / (name + ".yaml")).string()), options);
      for (Score* g : {&all, &group}) {
        ++g->withheld;
        g->withheld_unexplained += d.verdict == afford::Verdict::unexplained ? 1 : 0;
      }
      if (d.verdict != afford::Verdict::unexplained) {
        std::printf("  withheld %s from %s: verdict %s\n", truth.c_str(), name.c_str(), afford::verdict_name(d.verdict));
      }
    }
  }
  std::printf("\nconfusion (true effect: what the diagnosis said, cases)\n");
  for (const auto& [truth, row] : confusion) {
    std::printf("  %-36s", truth.c_str());
    for (const auto& [named, count] : row) std::printf(" %s x%d;", named.c_str(), count);
    std::printf("\n");
  }
  all.print("all cases");
  alone.print("the tools alone");
  actee.print("with an actee");
  return 0;
}
