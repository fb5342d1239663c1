// The range an axis of a chart shows for its data, and its ticks: the data
// and a margin, never a whole empty tick step more. Rounding the ends out
// to a tick is only done when that adds little; a quantity that never goes
// below zero (a force, a time) starts its axis at zero, not below it.
#pragma once

namespace afford::render {

struct AxisRange {
  double lo = 0, hi = 1;  // data units, the axis's ends
  double step = 1;        // between ticks; ticks at the multiples of it in [lo, hi]
  double first_tick() const;
};

// For data from lo to hi (finite; lo > hi: no data), about `ticks` ticks:
//  1. no data: [0, 1]; one value v: [v - 0.5, v + 0.5];
//  2. a margin of `margin` times the span on each side;
//  3. an end the margin takes past zero stays at zero when the data does not
//     cross it (data from 0 to 3400 N starts at 0 N, not at -136 N);
//  4. the step is tick_step(span, ticks): 1, 2 or 5 times a power of ten;
//  5. each end moves out to the next multiple of the step when that adds at
//     most 5 % of the span (0 to 88.3 s shows 0 to 90 s; 0 to 3536 N with
//     a step of 1000 N stays at 3536 N rather than add 464 N of nothing).
AxisRange axis_range(double lo, double hi, int ticks, double margin);

}  // namespace afford::render
