// The page's messages: parsing and checking (with nlohmann::json, without
// exceptions) and formatting (see protocol.h).
#include "protocol.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>

#include "recording.h"
#include "rules_explain.h"

namespace afford::serve {

using Json = nlohmann::json;

namespace {

// A value as the error shows it: short, and never the whole of a huge one.
std::string shown(const Json& v) {
  std::string s = v.dump(-1, ' ', true, Json::error_handler_t::replace);
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool fail(std::string* error, const std::string& text) {
  *error = text;
  return false;
}

// A finite number (JSON has no NaN; integers count as numbers).
bool number(const Json& v, double* out) {
  if (!v.is_number()) return false;
  *out = v.get<double>();
  return std::isfinite(*out);
}

}  // namespace

const char* command_name(CommandKind kind) {
  switch (kind) {
    case CommandKind::thumb: return "thumb";
    case CommandKind::grasp: return "grasp";
    case CommandKind::release: return "release";
    case CommandKind::move: return "move";
    case CommandKind::actee: return "actee";
    case CommandKind::reset: return "reset";
  }
  return "?";
}

bool parse_command(std::string_view text, const CommandLimits& limits, std::span<const std::string> shelf,
                   Command* out, std::string* error) {
  if (text.size() > kMaxMessageBytes) {
    return fail(error, "a message of at most " + std::to_string(kMaxMessageBytes) + " bytes, found " +
                           std::to_string(text.size()) + " bytes");
  }
  if (text.empty()) return fail(error, "a JSON object, found an empty message");
  if (text.find('\0') != std::string_view::npos) return fail(error, "a JSON object, found a NUL byte in the message");
  const Json j = Json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return fail(error, "a JSON object, found text that is not JSON (or is cut short)");
  if (!j.is_object()) return fail(error, "a JSON object, found " + shown(j));
  const auto type_it = j.find("type");
  if (type_it == j.end()) return fail(error, "a message with a \"type\", found none");
  if (!type_it->is_string()) return fail(error, "\"type\" as a string, found " + shown(*type_it));
  const std::string& type = type_it->get_ref<const std::string&>();

  Command c;
  const char* fields = "";  // the keys this type takes besides type and seq
  if (type == "thumb") {
    c.kind = CommandKind::thumb;
    fields = "squeeze";
  } else if (type == "grasp") {
    c.kind = CommandKind::grasp;
  } else if (type == "release") {
    c.kind = CommandKind::release;
  } else if (type == "move") {
    c.kind = CommandKind::move;
    fields = "position";
  } else if (type == "actee") {
    c.kind = CommandKind::actee;
    fields = "name";
  } else if (type == "reset") {
    c.kind = CommandKind::reset;
  } else {
    return fail(error, "a \"type\" of thumb, grasp, release, move, actee or reset, found " + shown(*type_it));
  }
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() == "type" || it.key() == "seq" || (*fields && it.key() == fields)) continue;
    return fail(error, "no key \"" + it.key().substr(0, 40) + "\" in a " + type + " message" +
                           (*fields ? std::string(" (it takes \"") + fields + "\")" : std::string()));
  }
  if (const auto seq = j.find("seq"); seq != j.end()) {
    if (!(seq->is_number_integer() || seq->is_number_unsigned()) || seq->get<std::int64_t>() < 0) {
      return fail(error, "\"seq\" as a non-negative integer, found " + shown(*seq));
    }
    c.seq = seq->get<std::int64_t>();
  }
  if (*fields) {
    const auto v = j.find(fields);
    if (v == j.end()) return fail(error, std::string("a ") + type + " message with \"" + fields + "\", found none");
    if (c.kind == CommandKind::thumb) {
      if (!number(*v, &c.squeeze) || c.squeeze < 0 || c.squeeze > limits.max_squeeze) {
        return fail(error, "\"squeeze\" as a number of metres from 0 to " + fmt(limits.max_squeeze) + ", found " +
                               shown(*v));
      }
    } else if (c.kind == CommandKind::move) {
      bool ok = v->is_array() && v->size() == 3;
      for (size_t i = 0; ok && i < 3; ++i) {
        ok = number((*v)[i], &c.position[i]) && c.position[i] >= limits.hand_min[i] &&
             c.position[i] <= limits.hand_max[i];
      }
      if (!ok) {
        return fail(error, "\"position\" as [x, y, z] in metres within [" + fmt(limits.hand_min[0]) + ", " +
                               fmt(limits.hand_min[1]) + ", " + fmt(limits.hand_min[2]) + "] to [" +
                               fmt(limits.hand_max[0]) + ", " + fmt(limits.hand_max[1]) + ", " +
                               fmt(limits.hand_max[2]) + "], found " + shown(*v));
      }
    } else {  // actee
      std::string names;
      for (size_t i = 0; i < shelf.size(); ++i) {
        if (v->is_string() && v->get_ref<const std::string&>() == shelf[i]) c.actee = static_cast<int>(i);
        names += (i ? ", " : "") + shelf[i];
      }
      if (c.actee < 0) return fail(error, "\"name\" as an actee of the shelf (" + names + "), found " + shown(*v));
    }
  }
  *out = c;
  return true;
}

