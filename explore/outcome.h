// A grid point's outcome (paper Sec. 2.2): the strongest function it
// reached while the hand applied the point's effort. Functions reached only
// on the way up and lost before the push got there (a sponge held until the
// squeeze passes its limit) do not count, nor do moments while the hand has
// let go of the tool. A break is for good: from the frame the actee breaks
// the window is open, whatever the push has reached by then. "Strongest"
// is the function models' own order (rules/functions.yaml `strength`).
#pragma once

#include <cstdint>
#include <vector>

#include "rules.h"

namespace afford {

class OutcomeWatch {
 public:
  // strength: per function, its rank (function_strength); applied_at: s,
  // when the push reaches the point's effort. Allocates here, never in frame().
  OutcomeWatch(std::vector<int> strength, double applied_at);

  // One frame after the rules ran: its time, its events, whether the actee
  // is broken and whether the hand grasps the tool.
  void frame(double t, const Event* begin, const Event* end, bool broken, bool grasped);

  // The strongest function in force at some moment of the window; -1: none.
  int outcome() const;
  // s, when the window opened; -1: never.
  double window_from() const { return from_; }

 private:
  std::vector<int> strength_;
  std::vector<std::uint8_t> in_force_;  // per function, inferred and not lost since
  std::vector<std::uint8_t> reached_;   // per function, in force at some moment of the window
  double applied_at_ = 0, from_ = -1;
};

}  // namespace afford
