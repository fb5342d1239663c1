#include "counted_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace afford {
namespace {

// A step coarser than the printing by less than this is the printing's.
constexpr double kCoarser = 10;
// The share of changes a step must divide: a glitch or two may not.
constexpr double kDivided = 0.99;
// Too few changes, or too few of one step, tell no count: a column that
// holds one value and then another has no step but that change.
constexpr size_t kMinChanges = 20;
constexpr size_t kMinSingleSteps = 3;
// Changes of up to this many least changes name their count of steps
// surely, however the printing rounded the least (it is within a tenth).
constexpr double kSureCount = 4.5;

// Calls `visit` with each change between neighbouring samples that the
// printing can tell from none (the same unit as the values).
template <typename Visit>
void for_each_change(const std::vector<double>& values, double printed, Visit visit) {
  for (size_t i = 1; i < values.size(); ++i) {
    const double change = std::abs(values[i] - values[i - 1]);
    if (change > printed) visit(change);
  }
}

// The step that fits the changes, each the nearest whole number of
// `guess`, by least squares; only changes under `most` count.
double fitted_step(const std::vector<double>& values, double printed, double guess, double most) {
  double counted = 0, squares = 0;
  for_each_change(values, printed, [&](double c) {
    if (c > most) return;
    const double k = std::round(c / guess);
    counted += k * c;
    squares += k * k;
  });
  return counted / squares;
}

}  // namespace

double counted_step(const std::vector<double>& values, double printed) {
  if (!(printed > 0)) return 0.0;
  size_t changes = 0;
  double least = std::numeric_limits<double>::infinity();
  for_each_change(values, printed, [&](double c) {
    ++changes;
    least = std::min(least, c);
  });
  if (changes < kMinChanges || least < kCoarser * printed) return 0.0;
  // The least change is one step, as printed: refined first on the changes
  // whose count is sure, then on all.
  const double sure = fitted_step(values, printed, least, kSureCount * least);
  const double step = fitted_step(values, printed, sure, std::numeric_limits<double>::infinity());
  size_t divided = 0, single = 0;
  for_each_change(values, printed, [&](double c) {
    const double k = std::round(c / step);
    divided += std::abs(c - k * step) <= 1.5 * printed ? 1 : 0;
    single += k == 1 ? 1 : 0;
  });
  const bool counted = static_cast<double>(divided) >= kDivided * static_cast<double>(changes);
  return counted && single >= kMinSingleSteps ? step : 0.0;
}

}  // namespace afford
