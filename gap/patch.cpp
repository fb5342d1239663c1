#include "patch.h"

#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "files.h"
#include "report.h"
#include "units.h"

namespace afford {
namespace {

namespace fs = std::filesystem;

// A fitted parameter as a file writes it: the total, the nominal's value
// and the fitted change together (the file replaces the nominal's value).
std::string total(const EffectFit& e, size_t i, const Model& nominal) {
  return si_quantity(parameter_change(e, i, nominal).total, manifest_of(e.kind).params[i]);
}

// The file as YAML with the effects of `home` among `fits` switched on.
YAML::Node patched(const std::string& file, const std::vector<EffectFit>& fits, EffectHome home, const Model& nominal) {
  YAML::Node root = YAML::LoadFile(file);
  for (const EffectFit& e : fits) {
    const EffectManifest& m = manifest_of(e.kind);
    if (m.home != home) continue;
    YAML::Node effect;
    for (size_t i = 0; i < m.params.size(); ++i) effect[m.params[i].key] = total(e, i, nominal);
    // The spring section's preload is this effect's parameter: given once.
    if (e.kind == EffectKind::spring_preload && root["spring"] && root["spring"]["preload"]) {
      root["spring"]["preload"] = total(e, 0, nominal);
      continue;
    }
    if (e.kind == EffectKind::spring_preload && root["spring"] && root["spring"]["rest_length"]) {
      root["spring"].remove("rest_length");
      root["spring"]["preload"] = total(e, 0, nominal);
      continue;
    }
    root["effects"][m.name] = effect;
    // A law whose reference keeps the file's, its stiffness scaled (fit.h).
    if (e.kind == EffectKind::actee_compliance && e.stiffness_factor != 1) {
      char stiffness[64];
      std::snprintf(stiffness, sizeof stiffness, "%.6g N/m", e.stiffness_factor * nominal.actee_stiffness);
      root["stiffness"] = stiffness;
    }
  }
  return root;
}

std::string write(const fs::path& path, const YAML::Node& root, const std::string& from) {
  YAML::Emitter out;
  out << root;
  // Through engine/base/output_file.h: never over an input or a file afford did not write.
  write_file_checked(path.string(), "# Written by afford gap from " + from +
                                        ": the fitted effects switched on, each parameter its total (the nominal's "
                                        "value plus the fitted change).\n" + out.c_str() + "\n");
  return path.string();
}

bool any_in(const std::vector<EffectFit>& fits, EffectHome home) {
  for (const EffectFit& e : fits) {
    if (manifest_of(e.kind).home == home) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> write_patch(const Measurement& m, const Diagnosis& d, const std::string& dir) {
  fs::create_directories(dir);
  std::vector<std::string> written;
  const Model nominal = nominal_model(m);
  YAML::Node measurement = YAML::LoadFile(m.file);
  const fs::path here = fs::absolute(m.file).parent_path();
  auto own_file = [&](const std::string& file, const char* what) {
    if (fs::equivalent(file, m.file)) {
      fail(SourceLoc{m.file, 1, 1}, std::string("the ") + what + " in a file of its own, to patch",
           std::string("the ") + what + " written inside the measurement");
    }
  };
  if (m.object) {
    own_file(m.object->file, "object");
    if (any_in(d.effects, EffectHome::object)) {
      written.push_back(write(fs::path(dir) / "object.yaml", patched(m.object->file, d.effects, EffectHome::object, nominal), m.object->file));
      measurement["object"] = "object.yaml";
    } else {
      measurement["object"] = fs::absolute(m.object->file).string();
    }
  }
  if (m.actee) {
    own_file(m.actee->file, "actee");
    std::string actee_path = fs::absolute(m.actee->file).string();
    if (any_in(d.effects, EffectHome::actee)) {
      written.push_back(write(fs::path(dir) / "actee.yaml", patched(m.actee->file, d.effects, EffectHome::actee, nominal), m.actee->file));
      actee_path = "actee.yaml";
    }
    measurement["actee"]["file"] = actee_path;
  }
  // The traces stay where they are (a {file, turned} entry keeps its turn).
  auto absolute = [&](YAML::Node n) {
    YAML::Node path = n.IsMap() ? n["file"] : n;
    const std::string full = (here / path.as<std::string>()).lexically_normal().string();
    if (!n.IsMap()) return YAML::Node(full);
    n["file"] = full;
    return n;
  };
  if (measurement["trace"]) measurement["trace"] = absolute(measurement["trace"]);
  if (measurement["traces"]) {
    for (size_t i = 0; i < measurement["traces"].size(); ++i) measurement["traces"][i] = absolute(measurement["traces"][i]);
  }
  for (const EffectFit& e : d.effects) {
    const EffectManifest& mf = manifest_of(e.kind);
    if (mf.home != EffectHome::measurement) continue;
    for (size_t i = 0; i < mf.params.size(); ++i) measurement["effects"][mf.name][mf.params[i].key] = total(e, i, nominal);
  }
  written.push_back(write(fs::path(dir) / "measurement.yaml", measurement, m.file));
  return written;
}

}  // namespace afford
