#include "trace.h"

#include <cmath>

namespace afford {

const char* TraceWriter::header() {
  return "t,angle,effort_force,actee_force,effort_pos,broken,grasped,held,contacts_object_actee,actee_load";
}

void TraceWriter::on_start(const Model&, const State&, const RuleSet&) { std::fprintf(out_, "%s\n", header()); }

void TraceWriter::on_frame(const Model& m, const State& s, const RuleSet&, const RuleState&) {
  const double effort_pos = s.grasped ? std::abs(s.effort_distance) * (m.theta_rest - s.theta_command) : 0.0;
  std::fprintf(out_, "%.6f,%.9g,%.9g,%.9g,%.9g,%d,%d,%d,%d,%.9g\n", s.t, s.theta, s.effort_force, s.actee_force,
               effort_pos, s.condition == ActeeCondition::broken ? 1 : 0, s.grasped ? 1 : 0, s.held ? 1 : 0,
               s.object_actee.count, s.actee_load);
}

void TraceWriter::on_end(const Model&, const State&, const RuleSet&, const RuleState&) { std::fflush(out_); }

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

void TimelineWriter::on_start(const Model&, const State&, const RuleSet& rules) {
  function_json_.clear();
  node_json_.clear();
  for (int f = 0; f < function_count(rules); ++f) {
    function_json_.push_back(json_string(function_name(rules, f)));
    std::vector<std::string> nodes;
    for (int n = 0; n < node_count(rules, f); ++n) nodes.push_back(json_string(node_text(rules, f, n)));
    node_json_.push_back(std::move(nodes));
  }
}

void TimelineWriter::on_frame(const Model&, const State&, const RuleSet&, const RuleState& rs) {
  static const char* const kKinds[] = {"node_reached", "node_lost", "inferred"};
  for (const Event* e = events_begin(rs); e != events_end(rs); ++e) {
    const size_t f = static_cast<size_t>(e->function);
    const std::vector<std::string>& nodes = node_json_[f];
    int node = e->node;
    if (e->kind == EventKind::inferred || node < 0 || node >= static_cast<int>(nodes.size())) {
      node = static_cast<int>(nodes.size()) - 1;
    }
    std::fprintf(out_, "{\"t\":%.6f,\"event\":\"%s\",\"function\":%s,\"node\":%d,\"text\":%s}\n", e->t,
                 kKinds[static_cast<int>(e->kind)], function_json_[f].c_str(), node,
                 node >= 0 ? nodes[static_cast<size_t>(node)].c_str() : "\"\"");
  }
}

void TimelineWriter::on_end(const Model&, const State&, const RuleSet&, const RuleState&) { std::fflush(out_); }

}  // namespace afford
