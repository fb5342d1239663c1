// Lever patterns (paper Fig. 2) from where the effort and the load sit.
#pragma once

#include <optional>
#include <string>

#include "spec.h"

namespace afford {

// A type 1 lever counts as balanced while its mechanical advantage is within
// this factor of 1 (scissors are never exactly symmetric).
inline constexpr double kBalanceTolerance = 1.1;

// The pattern made by an effort at signed distance effort_m and a load at
// load_m from the fulcrum (both nonzero).
LeverPattern pattern_at(double effort_m, double load_m);

// The pattern the two regions make over their whole extent, or nullopt with
// `why` saying what is wrong (a region across the fulcrum, regions that
// overlap).
std::optional<LeverPattern> derive_pattern(const RangeSpec& emphasis, const RangeSpec& application,
                                           std::string* why);

// Force at the load per unit force at the effort: |effort| / |load|.
double mechanical_advantage(double effort_m, double load_m);

}  // namespace afford
