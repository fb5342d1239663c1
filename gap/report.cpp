#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "units.h"

namespace afford {
namespace {

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

Model nominal_model(const Measurement& m) {
  return m.rig == Rig::lever ? compile_measurement(m) : compile_actee_only(*m.actee, m.options);
}

ParameterChange parameter_change(const EffectFit& fit, size_t i, const Model& nominal) {
  ParameterChange c;
  c.nominal = nominal_value(nominal, fit.kind, i);
  // The fitted law replaces the actee's own: linear unless its file has one.
  if (fit.kind == EffectKind::actee_compliance) c.has_nominal = i == 0 || nominal.actee_reference > 0;
  if (fit.kind == EffectKind::sensor_latency) {
    // The fit searches the delay on top of the measurement's own (the
    // replay has delayed the nominal already): its value is the change.
    c.change = fit.value[i];
    c.total = c.nominal + c.change;
    return c;
  }
  // Every other value is the total, the nominal included (fit.h).
  c.total = fit.value[i];
  c.change = c.has_nominal ? c.total - c.nominal : 0;
  return c;
}

std::string report_text(const Diagnosis& d, const Model* nominal) {
  std::string out = "measurement " + d.measurement + ": verdict " + verdict_name(d.verdict) + "\n";
  char line[512];
  auto shrink_of = [](double before, double after) { return before > 0 ? 100 * (1 - after / before) : 0.0; };
  std::snprintf(line, sizeof line,
                "held-out RMSE %.4g N before, %.4g N after (shrink %.0f %%; each sample weighed by its noise); noise "
                "about %.3g N, %.3g N with the motion's noise through the model\n",
                d.rmse_before, d.rmse_after, shrink_of(d.rmse_before, d.rmse_after), d.noise, d.noise_through_model);
  out += line;
  if (d.contact_samples > 0) {
    std::snprintf(line, sizeof line,
                  "in the actee's contact (%zu samples, each error scaled to the sensor's noise): %.4g N before, %.4g N "
                  "after (shrink %.0f %%)\n",
                  d.contact_samples, d.contact_before, d.contact_after, shrink_of(d.contact_before, d.contact_after));
    out += line;
  }
  std::snprintf(line, sizeof line, "shrink: %.0f %%, %s, where the gap is the largest against the noise\n",
                100 * d.shrink, d.shrink_in_contact ? "in the actee's contact" : "over every sample");
  out += line;
  if (d.folds < 2) {
    std::snprintf(line, sizeof line, "not cross-validated: one block of %zu trace%s (fitted samples:", d.traces,
                  d.traces == 1 ? "" : "s");
  } else {
    std::snprintf(line, sizeof line,
                  "judged by cross-validation over %zu folds of %zu blocks of %zu trace%s (fitted samples:", d.folds,
                  d.judged_on.size(), d.traces, d.traces == 1 ? "" : "s");
  }
  out += line;
  for (const FoldSize& f : d.fold_sizes) out += " " + std::to_string(f.fitted);
  std::snprintf(line, sizeof line, ")\n");
  out += line;
  if (!d.where.empty()) out += "where: " + d.where + "\n";
  for (const PhaseShare& p : d.phases) {
    std::snprintf(line, sizeof line, "  %-22s %6zu samples  %5.1f %% of the gap before, %5.1f %% after\n", phase_name(p.phase),
                  p.samples, 100 * p.before, 100 * p.after);
    out += line;
  }
  if (!d.effects.empty()) {
    if (d.verdict != Verdict::unexplained) out += "effects:\n";
    else if (d.gain_alike_explains) out += "effects fitted (a force sensor's gain error does as well, below):\n";
    else out += "effects fitted (not enough):\n";
  }
  // Each parameter as its change over the nominal model's, the nominal and
  // the total: "torque +0.3 +- 0.002 N*m over the nominal 0.01 (0.31 in all)".
  for (const EffectFit& e : d.effects) {
    const EffectManifest& m = manifest_of(e.kind);
    out += "  " + std::string(m.name) + ":";
    for (size_t i = 0; i < m.params.size(); ++i) {
      const std::string unit = m.params[i].dimension == dim::none ? "" : " " + si_unit(m.params[i]);
      out += i > 0 ? ", " : " ";
      if (nominal == nullptr) {
        std::snprintf(line, sizeof line, "%s %.4g +- %.2g%s in all (the nominal not given)", m.params[i].key, e.value[i],
                      e.sigma[i], unit.c_str());
      } else {
        const ParameterChange c = parameter_change(e, i, *nominal);
        if (c.has_nominal) {
          std::snprintf(line, sizeof line, "%s %+.4g +- %.2g%s over the nominal %.4g (%.4g in all)", m.params[i].key,
                        c.change, e.sigma[i], unit.c_str(), c.nominal, c.total);
        } else {
          std::snprintf(line, sizeof line, "%s %.4g +- %.2g%s (the nominal has none)", m.params[i].key, c.total,
                        e.sigma[i], unit.c_str());
        }
      }
      out += line;
    }
    if (e.stiffness_factor != 1) {
      std::snprintf(line, sizeof line, ", the actee's stiffness times %.4g +- %.2g", e.stiffness_factor,
                    e.stiffness_factor_sigma);
      out += line;
      if (nominal != nullptr) {
        std::snprintf(line, sizeof line, " (%.4g N/m in all, the nominal %.4g)",
                      e.stiffness_factor * nominal->actee_stiffness, nominal->actee_stiffness);
        out += line;
      }
    }
    out += "\n";
  }
  // The named set heads the sets that fit alike; the others are as good
  // as it. An inertia the turns named joins every set, and is last.
  std::vector<EffectKind> named;
  for (const EffectFit& e : d.effects) named.push_back(e.kind);
  if (d.turns.adopted && !named.empty()) named.pop_back();
  for (const auto& set : d.ambiguous) {
    if (same_effects(set, named)) continue;
    std::string s;
    for (EffectKind k : set) s += (s.empty() ? "" : " + ") + std::string(manifest_of(k).name);
    if (d.turns.adopted) s += " (and the turns' arm_inertia)";
    out += "  as good: " + s + "\n";
  }
  // "Nor from both" where the named set with the look-alike beside it is
  // listed: a listed set that holds the two in place of another effect
  // (a weight for a progressive spring, beside the preload it looks like)
  // says nothing of the two at once.
  for (const LookAlike& l : d.look_alikes) {
    std::vector<EffectKind> with = named;
    with.push_back(l.alike);
    const bool both = std::any_of(d.ambiguous.begin(), d.ambiguous.end(),
                                  [&](const std::vector<EffectKind>& set) { return same_effects(set, with); });
    out += "  " + look_alike_text(l, both) + "\n";
  }
  std::snprintf(line, sizeof line,
                "residual: %s (Ljung-Box Q = %.1f, white below %.1f; structured share %.1f %%); it follows %s "
                "(correlation %.2f)\n",
                d.residual.white ? "white" : "structured", d.residual.q, d.residual.threshold, 100 * d.residual.share,
                d.residual.follows.c_str(), d.residual.correlation);
  out += line;
  if (d.verdict == Verdict::unexplained && d.gain_alike_explains) {
    std::snprintf(line, sizeof line,
                  "the effects above take the gap to the noise, and so does a force sensor reading %+.3g %% (a gain "
                  "error, outside the library): the data cannot tell which, so none is named.\n",
                  100 * d.gain_alike);
    out += line;
  } else if (d.verdict == Verdict::unexplained) {
    out += "nothing in the library explains what is left";
    out += d.effects.empty() ? ".\n" : " after the effects above.\n";
  }
  if (d.turns.stretches >= kLeastStretches) {
    auto half = [&](const InertiaEstimate& e) {
      char text[96];
      if (e.stretches < kLeastStretches) {
        std::snprintf(text, sizeof text, "too few stretches (%zu)", e.stretches);
      } else {
        std::snprintf(text, sizeof text, "%+.3g +- %.2g (%zu stretches)", e.inertia, e.sigma, e.stretches);
      }
      return std::string(text);
    };
    std::snprintf(line, sizeof line,
                  "the turns (left out of every fit: friction turns over there), in %zu stretches of motion: the torque "
                  "left over across each, against its change of speed, is an arm inertia of %+.3g +- %.2g kg*m^2 beyond "
                  "the model's (%.3g N at the effort across the turns, %.2g times the noise); slowing into the turns %s, "
                  "speeding out of them %s (%s)\n",
                  d.turns.stretches, d.turns.inertia, d.turns.sigma, d.turns.force,
                  d.noise > 0 ? d.turns.force / d.noise : 0.0, half(d.turns.slowing).c_str(),
                  half(d.turns.speeding).c_str(), d.turns.adopted ? "named among the effects" : "not named");
    out += line;
  }
  if (d.per_trace.computed) {
    const PerTrace& p = d.per_trace;
    const auto [lo, hi] = std::minmax_element(p.first_parameter.begin(), p.first_parameter.end());
    const EffectParam& param = manifest_of(p.effect).params[0];
    // What the fits of each trace alone show, against the floor.
    const char* shows = p.nominal_at_floor
                            ? "each trace's nominal is within the noise's tolerance of it already: the gap is a shape "
                              "only the traces together show, not a difference between them"
                        : p.each_at_floor ? "each trace alone is within the noise's tolerance of it: the traces differ "
                                            "from one another more than one model allows"
                                          : "no one effect of the library explains every trace even alone";
    std::snprintf(line, sizeof line,
                  "each trace alone (in sample): %s would take the gap from %.4g N to %.4g N, with %s from %.4g to %.4g; "
                  "the floor %.4g N: %s\n",
                  manifest_of(p.effect).name, p.rmse_nominal, p.rmse_alone, param.key, *lo, *hi, p.floor, shows);
    out += line;
  }
  if (d.specimens.computed) {
    const SpecimenShape& sp = d.specimens;
    const ShapeJudged& own = sp.own_stiffness;
    const auto [lo, hi] = std::minmax_element(own.stiffness_factor.begin(), own.stiffness_factor.end());
    std::snprintf(line, sizeof line,
                  "specimens: each trace given its own stiffness (%.3g to %.3g times the nominal), %s with the exponent "
                  "fitted on the other traces (%.3g +/- %.2g on all) takes the held-out gap from %.4g N to %.4g N "
                  "(shrink %.0f %%)\n",
                  *lo, *hi, manifest_of(EffectKind::actee_compliance).name, own.exponent, own.exponent_sigma,
                  own.rmse_before, own.rmse_after, 100 * own.shrink);
    out += line;
    const ShapeJudged& seated = sp.own_zero;
    const auto [first, last] = std::minmax_element(seated.zero.begin(), seated.zero.end());
    std::snprintf(line, sizeof line,
                  "  if the soft toe is seating instead (each trace's law starting at a zero of its own, %.3g to %.3g mm "
                  "past the trace's): exponent %.3g +/- %.2g, held-out gap from %.4g N to %.4g N (shrink %.0f %%)\n",
                  1e3 * *first, 1e3 * *last, seated.exponent, seated.exponent_sigma, seated.rmse_before,
                  seated.rmse_after, 100 * seated.shrink);
    out += line;
    auto side = [](double v) { return v < 0 ? "below" : "above"; };
    std::snprintf(line, sizeof line,
                  "  with its own stiffness, the measured force lies %.4g N %s the nominal law over the first third of "
                  "each trace's deflection%s and %.4g N %s it over the last%s\n",
                  std::abs(sp.first_third), side(sp.first_third), sp.first_third < 0 ? " (a soft toe)" : "",
                  std::abs(sp.last_third), side(sp.last_third), sp.last_third > 0 ? " (it stiffens)" : "");
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

std::string report_json(const Diagnosis& d, const Model* nominal) {
  using Json = nlohmann::ordered_json;
  // Six significant digits, as the text report, whole numbers as integers;
  // non-finite and "never" (< 0) are null.
  const auto num = [](double x) -> Json {
    if (!std::isfinite(x)) return nullptr;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    const double rounded = std::strtod(buf, nullptr);
    if (rounded == std::trunc(rounded) && std::abs(rounded) < 1e15) return static_cast<std::int64_t>(rounded);
    return rounded;
  };
  const auto time = [&num](double t) -> Json { return t < 0 ? Json(nullptr) : num(t); };

  Json effects = Json::array();
  for (const EffectFit& fit : d.effects) {
    const EffectManifest& m = manifest_of(fit.kind);
    Json parameters = Json::object();
    // value: the total (as before); change over the nominal, and the
    // nominal (null where not given or where the nominal has none).
    for (size_t i = 0; i < m.params.size(); ++i) {
      Json total = num(fit.value[i]), change = nullptr, base = nullptr;
      if (nominal != nullptr) {
        const ParameterChange c = parameter_change(fit, i, *nominal);
        total = num(c.total);
        if (c.has_nominal) {
          change = num(c.change);
          base = num(c.nominal);
        }
      }
      parameters[m.params[i].key] = {{"value", total},
                                     {"change", change},
                                     {"nominal", base},
                                     {"unit", m.params[i].dimension == dim::none ? "" : si_unit(m.params[i])},
                                     {"uncertainty", num(fit.sigma[i])}};
    }
    Json effect = {{"name", m.name}, {"parameters", parameters}};
    // An actee's law: its stiffness times this (1 but where the law keeps
    // the nominal's reference: fit.h).
    if (fit.kind == EffectKind::actee_compliance) {
      effect["stiffness_factor"] = {{"value", num(fit.stiffness_factor)}, {"uncertainty", num(fit.stiffness_factor_sigma)}};
    }
    effects.push_back(effect);
  }
  Json ambiguous = Json::array();
  for (const auto& set : d.ambiguous) {
    Json names = Json::array();
    for (EffectKind k : set) names.push_back(manifest_of(k).name);
    ambiguous.push_back(names);
  }
  Json look_alikes = Json::array();
  for (const LookAlike& l : d.look_alikes) {
    look_alikes.push_back({{"named", manifest_of(l.chosen).name},
                           {"alike", manifest_of(l.alike).name},
                           {"cosine", num(l.cosine)},
                           {"separate", l.separate},
                           {"out_of_range", l.out_of_range},
                           {"told_apart", l.told_apart}});
  }
  Json phases = Json::array();
  for (const auto& p : d.phases) {
    phases.push_back({{"name", phase_name(p.phase)},
                      {"samples", p.samples},
                      {"share_before", num(p.before)},
                      {"share_after", num(p.after)}});
  }
  Json j = {{"measurement", d.measurement},
            {"verdict", verdict_name(d.verdict)},
            {"effects", effects},
            {"ambiguous", ambiguous},
            {"look_alikes", look_alikes},
            {"shrink", num(d.shrink)},
            {"shrink_where", d.shrink_in_contact ? "contact" : "every sample"},
            {"rmse_before", num(d.rmse_before)},
            {"rmse_after", num(d.rmse_after)},
            {"noise", num(d.noise)},
            {"noise_through_model", num(d.noise_through_model)},
            {"unit", "N"},
            {"contact",
             {{"samples", d.contact_samples},
              {"rmse_before", num(d.contact_before)},
              {"rmse_after", num(d.contact_after)}}},
            {"phases", phases},
            {"where", d.where},
            {"residual",
             {{"white", d.residual.white},
              {"ljung_box_q", num(d.residual.q)},
              {"threshold", num(d.residual.threshold)},
              {"structured_share", num(d.residual.share)},
              {"follows", d.residual.follows},
              {"correlation", num(d.residual.correlation)},
              {"out_of_contact", d.out_of_contact.computed
                                     ? Json{{"ljung_box_q", num(d.out_of_contact.test.q)},
                                            {"threshold", num(d.out_of_contact.test.threshold)},
                                            {"structured_share", num(d.out_of_contact.test.share)}}
                                     : Json(nullptr)}}}};
  if (d.turns.stretches >= kLeastStretches) {
    // A half of fewer than three stretches is counted, not estimated.
    auto estimate = [&](const InertiaEstimate& e) {
      return Json{{"stretches", e.stretches},
                  {"arm_inertia", e.stretches < kLeastStretches ? Json(nullptr)
                                                  : Json{{"value", num(e.inertia)},
                                                         {"unit", "kg*m^2"},
                                                         {"uncertainty", num(e.sigma)}}}};
    };
    j["turns"] = estimate(d.turns);
    j["turns"]["slowing"] = estimate(d.turns.slowing);
    j["turns"]["speeding"] = estimate(d.turns.speeding);
    j["turns"]["adopted"] = d.turns.adopted;
    j["turns"]["force"] = Json{{"value", num(d.turns.force)}, {"unit", "N"}};
  }
  if (d.per_trace.computed) {
    Json parameter = Json::array();
    for (double v : d.per_trace.first_parameter) parameter.push_back(num(v));
    j["per_trace"] = {{"effect", manifest_of(d.per_trace.effect).name},
                      {"rmse_nominal", num(d.per_trace.rmse_nominal)},
                      {"rmse_alone", num(d.per_trace.rmse_alone)},
                      {"floor", num(d.per_trace.floor)},
                      {"nominal_at_floor", d.per_trace.nominal_at_floor},
                      {"each_at_floor", d.per_trace.each_at_floor},
                      {"parameter", parameter}};
  }
  if (d.specimens.computed) {
    const SpecimenShape& sp = d.specimens;
    auto judged = [&](const ShapeJudged& s) {
      Json factors = Json::array(), zeros = Json::array();
      for (double v : s.stiffness_factor) factors.push_back(num(v));
      for (double v : s.zero) zeros.push_back(num(v));
      return Json{{"exponent", {{"value", num(s.exponent)}, {"unit", ""}, {"uncertainty", num(s.exponent_sigma)}}},
                  {"stiffness_factor", factors},
                  {"zero", {{"value", zeros}, {"unit", "m"}}},
                  {"rmse_before", num(s.rmse_before)},
                  {"rmse_after", num(s.rmse_after)},
                  {"shrink", num(s.shrink)}};
    };
    Json specimens = {{"effect", manifest_of(EffectKind::actee_compliance).name}};
    specimens.update(judged(sp.own_stiffness));
    specimens["first_third"] = num(sp.first_third);
    specimens["last_third"] = num(sp.last_third);
    specimens["own_zero"] = judged(sp.own_zero);
    j["specimens"] = specimens;
  }
  Json events = Json::array(), by_force = Json::array();
  for (size_t i = 0; i < d.by_force_before.size() && i < d.by_force_after.size(); ++i) {
    for (size_t e = 0; e < d.by_force_before[i].events.size(); ++e) {
      const EventGap& b = d.by_force_before[i].events[e];
      const EventGap& a = d.by_force_after[i].events[e];
      events.push_back({{"trace", d.by_force_before[i].file},
                        {"event", b.event},
                        {"measured_t", time(b.measured_t)},
                        {"simulated_t_before", time(b.simulated_t)},
                        {"simulated_t_after", time(a.simulated_t)},
                        {"measured_force", num(b.measured_force)},
                        {"simulated_force_before", num(b.simulated_force)},
                        {"simulated_force_after", num(a.simulated_force)}});
    }
    by_force.push_back({{"trace", d.by_force_before[i].file},
                        {"angle_rmse_before", num(d.by_force_before[i].angle_rmse)},
                        {"angle_rmse_after", num(d.by_force_after[i].angle_rmse)},
                        {"unit", "rad"}});
  }
  j["events"] = events;
  j["by_force"] = by_force;
  j["gain_alike"] = std::isnan(d.gain_alike) ? nlohmann::json(nullptr) : nlohmann::json(d.gain_alike);
  j["gain_alike_explains"] = d.gain_alike_explains;
  j["folds"] = d.folds;
  j["fold_sizes"] = nlohmann::json::array();
  for (const FoldSize& f : d.fold_sizes) j["fold_sizes"].push_back({{"blocks", f.blocks}, {"fitted", f.fitted}});
  j["traces"] = d.judged_on;
  return j.dump();
}

}  // namespace afford
