// afford_gapcheck SOURCE OUT --engine mujoco|ode --seeds dev|report [--count N] [--first SEED] [--again]
//
// The withheld check of `afford gap`: draws N cases at random (design.h),
// one per seed, has a physics engine play them (reality.h), writes each as
// a measurement (OUT/cases) with its label apart (OUT/labels), diagnoses
// every case with afford's gap diagnosis, and only then reads the labels
// and scores the diagnosis by design group (score.h). Development seeds
// lie below 1,000,000 and report seeds from there on: figures are called
// report figures only on report seeds.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "case_files.h"
#include "design.h"
#include "diagnose.h"
#include "reality.h"
#include "score.h"

namespace fs = std::filesystem;
using namespace gapcheck;

namespace {

constexpr unsigned kFirstReportSeed = 1000000;

int usage() {
  std::fprintf(stderr,
               "usage: afford_gapcheck SOURCE OUT --engine mujoco|ode --seeds dev|report [--count N] [--first SEED] "
               "[--again]\n"
               "  dev seeds lie below %u (default first 1), report seeds from %u on (default first %u);\n"
               "  N cases, one per seed (default 40)\n",
               kFirstReportSeed, kFirstReportSeed, kFirstReportSeed);
  return 2;
}

std::vector<std::string> sorted_names(const std::vector<afford::EffectKind>& kinds) {
  std::vector<std::string> names;
  for (afford::EffectKind k : kinds) names.emplace_back(afford::manifest_of(k).name);
  std::sort(names.begin(), names.end());
  return names;
}

// What the diagnosis says, each ambiguous set completed: a set of a
// selection step holds the effects chosen before it and one that fits as
// well as that step's choice, and is completed with the effects chosen
// after it (the adopted ones are in the order chosen); a look-alike set is
// whole already. An inertia named from the turns (adopted last) joins
// every set: the fits that made them did not see it.
Diagnosed summary(const afford::Diagnosis& d) {
  Diagnosed s;
  s.verdict = afford::verdict_name(d.verdict);
  s.shrink = d.shrink;
  s.gap = d.noise_through_model > 0 ? d.rmse_before / d.noise_through_model : 0.0;
  const double before = d.shrink_in_contact ? d.contact_before : d.rmse_before;
  s.ceiling = before > 0 ? std::max(0.0, 1 - d.noise_through_model / before) : 0.0;
  std::vector<afford::EffectKind> adopted;
  for (const afford::EffectFit& e : d.effects) adopted.push_back(e.kind);
  s.effects = sorted_names(adopted);
  if (d.turns.adopted) adopted.pop_back();
  for (std::vector<afford::EffectKind> set : d.ambiguous) {
    for (size_t i = set.size(); i < adopted.size(); ++i) set.push_back(adopted[i]);
    if (d.turns.adopted) set.push_back(afford::EffectKind::arm_inertia);
    std::vector<std::string> names = sorted_names(set);
    names.erase(std::unique(names.begin(), names.end()), names.end());
    if (std::find(s.alternatives.begin(), s.alternatives.end(), names) == s.alternatives.end()) {
      s.alternatives.push_back(names);
    }
  }
  return s;
}

std::unique_ptr<Reality> reality_for(const std::string& engine) {
  if (engine == "mujoco") return make_mujoco_reality();
#ifdef AFFORD_GAPCHECK_ODE
  if (engine == "ode") return make_ode_reality();
#else
  if (engine == "ode") std::fprintf(stderr, "afford_gapcheck: built without ODE (gapcheck/ode_reality.cpp)\n");
#endif
  return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const fs::path source = fs::absolute(argv[1]).lexically_normal(), out = argv[2];
  std::string engine, seeds;
  unsigned count = 40;
  std::optional<unsigned> first;
  bool again = false;
  for (int i = 3; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--again") {
      again = true;
      continue;
    }
    if (i + 1 >= argc) return usage();
    const std::string value = argv[++i];
    if (arg == "--engine") {
      engine = value;
    } else if (arg == "--seeds") {
      seeds = value;
    } else if (arg == "--count" || arg == "--first") {
      char* end = nullptr;
      const unsigned long n = std::strtoul(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || n > 100000000) return usage();
      (arg == "--count" ? count : first.emplace()) = static_cast<unsigned>(n);
    } else {
      return usage();
    }
  }
  if ((seeds != "dev" && seeds != "report") || count == 0) return usage();
  const bool report = seeds == "report";
  const unsigned from = first.value_or(report ? kFirstReportSeed : 1);
  // Development and report seeds apart: report figures only from report seeds.
  if (report ? from < kFirstReportSeed : from + count - 1 >= kFirstReportSeed || from == 0) {
    std::fprintf(stderr, "afford_gapcheck: %s seeds are %s; %u to %u are not\n", seeds.c_str(),
                 report ? "1000000 on" : "1 to 999999", from, from + count - 1);
    return 2;
  }
  const std::unique_ptr<Reality> reality = reality_for(engine);
  if (!reality) return usage();

