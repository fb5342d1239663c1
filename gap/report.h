// The diagnosis as text for people and as JSON for programs.
#pragma once

#include <string>

#include "diagnose.h"

namespace afford {

std::string report_text(const Diagnosis& d);

// An effect parameter's SI unit ("N*m"; "" for a plain number), and a value
// with it as the data files write it ("0.311 N*m").
std::string si_unit(const EffectParam& p);
std::string si_quantity(double si, const EffectParam& p);
std::string report_json(const Diagnosis& d);

}  // namespace afford
