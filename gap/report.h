// The diagnosis as text for people and as JSON for programs.
#pragma once

#include <string>

#include "diagnose.h"

namespace afford {

// `nominal`: the model the diagnosis started from (nominal_model()). Each
// fitted parameter is then given as its change over the nominal's, the
// nominal and the total (the text: "torque +0.3 N*m over the nominal 0.01
// (0.31 in all)"); without it, as the total alone, and said so.
std::string report_text(const Diagnosis& d, const Model* nominal = nullptr);

// An effect parameter's SI unit ("N*m"; "" for a plain number), and a value
// with it as the data files write it ("0.311 N*m").
std::string si_unit(const EffectParam& p);
std::string si_quantity(double si, const EffectParam& p);
std::string report_json(const Diagnosis& d, const Model* nominal = nullptr);

// The model the diagnosis of `m` starts from: what a fitted change adds to.
Model nominal_model(const Measurement& m);

// A fitted effect's parameter i against the nominal model: the total (the
// value in effect, what a file writes), the change over the nominal, and
// the nominal; has_nominal is false where the nominal model has no such
// value (the reference of an actee's linear law), and change is then 0.
struct ParameterChange {
  double total = 0, change = 0, nominal = 0;  // SI
  bool has_nominal = true;
};
ParameterChange parameter_change(const EffectFit& fit, size_t i, const Model& nominal);

}  // namespace afford
