// A measurement of a real tool (or an actee): the nominal model as YAML and
// the measured traces, read and checked like every other file.
//
//   measurement: nutcracker-walnut-3
//   object: object.yaml                  # the nominal tool (rig: lever)
//   actee: {file: actee.yaml, at: 50 mm} # optional
//   effort_at: 160 mm                    # where the effort was applied and measured
//   trace: run.csv                       # or traces: [a.csv, b.csv]
//   format: {...}                        # optional: another table layout
//   effects: {...}                       # optional: effects of the measurement
//   rig: plates                          # an actee alone between two plates
//
// See gap/README.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model.h"
#include "spec.h"

namespace afford {

struct MapSchema;

enum class Rig { lever, plates };

// The signals a trace may carry, SI.
enum class Signal { t, angle, effort_force, actee_force, broken, displacement, force };
inline constexpr int kSignals = 7;
const char* signal_name(Signal s);

// One measured trace: columns by signal, each as long as `t` or empty.
struct Trace {
  std::string file;
  double turned = 0;  // rad, the tool turned about its hinge from how its file holds it (gravity turns with it)
  std::array<std::vector<double>, kSignals> column;
  // SI, per signal: the deviation of the rounding its printed digits make
  // (a cell's last digit's step over sqrt(12), RMS over the column): no
  // noise estimate can be finer than what the file could hold.
  std::array<double, kSignals> resolution{};
  const std::vector<double>& operator[](Signal s) const { return column[static_cast<size_t>(s)]; }
  std::vector<double>& operator[](Signal s) { return column[static_cast<size_t>(s)]; }
  bool has(Signal s) const { return !(*this)[s].empty(); }
  size_t size() const { return (*this)[Signal::t].size(); }
};

struct Measurement {
  std::string file;
  std::string name;
  Rig rig = Rig::lever;
  std::optional<ObjectSpec> object;  // lever
  std::optional<ActeeSpec> actee;
  ModelOptions options;              // the actee's placement; the measurement's effects
  double effort_at = 0;              // m, signed distance along the moving arm (lever)
  std::vector<Trace> traces;
  std::vector<std::string> files;    // every file read, the measurement first
};

// A measurement file and everything it names; a DataError at file:line:col
// on the first mistake, a trace's row and column included.
Measurement load_measurement(const std::string& path);
Measurement read_measurement(const Node& root);
const MapSchema& measurement_schema();  // the keys of a measurement file

// Lets validate_file (afford check, afford.check) read measurements.
void add_measurement_file_kind();

// The model a lever measurement describes (no agent).
Model compile_measurement(const Measurement& m);

}  // namespace afford
