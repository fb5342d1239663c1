#include "lever.h"

#include <cmath>

namespace afford {

const char* pattern_name(LeverPattern p) {
  switch (p) {
    case LeverPattern::type1_power: return "type1-power";
    case LeverPattern::type1_distance: return "type1-distance";
    case LeverPattern::type1_balance: return "type1-balance";
    case LeverPattern::type2: return "type2";
    case LeverPattern::type3: return "type3";
  }
  return "?";
}

double mechanical_advantage(double effort_m, double load_m) {
  return std::abs(effort_m) / std::abs(load_m);
}

LeverPattern pattern_at(double effort_m, double load_m) {
  const double ma = mechanical_advantage(effort_m, load_m);
  if ((effort_m > 0) != (load_m > 0)) {  // fulcrum between effort and load
    if (ma > kBalanceTolerance) return LeverPattern::type1_power;
    if (ma < 1.0 / kBalanceTolerance) return LeverPattern::type1_distance;
    return LeverPattern::type1_balance;
  }
  return ma >= 1.0 ? LeverPattern::type2 : LeverPattern::type3;
}

std::optional<LeverPattern> derive_pattern(const RangeSpec& emphasis, const RangeSpec& application,
                                           std::string* why) {
  auto straddles = [](const RangeSpec& r) { return r.from < 0 && r.to > 0; };
  if (straddles(emphasis) || straddles(application)) {
    *why = "emphasis and application regions each on one side of the fulcrum";
    return std::nullopt;
  }
  const bool emphasis_positive = emphasis.to > 0;
  const bool application_positive = application.to > 0;
  if (emphasis_positive != application_positive) {
    return pattern_at(emphasis.middle(), application.middle());
  }
  // Same side: compare distances from the fulcrum over the whole regions.
  const double em_near = std::min(std::abs(emphasis.from), std::abs(emphasis.to));
  const double em_far = std::max(std::abs(emphasis.from), std::abs(emphasis.to));
  const double ap_near = std::min(std::abs(application.from), std::abs(application.to));
  const double ap_far = std::max(std::abs(application.from), std::abs(application.to));
  if (ap_far <= em_near) return LeverPattern::type2;
  if (em_far <= ap_near) return LeverPattern::type3;
  *why = "emphasis and application regions that do not overlap";
  return std::nullopt;
}

}  // namespace afford
