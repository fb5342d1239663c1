// The rules' events, from the frame thread to the sender thread without
// allocating: the frame copies each event, and for an inference what its
// explanation needs (its node times and values, engine/rules/rules_explain.h),
// into a ring sized when the trial begins; the sender takes them out and
// writes the event messages (protocol.h), text and all, off the frame
// thread.
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "rules.h"

namespace afford::serve {

class EventRing {
 public:
  static constexpr size_t kCapacity = 1024;  // events waiting for the sender; more are dropped (counted)

  explicit EventRing(std::shared_ptr<const RuleSet> rules, size_t capacity = kCapacity);

  // Frame thread: the frame's event e of the rule state rs. False (and
  // counted) when the ring is full. Allocates nothing.
  bool push(const RuleState& rs, const Event& e);

  // Sender thread: the oldest event's message (protocol.h's event_message,
  // with the explanation for an inference), removed from the ring; false
  // when it is empty. Allocates (the text).
  bool pop(std::string* message);

  long dropped() const;
  const RuleSet& rules() const { return *rules_; }

 private:
  struct Slot {
    Event event;
    bool has_inference = false;  // an inferred event whose record was found
    size_t nodes = 0, values = 0;
  };

  std::shared_ptr<const RuleSet> rules_;
  size_t max_nodes_ = 0, max_values_ = 0;
  mutable std::mutex mutex_;
  std::vector<Slot> slots_;
  std::vector<double> times_, values_;  // per slot: max_nodes_ and max_values_ of them
  size_t head_ = 0, size_ = 0;
  long dropped_ = 0;
  // The sender's copy of the slot it writes out (outside the lock).
  Slot out_;
  std::vector<double> out_times_, out_values_;
};

}  // namespace afford::serve
