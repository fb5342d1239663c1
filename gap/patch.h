// Adopting a diagnosis: copies of the measurement's object, actee and
// measurement files with the fitted effects switched on as data.
#pragma once

#include <string>
#include <vector>

#include "diagnose.h"

namespace afford {

// Writes into `dir` (created if needed) object.yaml and actee.yaml where
// the diagnosis changed them, and measurement.yaml naming them and the
// original traces; returns the files written. Each parameter is written as
// its total, the nominal's value and the fitted change together (the
// report gives both, report.h). A DataError if the tool or
// actee is written inside the measurement rather than in a file of its own.
std::vector<std::string> write_patch(const Measurement& m, const Diagnosis& d, const std::string& dir);

}  // namespace afford
