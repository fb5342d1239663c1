#pragma once
#include <vector>

namespace afford {

// The step a column's values are counted in (an encoder's count, a
// converter's least bit) where it is coarser than their printed digits:
// every change from one sample to the next a whole number of it, to
// within the printing's own step `printed` (the same unit). 0 where the
// values are no coarser than printed, change too seldom to tell, or
// change by amounts no one step divides.
double counted_step(const std::vector<double>& values, double printed);

}  // namespace afford
