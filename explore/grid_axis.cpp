#include "grid_axis.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "number_format.h"

namespace afford {

double tidy(double v) {
  if (!std::isfinite(v) || v == 0) return v;
  char buf[64];
  const char* end = write_general(buf, buf + sizeof buf, v, 12);
  double out = v;
  std::from_chars(buf, end, out);
  return out;
}

std::vector<double> spread(double from, double to, int n) {
  if (n == 1) return {tidy(0.5 * (from + to))};
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(tidy(from + (to - from) * i / (n - 1)));
  return v;
}

double effort_axis_top(double last_turn, int n, double max_effort, double min_step) {
  if (n < 2 || !(last_turn > 0)) return max_effort;
  const double wanted = std::max(min_step, kTurnMargin * last_turn / (n - 1));  // N, the smallest step that will do
  const double decade = std::pow(10.0, std::floor(std::log10(wanted)));
  double step = 10 * decade;
  for (double m : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0}) {
    if (tidy(m * decade) >= wanted) {
      step = m * decade;
      break;
    }
  }
  return std::min(max_effort, tidy(step * (n - 1)));
}

}  // namespace afford
