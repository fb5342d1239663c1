// The difference of two timelines of rule events: a recording's and a
// re-run's under edited function models (`afford replay --rules`). Events
// are matched by what they are, not by index (an edit may add functions or
// nodes): the kind, the function's name and, for node events, the node's
// `when` as written. The n-th occurrence of an event in one timeline is
// paired with the n-th of the same event in the other; a pair at different
// times is shifted, an occurrence without a partner is only in one.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "observer.h"
#include "rules.h"

namespace afford {

struct NamedEvent {
  EventKind kind = EventKind::inferred;
  double t = 0;          // s
  std::string function;  // its name
  int node = 0;          // index, for node events
  std::string text;      // the node's `when` as written (node events)
};

// Names events of a rule set (function names and node texts).
NamedEvent name_event(const RuleSet& rules, const Event& e);

// "2.560 s  crash inferred", "1.100 s  hold node 2 reached: held(actee)".
std::string format_event(const NamedEvent& e);

struct TimelineChange {
  enum Kind { removed, added, shifted } kind = removed;
  NamedEvent before;  // in the first timeline (removed, shifted)
  NamedEvent after;   // in the second (added, shifted)
};

struct TimelineDiff {
  std::vector<TimelineChange> changes;  // ordered by time (the earlier of a shifted pair)
  size_t same = 0;                      // events in both at the same time
  size_t shifted = 0, removed = 0, added = 0;
  bool identical() const { return changes.empty(); }
};

TimelineDiff diff_timelines(const std::vector<NamedEvent>& before, const std::vector<NamedEvent>& after);

// The diff as text, one line per event: "- 2.560 s  crash inferred" for the
// first timeline, "+ 2.731 s  crash inferred  (+0.171 s)" for the second.
std::string format_diff(const TimelineDiff& diff);

// An observer that keeps every event of a run, named. Reserves room in
// on_start; it allocates in a frame only when a run has far more events
// than reserved (it serves replays, not the live loop).
class TimelineCollector : public Observer {
 public:
  explicit TimelineCollector(size_t reserve = 4096) : reserve_(reserve) {}
  void on_start(const Model& model, const State& state, const RuleSet& rules) override;
  void on_frame(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override;
  // The events named after the run (allocates).
  std::vector<NamedEvent> named(const RuleSet& rules) const;
  const std::vector<Event>& events() const { return events_; }

 private:
  size_t reserve_;
  std::vector<Event> events_;
};

}  // namespace afford