void encode_command(const Command& c, double t, unsigned char* out) {
  *out++ = static_cast<unsigned char>(c.kind);
  out = put_i64(out, c.seq);
  out = put_f64(out, t);
  out = put_f64(out, c.squeeze);
  for (double v : c.position) out = put_f64(out, v);
  put_u32(out, static_cast<std::uint32_t>(c.actee));
}

Command decode_command(const unsigned char* in, double* t) {
  Command c;
  c.kind = static_cast<CommandKind>(*in++);
  c.seq = get_i64(in);
  *t = get_f64(in + 8);
  c.squeeze = get_f64(in + 16);
  for (size_t i = 0; i < 3; ++i) c.position[i] = get_f64(in + 24 + 8 * i);
  c.actee = static_cast<int>(static_cast<std::int32_t>(get_u32(in + 48)));
  return c;
}

bool SeqCheck::accept(const Command& c) {
  if (c.seq < 0) return true;
  if (c.seq <= last_) return false;
  last_ = c.seq;
  return true;
}

namespace {

void put_pose(std::array<double, 16>* out, const Eigen::Isometry3d& pose) {
  const Eigen::Matrix4d& m = pose.matrix();
  for (int i = 0; i < 16; ++i) (*out)[static_cast<size_t>(i)] = m.data()[i];  // column-major
}

// Appends to a fixed buffer; `ok` turns false when it is full.
struct Writer {
  char* p;
  char* end;
  bool ok = true;
  void raw(const char* s) {
    const size_t n = std::strlen(s);
    if (static_cast<size_t>(end - p) <= n) {
      ok = false;
      return;
    }
    std::memcpy(p, s, n);
    p += n;
  }
  void num(double v) {
    if (!std::isfinite(v)) {
      raw("null");
      return;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    raw(buf);
  }
  void integer(std::int64_t v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v));
    raw(buf);
  }
  void key(const char* k) {
    raw(",\"");
    raw(k);
    raw("\":");
  }
  void boolean(bool b) { raw(b ? "true" : "false"); }
  void array(const double* v, size_t n) {
    raw("[");
    for (size_t i = 0; i < n; ++i) {
      if (i) raw(",");
      num(v[i]);
    }
    raw("]");
  }
};

}  // namespace

void fill_state_message(const State& s, const Model& model, StateMessage* out) {
  out->t = s.t;
  out->frame = s.frame;
  out->angle = s.theta;
  out->grasped = s.grasped;
  out->reaction = s.effort_force;
  out->max_force = s.max_force;
  out->actee_force = s.actee_force;
  out->actee_load = s.actee_load;
  out->actee_limit = model.has_actee ? model.actee_limit : 0;
  out->peak_actee_load = s.peak_actee_load;
  out->condition = condition_name(s.condition);
  out->held = s.held;
  put_pose(&out->object, s.object_pose);
  put_pose(&out->moving_arm, s.object_pose * moving_arm_pose(s.theta));
  put_pose(&out->actee, s.actee_pose);
  put_pose(&out->hand, s.hand);
  for (size_t f = 0; f < 5; ++f) {
    for (int k = 0; k < 3; ++k) out->fingertip[f][static_cast<size_t>(k)] = s.fingertip[f][k];
  }
}

