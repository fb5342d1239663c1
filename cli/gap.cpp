// afford gap MEASUREMENT [--json] [--effects a,b,...] [--out DIR] [--write-patch DIR] [--probe]:
// where and why the nominal model differs from the measured tool, which
// effect of the library explains it, and how far the gap shrinks on data
// the fit never saw (gap/README.md). With --probe: the lever and spring
// from a probing trace (paper Sec. 3.2).
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "did_you_mean.h"
#include "diagnose.h"
#include "patch.h"
#include "plots.h"
#include "probe.h"
#include "report.h"

namespace afford::cli {
namespace {

// "pivot_friction,viscous_damping" -> kinds; a name not in the registry is
// a usage error with "did you mean".
bool parse_library(const std::string& list, std::vector<EffectKind>* out, std::string* error) {
  std::vector<std::string> names;
  for (const EffectManifest& e : effect_registry()) names.emplace_back(e.name);
  size_t start = 0;
  while (start <= list.size()) {
    const size_t comma = list.find(',', start);
    const std::string name = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const EffectManifest* e = find_effect(name);
    if (e == nullptr) {
      *error = "--effects: unknown effect '" + name + "'" + did_you_mean(name, names);
      return false;
    }
    out->push_back(e->kind);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return true;
}

}  // namespace

int run_gap(const Args& args) {
  std::string file, patch_dir, out_dir;
  bool json = false, probe = false;
  DiagnoseOptions options;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--json") {
      json = true;
    } else if (args[i] == "--probe") {
      probe = true;
    } else if (args[i] == "--effects") {
      if (i + 1 >= args.size()) return usage_error("--effects needs a list of effects, e.g. pivot_friction,arm_inertia");
      std::string error;
      if (!parse_library(args[++i], &options.library, &error)) return usage_error(error);
    } else if (args[i] == "--out") {
      if (i + 1 >= args.size()) return usage_error("--out needs a DIR");
      out_dir = args[++i];
    } else if (args[i] == "--write-patch") {
      if (i + 1 >= args.size()) return usage_error("--write-patch needs a DIR");
      patch_dir = args[++i];
    } else if (file.empty() && args[i].rfind("--", 0) != 0) {
      file = args[i];
    } else {
      return usage_error("gap: unexpected '" + args[i] + "'; usage: afford gap MEASUREMENT [--json] [--effects a,b] [--out DIR] [--write-patch DIR] [--probe]");
    }
  }
  if (file.empty()) return usage_error("gap needs a MEASUREMENT file");
  const Measurement m = load_measurement(file);
  if (probe) {  // active modelling: the lever and spring from a probing trace
    const ProbeResult p = probe_lever(m);
    std::cout << probe_text(p);
    if (!patch_dir.empty()) {
      std::filesystem::create_directories(patch_dir);
      const std::string out = (std::filesystem::path(patch_dir) / "object.yaml").string();
      write_probed_object(p, out);
      std::cerr << "wrote " << out << "\n";
    }
    return 0;
  }
  const Diagnosis d = diagnose(m, options);
  std::cout << (json ? report_json(d) + "\n" : report_text(d));
  if (!out_dir.empty()) {
    for (const std::string& written : write_gap_plots(d, out_dir)) std::cerr << "wrote " << written << "\n";
  }
  if (!patch_dir.empty()) {
    for (const std::string& written : write_patch(m, d, patch_dir)) std::cerr << "wrote " << written << "\n";
  }
  return 0;
}

}  // namespace afford::cli
