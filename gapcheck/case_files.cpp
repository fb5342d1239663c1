#include "case_files.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include "plates_fit.h"

namespace fs = std::filesystem;

namespace gapcheck {
namespace {

// The shipped actee file with its stiffness replaced by the plates' (every
// other line as it was) and, where the plates' curve wanted the power
// law, that law as the file's `actee_compliance` effect.
void write_actee(const fs::path& shipped, const fs::path& to, const PlatesFit& law) {
  std::ifstream in(shipped);
  if (!in) throw std::runtime_error("gapcheck: cannot read " + shipped.string());
  std::ofstream o(to);
  std::string line;
  bool replaced = false;
  while (std::getline(in, line)) {
    if (line.rfind("effects:", 0) == 0) throw std::runtime_error("gapcheck: " + shipped.string() + " has effects of its own");
    if (line.rfind("stiffness:", 0) == 0) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "stiffness: %.9g N/m", law.stiffness);
      line = buf;
      replaced = true;
    }
    o << line << "\n";
  }
  if (!replaced) throw std::runtime_error("gapcheck: " + shipped.string() + " has no stiffness line");
  if (law.exponent > 0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "effects: {actee_compliance: {exponent: %.9g, reference: %.9g mm}}", law.exponent,
                  law.reference * 1000);
    o << "# fitted on the plates' curve: its RMS misfit " << law.rms_power << " N, the linear law's " << law.rms_linear
      << " N\n"
      << buf << "\n";
  }
}

}  // namespace

fs::path write_case(const fs::path& out, const Case& c, const std::vector<std::vector<Measured>>& traces,
                    const std::optional<PlatesLaw>& plates) {
  const fs::path dir = out / "cases";
  const bool actee = c.tool.actee.has_value();
  std::string list;
  for (size_t k = 0; k < traces.size(); ++k) {
    const std::string file = c.name + "-" + std::to_string(k + 1) + ".csv";
    std::ofstream csv(dir / file);
    csv << (actee ? "t,angle,effort_force,actee_force,broken\n" : "t,angle,effort_force,actee_force\n");
    for (const Measured& s : traces[k]) {
      if (!c.drives[k].measured(s.t)) continue;
      char row[160];
      if (actee) {
        std::snprintf(row, sizeof row, "%.3f,%.7f,%.6f,%.4f,%d\n", s.t, s.angle, s.effort, s.actee, s.broken ? 1 : 0);
      } else {
        std::snprintf(row, sizeof row, "%.3f,%.7f,%.6f,%.4f\n", s.t, s.angle, s.effort, s.actee);
      }
      csv << row;
    }
    const double turned_deg = c.drives[k].turned * 180 / 3.14159265358979323846;
    char entry[200];
    if (turned_deg != 0) {
      std::snprintf(entry, sizeof entry, "{file: %s, turned: %.6g deg}", file.c_str(), turned_deg);
    } else {
      std::snprintf(entry, sizeof entry, "%s", file.c_str());
    }
    list += (list.empty() ? "" : ", ") + std::string(entry);
  }
  const fs::path yaml = dir / (c.name + ".yaml");
  std::ofstream m(yaml);
  char line[400];
  m << "measurement: " << c.name << "\nobject: " << c.tool.file << "\n";
  std::snprintf(line, sizeof line, "effort_at: %.9g mm\n", c.tool.effort_sign * c.tool.effort_at * 1000);
  m << line;
  if (actee) {
    if (!plates) throw std::runtime_error(c.name + ": an actee without its plates' measurement");
    const std::string file = c.name + "-actee.yaml";
    // The curve fitted with the file's family; a reality that gives no
    // curve gives the linear law's stiffness.
    PlatesFit law;
    law.stiffness = plates->stiffness;
    if (!plates->deflection.empty()) {
      law = fit_plates(plates->deflection, plates->force, c.tool.actee->thickness, c.tool.actee->limit);
    }
    write_actee(c.tool.actee->file, dir / file, law);
    std::snprintf(line, sizeof line, "actee: {file: %s, at: %.9g mm}\n", file.c_str(), c.tool.actee->at * 1000);
    m << line;
  }
  m << "traces: [" << list << "]\n";
  // The label, and the hidden sizes for whoever studies a case afterwards
  // (the scorer reads the first word only).
  const Truth& t = c.truth;
  std::snprintf(line, sizeof line,
                "friction %.4g N*m, damping %.4g N*m*s/rad, preload %.4g N*m, cubic %.4g N/m^3, inertia %.4g kg*m^2, "
                "weight %.4g N*m, latency %.4g s, actee exponent %.4g\n",
                t.friction, t.damping, t.preload, t.cubic, t.inertia, t.weight, t.latency, t.actee_exponent);
  std::ofstream(out / "labels" / (c.name + ".txt")) << label_of(c) << "\n" << line;
  return yaml;
}

Played play_and_write(const fs::path& out, const Case& c, const Reality& reality) {
  std::vector<std::vector<Measured>> traces;
  for (const Drive& d : c.drives) traces.push_back(reality.play(c, d, d.noise_seed));
  Played played;
  if (c.tool.actee) played.plates = reality.plates(c);
  played.measurement = write_case(out, c, traces, played.plates);
  return played;
}

}  // namespace gapcheck