size_t format_state(const StateMessage& m, char* buf, size_t size) {
  if (size == 0) return 0;
  Writer w{buf, buf + size};
  w.raw("{\"type\":\"state\"");
  w.key("trial");
  w.integer(m.trial);
  w.key("t");
  w.num(m.t);
  w.key("frame");
  w.integer(m.frame);
  w.key("angle");
  w.num(m.angle);
  w.key("squeeze");
  w.num(m.squeeze);
  w.key("squeeze_target");
  w.num(m.squeeze_target);
  w.key("gripping");
  w.boolean(m.gripping);
  w.key("grasped");
  w.boolean(m.grasped);
  w.key("reaction");
  w.num(m.reaction);
  w.key("max_force");
  w.num(m.max_force);
  w.key("actee_force");
  w.num(m.actee_force);
  w.key("actee_load");
  w.num(m.actee_load);
  w.key("actee_limit");
  w.num(m.actee_limit);
  w.key("peak_actee_load");
  w.num(m.peak_actee_load);
  w.key("condition");
  w.raw("\"");
  w.raw(m.condition);
  w.raw("\"");
  w.key("held");
  w.boolean(m.held);
  w.key("object");
  w.array(m.object.data(), 16);
  w.key("moving_arm");
  w.array(m.moving_arm.data(), 16);
  w.key("actee");
  w.array(m.actee.data(), 16);
  w.key("hand");
  w.array(m.hand.data(), 16);
  w.key("fingertips");
  w.raw("[");
  for (size_t f = 0; f < m.fingertip.size(); ++f) {
    if (f) w.raw(",");
    w.array(m.fingertip[f].data(), 3);
  }
  w.raw("]");
  w.key("deadline_misses");
  w.integer(m.deadline_misses);
  w.key("applied_seq");
  w.integer(m.applied_seq);
  w.raw("}");
  if (!w.ok) return 0;
  *w.p = '\0';
  return static_cast<size_t>(w.p - buf);
}

std::string hello_message(bool driver) {
  return Json{{"type", "hello"}, {"role", driver ? "driver" : "watcher"}, {"protocol", kProtocolVersion}}.dump();
}

std::string role_message(bool driver) { return Json{{"type", "role"}, {"role", driver ? "driver" : "watcher"}}.dump(); }

std::string error_message(std::string_view message) {
  return Json{{"type", "error"}, {"message", std::string(message)}}.dump(-1, ' ', false,
                                                                          Json::error_handler_t::replace);
}

std::string event_message(const RuleSet& rules, const Event& e, const Inference* inference) {
  static const char* kKinds[] = {"node_reached", "node_lost", "inferred"};
  Json j{{"type", "event"},
         {"kind", kKinds[static_cast<int>(e.kind)]},
         {"t", e.t},
         {"function", function_name(rules, e.function)}};
  if (e.kind != EventKind::inferred) {
    j["node"] = e.node;
    j["text"] = node_text(rules, e.function, e.node);
  }
  if (inference != nullptr) {
    Json nodes = Json::array();
    for (size_t i = 0; i < inference->nodes.size(); ++i) {
      Json n{{"t", inference->nodes[i].t}, {"text", inference->nodes[i].text}};
      if (i < inference->node_details.size() && !inference->node_details[i].empty()) {
        n["detail"] = inference->node_details[i];
      }
      nodes.push_back(std::move(n));
    }
    j["explanation"] = std::move(nodes);
  }
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string frame_event_message(const RuleSet& rules, const RuleState& rs, const Event& e) {
  if (e.kind != EventKind::inferred) return event_message(rules, e, nullptr);
  for (size_t i = inference_count(rs); i-- > 0;) {  // this frame's is the newest of its function and time
    const InferenceValues v = inference_values(rs, i);
    if (v.function != e.function || v.t != e.t) continue;
    const Inference inf = explain_inference(rules, v.function, v.t, v.node_times, v.values);
    return event_message(rules, e, &inf);
  }
  return event_message(rules, e, nullptr);  // not recorded (the rule state's log was full)
}

}  // namespace afford::serve
