#include "event_ring.h"

#include <algorithm>
#include <span>

#include "protocol.h"
#include "rules_explain.h"

namespace afford::serve {

EventRing::EventRing(std::shared_ptr<const RuleSet> rules, size_t capacity)
    : rules_(std::move(rules)),
      max_nodes_(max_inference_nodes(*rules_)),
      max_values_(max_inference_values(*rules_)),
      slots_(capacity),
      times_(capacity * max_nodes_),
      values_(capacity * max_values_),
      out_times_(max_nodes_),
      out_values_(max_values_) {}

bool EventRing::push(const RuleState& rs, const Event& e) {
  std::lock_guard lock(mutex_);
  if (size_ == slots_.size()) {
    ++dropped_;
    return false;
  }
  const size_t at = (head_ + size_) % slots_.size();
  Slot& s = slots_[at];
  s = Slot{e, false, 0, 0};
  if (e.kind == EventKind::inferred) {
    // This frame's inference is the newest record of its function at its time.
    for (size_t i = inference_count(rs); i-- > 0;) {
      const InferenceValues v = inference_values(rs, i);
      if (v.function != e.function || v.t != e.t) continue;
      if (v.node_times.size() <= max_nodes_ && v.values.size() <= max_values_) {
        std::copy(v.node_times.begin(), v.node_times.end(), times_.begin() + static_cast<std::ptrdiff_t>(at * max_nodes_));
        std::copy(v.values.begin(), v.values.end(), values_.begin() + static_cast<std::ptrdiff_t>(at * max_values_));
        s.has_inference = true;
        s.nodes = v.node_times.size();
        s.values = v.values.size();
      }
      break;
    }
  }
  ++size_;
  return true;
}

bool EventRing::pop(std::string* message) {
  {
    std::lock_guard lock(mutex_);
    if (size_ == 0) return false;
    out_ = slots_[head_];
    std::copy_n(times_.begin() + static_cast<std::ptrdiff_t>(head_ * max_nodes_), out_.nodes, out_times_.begin());
    std::copy_n(values_.begin() + static_cast<std::ptrdiff_t>(head_ * max_values_), out_.values, out_values_.begin());
    head_ = (head_ + 1) % slots_.size();
    --size_;
  }
  if (!out_.has_inference) {
    *message = event_message(*rules_, out_.event, nullptr);
    return true;
  }
  const Inference inf =
      explain_inference(*rules_, out_.event.function, out_.event.t, std::span<const double>(out_times_.data(), out_.nodes),
                        std::span<const double>(out_values_.data(), out_.values));
  *message = event_message(*rules_, out_.event, &inf);
  return true;
}

long EventRing::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

}  // namespace afford::serve
