// The diagnosis as text for people and as JSON for programs.
#pragma once

#include <string>

#include "diagnose.h"

namespace afford {

std::string report_text(const Diagnosis& d);
std::string report_json(const Diagnosis& d);

}  // namespace afford
