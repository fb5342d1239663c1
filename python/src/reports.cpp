// The calls of the package that answer with text or plain data: the gap
// report (as `afford gap --json`), checking a file (as `afford check`), the
// effects' and signals' manifests (as `afford describe --effects` and
// `afford rules --list`), and the MuJoCo scene (as `afford export --mjcf`).
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "bindings.h"
#include "device_description.h"
#include "diagnose.h"
#include "did_you_mean.h"
#include "effects.h"
#include "measurement.h"
#include "mjcf_scene.h"
#include "report.h"
#include "rule_tests.h"
#include "setup_warnings.h"
#include "validate.h"

namespace afford::python {
namespace {

py::dict check(const std::string& path) {
  static const bool kinds_added = [] {
    add_device_file_kind();  // the kinds defined outside the engine, as afford check adds them
    add_measurement_file_kind();
    add_rule_test_file_kind();
    return true;
  }();
  (void)kinds_added;
  std::vector<Warning> warnings;
  std::string what;
  {
    py::gil_scoped_release unlocked;
    what = validate_file(path, &warnings);  // DataError: afford.DataError
  }
  py::list found;
  for (const Warning& w : warnings) {
    py::dict d;
    d["file"] = w.loc.file;
    d["line"] = w.loc.line;
    d["column"] = w.loc.column;
    d["message"] = w.message;
    found.append(d);
  }
  py::dict out;
  out["what"] = what;
  out["warnings"] = found;
  return out;
}

// The effects to try, by name; a name not in the registry is a ValueError with "did you mean".
std::vector<EffectKind> effect_kinds(const std::vector<std::string>& names) {
  std::vector<std::string> known;
  for (const EffectManifest& e : effect_registry()) known.emplace_back(e.name);
  std::vector<EffectKind> kinds;
  for (const std::string& name : names) {
    const EffectManifest* e = find_effect(name);
    if (e == nullptr) throw py::value_error("unknown effect '" + name + "'" + did_you_mean(name, known));
    kinds.push_back(e->kind);
  }
  return kinds;
}

std::string gap_json(const std::string& path, const std::vector<std::string>& effects) {
  DiagnoseOptions options;
  options.library = effect_kinds(effects);
  py::gil_scoped_release unlocked;
  const Measurement m = load_measurement(path);
  const Diagnosis d = diagnose(m, options);
  const Model nominal = nominal_model(m);
  return report_json(d, &nominal);
}

py::list effects() {
  py::list out;
  for (const EffectManifest& e : effect_registry()) {
    py::list params;
    for (const EffectParam& p : e.params) {
      py::dict d;
      d["key"] = p.key;
      d["unit"] = p.dimension.str();  // SI, as min and max are given
      d["min"] = p.min;
      d["min_included"] = p.min_included;
      d["max"] = p.max;
      d["keeps_sign"] = p.keeps_sign;  // a measured tool's value keeps the file's sign
      d["range"] = std::string(p.min_included ? "from " : "above ") + format_quantity(p.min, p.dimension) + " to " +
                   format_quantity(p.max, p.dimension);
      d["doc"] = p.doc;
      params.append(d);
    }
    py::dict d;
    d["name"] = e.name;
    d["home"] = home_name(e.home);
    d["doc"] = e.doc;
    d["params"] = params;
    out.append(d);
  }
  return out;
}

py::list signals() {
  py::list out;
  for (const SignalDoc& s : vocabulary()) {
    py::dict d;
    d["signature"] = s.signature;
    d["type"] = s.type;
    d["doc"] = s.doc;
    out.append(d);
  }
  return out;
}

}  // namespace

void bind_reports(py::module_& m) {
  m.def("check", &check, py::arg("path"));
  m.def("gap_json", &gap_json, py::arg("path"), py::arg("effects"));
  m.def("effects", &effects);
  m.def("signals", &signals);
  m.def("export_mjcf", [](const SessionPtr& s) { return export_mjcf(*s); }, py::arg("model"));
}

}  // namespace afford::python
