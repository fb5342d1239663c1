#include "outcome.h"

#include <utility>

namespace afford {

namespace {
// A frame time this close below applied_at counts as reaching it (frame
// times are sums of the step).
constexpr double kTimeSlack = 1e-9;  // s
}  // namespace

OutcomeWatch::OutcomeWatch(std::vector<int> strength, double applied_at)
    : strength_(std::move(strength)),
      in_force_(strength_.size(), 0),
      reached_(strength_.size(), 0),
      applied_at_(applied_at) {}

void OutcomeWatch::frame(double t, const Event* begin, const Event* end, bool broken, bool grasped) {
  // In order: a node lost and the function inferred again in one frame ends in force.
  for (const Event* ev = begin; ev != end; ++ev) {
    const size_t f = static_cast<size_t>(ev->function);
    if (ev->kind == EventKind::inferred) in_force_[f] = 1;
    if (ev->kind == EventKind::node_lost) in_force_[f] = 0;
  }
  if (from_ < 0 && (t >= applied_at_ - kTimeSlack || broken)) from_ = t;
  if (from_ < 0 || !grasped) return;
  for (size_t f = 0; f < in_force_.size(); ++f) reached_[f] = reached_[f] | in_force_[f];
}

int OutcomeWatch::outcome() const {
  int best = -1;
  for (size_t f = 0; f < reached_.size(); ++f) {
    if (reached_[f] && (best < 0 || strength_[f] > strength_[static_cast<size_t>(best)])) best = static_cast<int>(f);
  }
  return best;
}

}  // namespace afford