  if (again && !fs::is_directory(out / "cases")) {
    std::fprintf(stderr, "afford_gapcheck: --again needs the cases of an earlier run in %s\n", (out / "cases").c_str());
    return 2;
  }
  if (!again) {
    fs::remove_all(out);
    fs::create_directories(out / "cases");
    fs::create_directories(out / "labels");
  }

  // 1. Draw, play and write every case; the labels apart.
  struct Made {
    fs::path measurement;
    Diagnosed diagnosed;
  };
  std::vector<Made> made;
  for (unsigned seed = from; seed < from + count; ++seed) {
    const auto start = std::chrono::steady_clock::now();
    Case c;
    Made m;
    std::optional<PlatesLaw> plates;
    try {
      c = draw_case(source, out / "cases", seed,
                    [&reality](const Case& k, const Drive& d) { return reality->play(k, d, d.noise_seed); });
      if (again) {
        m.measurement = out / "cases" / (c.name + ".yaml");
        if (!fs::is_regular_file(m.measurement)) throw std::runtime_error("no case " + m.measurement.string());
      } else {
        const Played played = play_and_write(out, c, *reality);
        m.measurement = played.measurement;
        plates = played.plates;
      }
    } catch (const std::exception& e) {
      // A set with a case left out would not be the set its seeds name.
      std::fprintf(stderr, "afford_gapcheck: seed %u: %s\n", seed, e.what());
      return 1;
    }
    m.diagnosed.name = c.name;
    m.diagnosed.scenario = actee_scenario_name(c.scenario);
    std::set<double> turns;
    for (const Drive& d : c.drives) turns.insert(d.turned);
    m.diagnosed.several_orientations = turns.size() > 1;
    made.push_back(m);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "%s: %s, %zu traces, %s in %.1f s", c.name.c_str(), c.group.c_str(), c.drives.size(),
                 again ? "drawn" : "played", seconds);
    if (plates) std::fprintf(stderr, "; plates %.6g N/m (misfit %.3g N)", plates->stiffness, plates->rms_misfit);
    std::fprintf(stderr, "\n");
  }

  // 2. Diagnose every case, the labels unseen.
  for (Made& m : made) {
    try {
      const std::string name = m.diagnosed.name;
      const bool several = m.diagnosed.several_orientations;
      const std::string scenario = m.diagnosed.scenario;
      m.diagnosed = summary(afford::diagnose(afford::load_measurement(m.measurement.string())));
      m.diagnosed.name = name;
      m.diagnosed.several_orientations = several;
      m.diagnosed.scenario = scenario;
    } catch (const std::exception& e) {
      m.diagnosed.verdict = std::string("error: ") + e.what();
      std::fprintf(stderr, "%s: the diagnosis threw: %s\n", m.diagnosed.name.c_str(), e.what());
    }
  }

  // 3. Only now the labels; then each single effect of the library taken
  // out of it: the diagnosis must say unexplained.
  std::map<std::string, std::string> labels, withheld;
  std::vector<Diagnosed> diagnosed;
  for (const Made& m : made) {
    std::string label;
    std::ifstream(out / "labels" / (m.diagnosed.name + ".txt")) >> label;
    labels[m.diagnosed.name] = label;
    diagnosed.push_back(m.diagnosed);
    const std::vector<std::string> truth = label_effects(label);
    if (truth.size() != 1) continue;
    afford::DiagnoseOptions options;
    for (const afford::EffectManifest& e : afford::effect_registry()) {
      if (truth.front() != e.name) options.library.push_back(e.kind);
    }
    try {
      withheld[m.diagnosed.name] =
          afford::verdict_name(afford::diagnose(afford::load_measurement(m.measurement.string()), options).verdict);
    } catch (const std::exception& e) {
      withheld[m.diagnosed.name] = std::string("error: ") + e.what();
    }
  }
  score(diagnosed, labels, withheld, reality->name(), report ? "report" : "development", out);
  return 0;
}
