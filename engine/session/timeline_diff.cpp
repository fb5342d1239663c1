// Timeline differences (timeline_diff.h).
#include "timeline_diff.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace afford {
namespace {

std::string key(const NamedEvent& e) {
  std::string k(1, static_cast<char>('0' + static_cast<int>(e.kind)));
  k += e.function;
  if (e.kind != EventKind::inferred) k += '\n' + e.text;
  return k;
}

std::string seconds(double t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", t);
  return buf;
}

double when(const TimelineChange& c) {
  switch (c.kind) {
    case TimelineChange::removed: return c.before.t;
    case TimelineChange::added: return c.after.t;
    case TimelineChange::shifted: return std::min(c.before.t, c.after.t);
  }
  return 0;
}

}  // namespace

NamedEvent name_event(const RuleSet& rules, const Event& e) {
  NamedEvent n;
  n.kind = e.kind;
  n.t = e.t;
  n.function = function_name(rules, e.function);
  const int nodes = node_count(rules, e.function);
  n.node = e.kind == EventKind::inferred || e.node < 0 || e.node >= nodes ? nodes - 1 : e.node;
  if (n.node >= 0) n.text = node_text(rules, e.function, n.node);
  return n;
}

std::string format_event(const NamedEvent& e) {
  std::string s = seconds(e.t) + "  " + e.function;
  switch (e.kind) {
    case EventKind::inferred: return s + " inferred";
    case EventKind::node_reached: return s + " node " + std::to_string(e.node) + " reached: " + e.text;
    case EventKind::node_lost: return s + " node " + std::to_string(e.node) + " lost: " + e.text;
  }
  return s;
}

TimelineDiff diff_timelines(const std::vector<NamedEvent>& before, const std::vector<NamedEvent>& after) {
  // Occurrences of each event, in time order, in either timeline.
  std::map<std::string, std::pair<std::vector<size_t>, std::vector<size_t>>> by_key;
  for (size_t i = 0; i < before.size(); ++i) by_key[key(before[i])].first.push_back(i);
  for (size_t i = 0; i < after.size(); ++i) by_key[key(after[i])].second.push_back(i);
  TimelineDiff d;
  for (const auto& [k, lists] : by_key) {
    const auto& [b, a] = lists;
    const size_t pairs = std::min(b.size(), a.size());
    for (size_t i = 0; i < pairs; ++i) {
      if (before[b[i]].t == after[a[i]].t) {
        ++d.same;
        continue;
      }
      d.changes.push_back({TimelineChange::shifted, before[b[i]], after[a[i]]});
      ++d.shifted;
    }
    for (size_t i = pairs; i < b.size(); ++i) {
      d.changes.push_back({TimelineChange::removed, before[b[i]], {}});
      ++d.removed;
    }
    for (size_t i = pairs; i < a.size(); ++i) {
      d.changes.push_back({TimelineChange::added, {}, after[a[i]]});
      ++d.added;
    }
  }
  std::stable_sort(d.changes.begin(), d.changes.end(),
                   [](const TimelineChange& x, const TimelineChange& y) { return when(x) < when(y); });
  return d;
}

std::string format_diff(const TimelineDiff& diff) {
  std::string out;
  for (const TimelineChange& c : diff.changes) {
    if (c.kind != TimelineChange::added) out += "- " + format_event(c.before) + "\n";
    if (c.kind != TimelineChange::removed) {
      out += "+ " + format_event(c.after);
      if (c.kind == TimelineChange::shifted) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "  (%+.3f s)", c.after.t - c.before.t);
        out += buf;
      }
      out += "\n";
    }
  }
  return out;
}

void TimelineCollector::on_start(const Model&, const State&, const RuleSet&) {
  events_.clear();
  events_.reserve(reserve_);
}

void TimelineCollector::on_frame(const Model&, const State&, const RuleSet&, const RuleState& rs) {
  events_.insert(events_.end(), events_begin(rs), events_end(rs));
}

std::vector<NamedEvent> TimelineCollector::named(const RuleSet& rules) const {
  std::vector<NamedEvent> out;
  out.reserve(events_.size());
  for (const Event& e : events_) out.push_back(name_event(rules, e));
  return out;
}

}  // namespace afford
