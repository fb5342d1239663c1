#include "trace.h"

#include <charconv>
#include <cmath>
#include <cstring>

#include "number_format.h"

namespace afford {

const char* TraceWriter::units() {
  return "# units: t s, angle rad, effort_force N, actee_force N, effort_pos m, broken 0/1, grasped 0/1, held 0/1, "
         "contacts_object_actee count, actee_load N";
}

const char* TraceWriter::header() {
  return "t,angle,effort_force,actee_force,effort_pos,broken,grasped,held,contacts_object_actee,actee_load";
}

void TraceWriter::on_start(const Model&, const State&, const RuleSet&) {
  std::fprintf(out_, "%s\n%s\n", units(), header());
}

namespace {

// As printf's "%.6f" and "%.9g" (number_format.h). Each appends a comma.
char* put_fixed6(char* p, char* end, double v) {
  p = write_fixed(p, end, v, 6);
  *p++ = ',';
  return p;
}

char* put_int(char* p, char* end, int v) {
  p = std::to_chars(p, end, v).ptr;
  *p++ = ',';
  return p;
}

}  // namespace

char* TraceWriter::put_general9(char* p, char* end, double v, Written& last) {
  // The same bits give the same text (bits, not ==: 0.0 and -0.0 print differently).
  if (last.valid && std::memcmp(&v, &last.value, sizeof v) == 0) {
    std::memcpy(p, last.text, last.size);
    p += last.size;
  } else {
    char* const start = p;
    p = write_general(p, end, v, 9);
    last.size = static_cast<std::uint8_t>(p - start);
    std::memcpy(last.text, start, last.size);
    last.value = v;
    last.valid = true;
  }
  *p++ = ',';
  return p;
}

size_t TraceWriter::format_row(char* buf, size_t size, double t, double angle, double effort_force,
                               double actee_force, double effort_pos, int broken, int grasped, int held,
                               int contacts, double actee_load) {
  // Fits whatever the values: t in fixed notation is at most 317 characters
  // (-1e308), each %.9g field at most 16 ("-1.23456789e-308") and each
  // integer 11, with its comma: under 480 < kMaxRow.
  char* const end = buf + size;
  char* p = buf;
  p = put_fixed6(p, end, t);
  p = put_general9(p, end, angle, angle_);
  p = put_general9(p, end, effort_force, effort_force_);
  p = put_general9(p, end, actee_force, actee_force_);
  p = put_general9(p, end, effort_pos, effort_pos_);
  p = put_int(p, end, broken);
  p = put_int(p, end, grasped);
  p = put_int(p, end, held);
  p = put_int(p, end, contacts);
  p = put_general9(p, end, actee_load, actee_load_);
  p[-1] = '\n';  // the last comma ends the row
  return static_cast<size_t>(p - buf);
}

void TraceWriter::on_frame(const Model& m, const State& s, const RuleSet&, const RuleState&) {
  const double effort_pos = s.grasped ? std::abs(s.effort_distance) * (m.theta_rest - s.theta_command) : 0.0;
  char row[kMaxRow];
  const size_t n = format_row(row, sizeof row, s.t, s.theta, s.effort_force, s.actee_force, effort_pos,
                              s.condition == ActeeCondition::broken ? 1 : 0, s.grasped ? 1 : 0, s.held ? 1 : 0,
                              s.object_actee.count, s.actee_load);
  std::fwrite(row, 1, n, out_);
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

void TimelineWriter::on_start(const Model& model, const State&, const RuleSet& rules) {
  model_ = &model;
  out_of_reach_.fill(false);
  function_json_.clear();
  node_json_.clear();
  for (int f = 0; f < function_count(rules); ++f) {
    function_json_.push_back(json_string(function_name(rules, f)));
    std::vector<std::string> nodes;
    for (int n = 0; n < node_count(rules, f); ++n) nodes.push_back(json_string(node_text(rules, f, n)));
    node_json_.push_back(std::move(nodes));
  }
}

void TimelineWriter::on_frame(const Model& model, const State& state, const RuleSet&, const RuleState& rs) {
  static const char* const kKinds[] = {"node_reached", "node_lost", "inferred"};
  // Actee names are names (read_name): nothing in them to escape.
  if (&model != model_) {
    std::fprintf(out_, "{\"t\":%.6f,\"event\":\"actee\",\"actee\":\"%s\"}\n", state.t, model.actee_name.c_str());
    model_ = &model;
  }
  for (size_t f = 0; f < kFingers; ++f) {
    const bool out = state.reach_short[f] > 0;
    if (out == out_of_reach_[f]) continue;
    out_of_reach_[f] = out;
    if (out) {
      std::fprintf(out_, "{\"t\":%.6f,\"event\":\"out_of_reach\",\"finger\":\"%s\",\"short_m\":%.6g}\n", state.t,
                   kFingerNames[f], state.reach_short[f]);
    } else {
      std::fprintf(out_, "{\"t\":%.6f,\"event\":\"within_reach\",\"finger\":\"%s\"}\n", state.t, kFingerNames[f]);
    }
  }
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
