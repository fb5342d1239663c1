// afford gap MEASUREMENT [--json] [--effects a,b,...] [--out DIR] [--write-patch DIR] [--probe]:
// where and why the nominal model differs from the measured tool, which
// effect of the library explains it, and how far the gap shrinks on data
// the fit never saw (gap/README.md). With --probe: the lever and spring
// from a probing trace (paper Sec. 3.2).
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "option_checks.h"
#include "output_file.h"
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
      *error = "unknown effect '" + name + "'" + did_you_mean(name, names);
      return false;
    }
    out->push_back(e->kind);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return true;
}

// Checks an --effects list as CLI11 reads it.
CLI::Validator effect_list() {
  return CLI::Validator(
      [](std::string& list) {
        std::vector<EffectKind> kinds;
        std::string error;
        return parse_library(list, &kinds, &error) ? std::string() : error;
      },
      "");  // no description: the help line says what is allowed
}

// The most rows a diagnosis takes, over all its traces. Measured (issue 31,
// one core): 100k rows 2.0 s and 94 MB, 1M rows 28.7 s and 789 MB: the fit
// grows faster than its rows, so that 10M rows would take several minutes
// and some 8 GB. Longer traces are refused, with the reason, not left to run.
constexpr size_t kMaxGapRows = 1'000'000;
// More rows than this are announced before the fit starts.
constexpr size_t kAnnouncedGapRows = 100'000;

// Refuses a measurement too long to diagnose; announces a long one.
void check_rows(const Measurement& m) {
  size_t rows = 0;
  for (const Trace& t : m.traces) rows += t.size();
  if (rows > kMaxGapRows) {
    throw std::runtime_error(m.file + ": " + std::to_string(rows) + " rows in its traces, more than the " +
                             std::to_string(kMaxGapRows) +
                             " a diagnosis takes (its fit grows faster than the rows: 1M rows take about 30 s "
                             "and 0.8 GB); resample the traces (every 10th row of a 10 kHz trace is 1 kHz) or "
                             "cut them to the part that matters");
  }
  if (rows > kAnnouncedGapRows) {
    std::cerr << "gap: " << rows << " rows to fit; this takes a while (1M rows: about 30 s)\n";
  }
}

struct GapOptions {
  std::string file, patch_dir, out_dir, effects;
  bool json = false, probe = false, force = false;
};

int gap(const GapOptions& o) {
  const std::string& file = o.file;
  const std::string& patch_dir = o.patch_dir;
  DiagnoseOptions options;
  std::string error;
  if (!o.effects.empty() && !parse_library(o.effects, &options.library, &error)) return usage_error(error);
  const Measurement m = load_measurement(file);
  check_rows(m);
  // Its files are never outputs; files afford did not write are kept (engine/base/output_file.h).
  const OutputScope scope({.writer = "gap", .force = o.force, .inputs = m.files});
  if (o.probe) {  // active modelling: the lever and spring from a probing trace
    const ProbeResult p = probe_lever(m);
    std::cout << probe_text(p);
    if (!patch_dir.empty()) {
      std::filesystem::create_directories(patch_dir);
      const std::string out = (std::filesystem::path(patch_dir) / "object.yaml").string();
      write_probed_object(p, out);
      clear_stale_outputs(patch_dir);
      std::cerr << "wrote " << out << "\n";
    }
    return 0;
  }
  const Diagnosis d = diagnose(m, options);
  const Model nominal = nominal_model(m);  // each fitted parameter is reported as a change over it and as the total
  std::cout << (o.json ? report_json(d, &nominal) + "\n" : report_text(d, &nominal));
  if (!o.out_dir.empty()) {
    for (const std::string& written : write_gap_plots(d, o.out_dir)) std::cerr << "wrote " << written << "\n";
    clear_stale_outputs(o.out_dir);
  }
  if (!patch_dir.empty()) {
    for (const std::string& written : write_patch(m, d, patch_dir)) std::cerr << "wrote " << written << "\n";
    clear_stale_outputs(patch_dir);
  }
  return 0;
}

}  // namespace

void add_gap(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand(
      "gap", "where a measured tool differs from its model, which effect explains it, how far the gap shrinks");
  auto o = std::make_shared<GapOptions>();
  cmd->add_option("MEASUREMENT", o->file, "a measurement file (gap/README.md)")->required()->type_name(kFile);
  cmd->add_flag("--json", o->json, "print the diagnosis as JSON");
  cmd->add_option("--effects", o->effects, "the effects to try, comma-separated (default: every one)")
      ->type_name("NAME,...")
      ->check(effect_list());
  cmd->add_option("--out", o->out_dir, "write plots into DIR: the residual over time, the force-angle loop (SVG, PNG)")
      ->type_name(kDir);
  cmd->add_option("--write-patch", o->patch_dir, "write the fitted effects (or the probed object) into DIR")
      ->type_name(kDir);
  cmd->add_flag("--probe", o->probe, "fit the lever and spring from a probing trace instead");
  cmd->add_flag("--force", o->force, "replace existing files in DIR that afford did not write");
  cmd->callback([run, o] { *run = [o] { return gap(*o); }; });
}

}  // namespace afford::cli
