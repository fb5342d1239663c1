#include "axis_range.h"

#include <cmath>

#include "canvas.h"

namespace afford::render {

double AxisRange::first_tick() const { return std::ceil(lo / step - 1e-9) * step; }

AxisRange axis_range(double lo, double hi, int ticks, double margin) {
  AxisRange r;
  if (!(lo <= hi)) return r;
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) lo -= 0.5, hi += 0.5;
  const double pad = margin * (hi - lo);
  r.lo = lo - pad;
  r.hi = hi + pad;
  if (lo >= 0 && r.lo < 0) r.lo = 0;
  if (hi <= 0 && r.hi > 0) r.hi = 0;
  const double span = r.hi - r.lo;
  r.step = tick_step(span, ticks);
  const double down = std::floor(r.lo / r.step + 1e-9) * r.step, up = std::ceil(r.hi / r.step - 1e-9) * r.step;
  if (r.lo - down <= 0.05 * span) r.lo = down;
  if (up - r.hi <= 0.05 * span) r.hi = up;
  return r;
}

}  // namespace afford::render
