#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "trace.h"  // json_string
#include "units.h"

namespace afford {
namespace {

std::string number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string when(double t) {
  if (t < 0) return "never";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", t);
  return buf;
}

}  // namespace

std::string si_unit(const EffectParam& p) {
  if (p.dimension == dim::none) return "";
  if (p.dimension == dim::length) return "m";
  const std::string q = format_quantity(1, p.dimension);  // "1 N*m": the others show in SI
  return q.substr(q.find(' ') + 1);
}

std::string si_quantity(double si, const EffectParam& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", si);
  return p.dimension == dim::none ? std::string(buf) : std::string(buf) + " " + si_unit(p);
}

std::string report_text(const Diagnosis& d) {
  std::string out = "measurement " + d.measurement + ": verdict " + verdict_name(d.verdict) + "\n";
  char line[512];
  std::snprintf(line, sizeof line, "held-out RMSE %.4g N before, %.4g N after (shrink %.0f %%); noise about %.3g N\n",
                d.rmse_before, d.rmse_after, 100 * d.shrink, d.noise);
  out += line;
  std::snprintf(line, sizeof line, "judged by cross-validation over %zu folds of %zu traces\n", d.folds, d.judged_on.size());
  out += line;
  if (!d.where.empty()) out += "where: " + d.where + "\n";
  for (const PhaseShare& p : d.phases) {
    std::snprintf(line, sizeof line, "  %-22s %6zu samples  %5.1f %% of the gap before, %5.1f %% after\n", phase_name(p.phase),
                  p.samples, 100 * p.before, 100 * p.after);
    out += line;
  }
  if (!d.effects.empty()) out += d.verdict == Verdict::unexplained ? "effects fitted (not enough):\n" : "effects:\n";
  for (const EffectFit& e : d.effects) {
    const EffectManifest& m = manifest_of(e.kind);
    out += "  " + std::string(m.name) + ":";
    for (size_t i = 0; i < m.params.size(); ++i) {
      std::snprintf(line, sizeof line, " %s %.4g +- %.2g %s", m.params[i].key, e.value[i], e.sigma[i], si_unit(m.params[i]).c_str());
      out += line;
    }
    out += "\n";
  }
  for (const auto& set : d.ambiguous) {
    std::string s;
    for (EffectKind k : set) s += (s.empty() ? "" : " + ") + std::string(manifest_of(k).name);
    out += "  as good: " + s + "\n";
  }
  std::snprintf(line, sizeof line, "residual: %s (Ljung-Box Q = %.1f, white below %.1f); it follows %s (correlation %.2f)\n",
                d.residual.white ? "white" : "structured", d.residual.q, d.residual.threshold, d.residual.follows.c_str(),
                d.residual.correlation);
  out += line;
  if (d.verdict == Verdict::unexplained) {
    out += "nothing in the library explains what is left";
    out += d.effects.empty() ? ".\n" : " after the effects above.\n";
  }
  if (d.per_trace.computed) {
    const PerTrace& p = d.per_trace;
    const auto [lo, hi] = std::minmax_element(p.first_parameter.begin(), p.first_parameter.end());
    const EffectParam& param = manifest_of(p.effect).params[0];
    std::snprintf(line, sizeof line,
                  "each trace alone (in sample): %s would take the gap from %.4g N to %.4g N, with %s from %.4g to %.4g; "
                  "the traces differ from one another more than one model allows\n",
                  manifest_of(p.effect).name, p.rmse_nominal, p.rmse_alone, param.key, *lo, *hi);
    out += line;
  }
  for (size_t i = 0; i < d.by_force_before.size() && i < d.by_force_after.size(); ++i) {
    const ForceGap& b = d.by_force_before[i];
    const ForceGap& a = d.by_force_after[i];
    std::snprintf(line, sizeof line, "by force, %s: angle off by %.3g deg before, %.3g deg after (RMSE)\n", b.file.c_str(),
                  b.angle_rmse * 180 / 3.14159265358979323846, a.angle_rmse * 180 / 3.14159265358979323846);
    out += line;
    for (size_t e = 0; e < b.events.size() && e < a.events.size(); ++e) {
      std::snprintf(line, sizeof line, "  %s: measured at %s, simulated at %s before, %s after\n", b.events[e].event.c_str(),
                    when(b.events[e].measured_t).c_str(), when(b.events[e].simulated_t).c_str(),
                    when(a.events[e].simulated_t).c_str());
      out += line;
    }
  }
  out += "selection:\n";
  for (const std::string& s : d.steps) out += "  " + s + "\n";
  return out;
}

std::string report_json(const Diagnosis& d) {
  std::string j = "{\"measurement\":" + json_string(d.measurement) + ",\"verdict\":\"" + verdict_name(d.verdict) + "\"";
  j += ",\"effects\":[";
  for (size_t e = 0; e < d.effects.size(); ++e) {
    const EffectManifest& m = manifest_of(d.effects[e].kind);
    j += std::string(e ? "," : "") + "{\"name\":\"" + m.name + "\",\"parameters\":{";
    for (size_t i = 0; i < m.params.size(); ++i) {
      j += std::string(i ? "," : "") + "\"" + m.params[i].key + "\":{\"value\":" + number(d.effects[e].value[i]) +
           ",\"unit\":\"" + (m.params[i].dimension == dim::none ? "" : std::string(si_unit(m.params[i]))) +
           "\",\"uncertainty\":" + number(d.effects[e].sigma[i]) + "}";
    }
    j += "}}";
  }
  j += "],\"ambiguous\":[";
  for (size_t s = 0; s < d.ambiguous.size(); ++s) {
    j += s ? ",[" : "[";
    for (size_t k = 0; k < d.ambiguous[s].size(); ++k) {
      j += std::string(k ? "," : "") + "\"" + manifest_of(d.ambiguous[s][k]).name + "\"";
    }
    j += "]";
  }
  j += "],\"shrink\":" + number(d.shrink) + ",\"rmse_before\":" + number(d.rmse_before) +
       ",\"rmse_after\":" + number(d.rmse_after) + ",\"noise\":" + number(d.noise) + ",\"unit\":\"N\"";
  j += ",\"phases\":[";
  for (size_t p = 0; p < d.phases.size(); ++p) {
    j += std::string(p ? "," : "") + "{\"name\":" + json_string(phase_name(d.phases[p].phase)) +
         ",\"samples\":" + std::to_string(d.phases[p].samples) + ",\"share_before\":" + number(d.phases[p].before) +
         ",\"share_after\":" + number(d.phases[p].after) + "}";
  }
  j += "],\"where\":" + json_string(d.where);
  j += ",\"residual\":{\"white\":" + std::string(d.residual.white ? "true" : "false") + ",\"ljung_box_q\":" +
       number(d.residual.q) + ",\"threshold\":" + number(d.residual.threshold) + ",\"follows\":" +
       json_string(d.residual.follows) + ",\"correlation\":" + number(d.residual.correlation) + "}";
  if (d.per_trace.computed) {
    j += ",\"per_trace\":{\"effect\":\"" + std::string(manifest_of(d.per_trace.effect).name) + "\",\"rmse_nominal\":" +
         number(d.per_trace.rmse_nominal) + ",\"rmse_alone\":" + number(d.per_trace.rmse_alone) + ",\"parameter\":[";
    for (size_t i = 0; i < d.per_trace.first_parameter.size(); ++i) {
      j += std::string(i ? "," : "") + number(d.per_trace.first_parameter[i]);
    }
    j += "]}";
  }
  j += ",\"events\":[";
  bool first = true;
  for (size_t i = 0; i < d.by_force_before.size() && i < d.by_force_after.size(); ++i) {
    for (size_t e = 0; e < d.by_force_before[i].events.size(); ++e) {
      const EventGap& b = d.by_force_before[i].events[e];
      const EventGap& a = d.by_force_after[i].events[e];
      j += std::string(first ? "" : ",") + "{\"trace\":" + json_string(d.by_force_before[i].file) + ",\"event\":\"" +
           b.event + "\",\"measured_t\":" + (b.measured_t < 0 ? "null" : number(b.measured_t)) +
           ",\"simulated_t_before\":" + (b.simulated_t < 0 ? "null" : number(b.simulated_t)) +
           ",\"simulated_t_after\":" + (a.simulated_t < 0 ? "null" : number(a.simulated_t)) +
           ",\"measured_force\":" + number(b.measured_force) + ",\"simulated_force_before\":" + number(b.simulated_force) +
           ",\"simulated_force_after\":" + number(a.simulated_force) + "}";
      first = false;
    }
  }
  j += "],\"by_force\":[";
  for (size_t i = 0; i < d.by_force_before.size() && i < d.by_force_after.size(); ++i) {
    j += std::string(i ? "," : "") + "{\"trace\":" + json_string(d.by_force_before[i].file) + ",\"angle_rmse_before\":" +
         number(d.by_force_before[i].angle_rmse) + ",\"angle_rmse_after\":" + number(d.by_force_after[i].angle_rmse) +
         ",\"unit\":\"rad\"}";
  }
  j += "]";
  j += ",\"folds\":" + std::to_string(d.folds) + ",\"traces\":[";
  for (size_t i = 0; i < d.judged_on.size(); ++i) j += std::string(i ? "," : "") + json_string(d.judged_on[i]);
  j += "]}";
  return j;
}

}  // namespace afford
