// afford serve without sockets: the page's messages (bad, truncated, huge,
// out of order), the state and event messages, the hand a page drives
// (the paper-tongs experiment driven by commands infers pinch, hold, carry
// and crash), the trials' session files and the scene.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "event_ring.h"
#include "page_agent.h"
#include "protocol.h"
#include "run.h"
#include "scene_message.h"
#include "session.h"
#include "trial.h"
#include "test_util.h"

namespace afford::serve {
namespace {
using test::kSource;

using ::testing::HasSubstr;
using Json = nlohmann::json;
namespace fs = std::filesystem;

const std::vector<std::string> kShelf = {"egg", "walnut"};

CommandLimits limits() {
  CommandLimits l;
  l.max_squeeze = 0.05;
  l.hand_min = {-0.5, -0.5, 0};
  l.hand_max = {0.5, 0.5, 0.5};
  return l;
}

// The error of a message that must be dropped ("" when it is accepted).
std::string error_of(std::string_view text) {
  Command c;
  std::string error;
  if (parse_command(text, limits(), kShelf, &c, &error)) return "";
  EXPECT_FALSE(error.empty());
  return error;
}

Command parsed(std::string_view text) {
  Command c;
  std::string error;
  EXPECT_TRUE(parse_command(text, limits(), kShelf, &c, &error)) << text << ": " << error;
  return c;
}

TEST(ServeProtocol, ReadsEveryCommand) {
  EXPECT_EQ(parsed(R"({"type":"grasp"})").kind, CommandKind::grasp);
  EXPECT_EQ(parsed(R"({"type":"release"})").kind, CommandKind::release);
  EXPECT_EQ(parsed(R"({"type":"reset"})").kind, CommandKind::reset);
  const Command thumb = parsed(R"({"type":"thumb","squeeze":0.012,"seq":7})");
  EXPECT_EQ(thumb.kind, CommandKind::thumb);
  EXPECT_EQ(thumb.squeeze, 0.012);
  EXPECT_EQ(thumb.seq, 7);
  EXPECT_EQ(parsed(R"({"type":"thumb","squeeze":0})").seq, -1);
  const Command move = parsed(R"({"type":"move","position":[0.06,-0.1,0.2]})");
  EXPECT_EQ(move.kind, CommandKind::move);
  EXPECT_EQ(move.position[1], -0.1);
  EXPECT_EQ(parsed(R"({"type":"actee","name":"walnut"})").actee, 1);
  EXPECT_EQ(parsed(R"(  {"seq":1, "type":"grasp"}  )").kind, CommandKind::grasp);  // any key order, spaces
}

TEST(ServeProtocol, DropsBadJson) {
  EXPECT_THAT(error_of(""), HasSubstr("empty message"));
  EXPECT_THAT(error_of("grasp"), HasSubstr("not JSON"));
  EXPECT_THAT(error_of("{\"type\":\"grasp\"} trailing"), HasSubstr("not JSON"));
  EXPECT_THAT(error_of("[1,2,3]"), HasSubstr("a JSON object, found [1,2,3]"));
  EXPECT_THAT(error_of("42"), HasSubstr("a JSON object"));
  EXPECT_THAT(error_of("\"grasp\""), HasSubstr("a JSON object"));
  EXPECT_THAT(error_of("null"), HasSubstr("a JSON object"));
  EXPECT_THAT(error_of(std::string("{\"type\":\"gr\xff\xfe\"}")), HasSubstr("not JSON"));  // invalid UTF-8
  EXPECT_THAT(error_of(std::string("{\"type\":\"grasp\"}\0", 17)), HasSubstr("a NUL byte"));
}

TEST(ServeProtocol, DropsTruncatedMessages) {
  const std::string whole = R"({"type":"move","position":[0.06,-0.1,0.2],"seq":12})";
  ASSERT_EQ(error_of(whole), "");
  for (size_t n = 0; n < whole.size(); ++n) {
    EXPECT_NE(error_of(whole.substr(0, n)), "") << "cut at " << n;  // every prefix is dropped, none crashes
  }
}

TEST(ServeProtocol, DropsHugeMessages) {
  std::string huge = R"({"type":"grasp","pad":")" + std::string(kMaxMessageBytes, 'x') + "\"}";
  EXPECT_THAT(error_of(huge), HasSubstr("at most 4096 bytes, found " + std::to_string(huge.size())));
  // Deep nesting within the size limit: parsed, refused, no stack trouble.
  const std::string deep = std::string(2000, '[') + std::string(2000, ']');
  EXPECT_THAT(error_of(deep), HasSubstr("a JSON object"));
  const std::string deep_object = R"({"type":"thumb","squeeze":)" + std::string(1900, '[') + std::string(1900, ']') + "}";
  EXPECT_THAT(error_of(deep_object), HasSubstr("\"squeeze\" as a number"));
}

TEST(ServeProtocol, DropsUnknownTypesAndKeys) {
  EXPECT_THAT(error_of(R"({"squeeze":0.01})"), HasSubstr("a message with a \"type\""));
  EXPECT_THAT(error_of(R"({"type":3})"), HasSubstr("\"type\" as a string, found 3"));
  EXPECT_THAT(error_of(R"({"type":"squash"})"),
              HasSubstr("a \"type\" of thumb, grasp, release, move, actee or reset, found \"squash\""));
  EXPECT_THAT(error_of(R"({"type":"grasp","force":3})"), HasSubstr("no key \"force\" in a grasp message"));
  EXPECT_THAT(error_of(R"({"type":"grasp","":3})"), HasSubstr("no key \"\" in a grasp message"));
  EXPECT_THAT(error_of(R"({"type":"thumb","squeez":0.01})"), HasSubstr("it takes \"squeeze\""));
}

TEST(ServeProtocol, DropsWrongFieldTypesAndRanges) {
  EXPECT_THAT(error_of(R"({"type":"thumb"})"), HasSubstr("a thumb message with \"squeeze\", found none"));
  EXPECT_THAT(error_of(R"({"type":"thumb","squeeze":"0.01"})"),
              HasSubstr("\"squeeze\" as a number of metres from 0 to 0.05, found \"0.01\""));
  EXPECT_THAT(error_of(R"({"type":"thumb","squeeze":true})"), HasSubstr("found true"));
  EXPECT_THAT(error_of(R"({"type":"thumb","squeeze":-0.001})"), HasSubstr("from 0 to 0.05"));
  EXPECT_THAT(error_of(R"({"type":"thumb","squeeze":1e308})"), HasSubstr("from 0 to 0.05"));
  EXPECT_NE(error_of(R"({"type":"thumb","squeeze":1e999})"), "");  // overflows: not a number JSON can hold
  EXPECT_THAT(error_of(R"({"type":"move","position":[0.1,0.2]})"), HasSubstr("\"position\" as [x, y, z]"));
  EXPECT_THAT(error_of(R"({"type":"move","position":[0.1,0.2,"z"]})"), HasSubstr("\"position\" as [x, y, z]"));
  EXPECT_THAT(error_of(R"({"type":"move","position":{"x":0}})"), HasSubstr("\"position\" as [x, y, z]"));
  EXPECT_THAT(error_of(R"({"type":"move","position":[0.1,0.2,0.9]})"), HasSubstr("within [-0.5, -0.5, 0]"));
  EXPECT_THAT(error_of(R"({"type":"actee","name":"coconut"})"),
              HasSubstr("an actee of the shelf (egg, walnut), found \"coconut\""));
  EXPECT_THAT(error_of(R"({"type":"actee","name":7})"), HasSubstr("found 7"));
  EXPECT_THAT(error_of(R"({"type":"grasp","seq":-1})"), HasSubstr("\"seq\" as a non-negative integer"));
  EXPECT_THAT(error_of(R"({"type":"grasp","seq":1.5})"), HasSubstr("\"seq\" as a non-negative integer"));
  EXPECT_THAT(error_of(R"({"type":"grasp","seq":"2"})"), HasSubstr("\"seq\" as a non-negative integer"));
  EXPECT_THAT(error_of(R"({"type":"grasp","seq":18446744073709551615})"), HasSubstr("\"seq\""));
  // A long bad value is shown cut short.
  const std::string long_name = R"({"type":"actee","name":")" + std::string(500, 'n') + "\"}";
  EXPECT_LT(error_of(long_name).size(), 200u);
}

TEST(ServeProtocol, DropsOutOfOrderMessages) {
  SeqCheck check;
  EXPECT_TRUE(check.accept(parsed(R"({"type":"grasp","seq":5})")));
  EXPECT_FALSE(check.accept(parsed(R"({"type":"release","seq":3})")));  // stale
  EXPECT_FALSE(check.accept(parsed(R"({"type":"release","seq":5})")));  // repeated
  EXPECT_TRUE(check.accept(parsed(R"({"type":"release"})")));           // without seq: always
  EXPECT_TRUE(check.accept(parsed(R"({"type":"release","seq":6})")));
  EXPECT_EQ(check.last(), 6);
}

TEST(ServeProtocol, CommandsRoundTripThroughTheirRecord) {
  Command c = parsed(R"({"type":"move","position":[0.06,-0.1,0.2],"seq":12})");
  std::array<unsigned char, kCommandRecordBytes> bytes{};
  encode_command(c, 1.234, bytes.data());
  double t = 0;
  const Command back = decode_command(bytes.data(), &t);
  EXPECT_EQ(t, 1.234);
  EXPECT_EQ(back.kind, CommandKind::move);
  EXPECT_EQ(back.seq, 12);
  EXPECT_EQ(back.position, c.position);
  EXPECT_EQ(back.actee, -1);
  encode_command(parsed(R"({"type":"actee","name":"walnut"})"), 0, bytes.data());
  EXPECT_EQ(decode_command(bytes.data(), &t).actee, 1);
  EXPECT_EQ(decode_command(bytes.data(), &t).seq, -1);
}

TEST(ServeProtocol, FormatsStateAsJson) {
  StateMessage m;
  m.trial = 3;
  m.t = 1.25;
  m.frame = 1250;
  m.reaction = 35.5;
  m.actee_limit = std::numeric_limits<double>::quiet_NaN();  // written as null, never as nan
  m.condition = "broken";
  m.fingertip[0] = {0.1, 0.2, 0.3};
  std::array<char, kStateMessageBytes> buf{};
  const size_t n = format_state(m, buf.data(), buf.size());
  ASSERT_GT(n, 0u);
  const Json j = Json::parse(std::string(buf.data(), n));
  EXPECT_EQ(j["type"], "state");
  EXPECT_EQ(j["trial"], 3);
  EXPECT_EQ(j["t"], 1.25);
  EXPECT_EQ(j["reaction"], 35.5);
  EXPECT_TRUE(j["actee_limit"].is_null());
  EXPECT_EQ(j["condition"], "broken");
  EXPECT_EQ(j["fingertips"][0][2], 0.3);
  EXPECT_EQ(j["object"].size(), 16u);
  EXPECT_EQ(format_state(m, buf.data(), 100), 0u);  // does not fit: nothing
  EXPECT_EQ(format_state(m, buf.data(), 0), 0u);
}

TEST(ServeProtocol, SmallMessagesAreJson) {
  EXPECT_EQ(Json::parse(hello_message(true))["role"], "driver");
  EXPECT_EQ(Json::parse(role_message(false))["role"], "watcher");
  EXPECT_EQ(Json::parse(error_message("bad \"x\"\n"))["message"], "bad \"x\"\n");
  EXPECT_TRUE(Json::accept(error_message(std::string("\xff\xfe", 2))));  // never invalid JSON
}

// ------------------------------------------------------------ the page's hand

// Commands at session times, played through a PageAgent.
class Plan : public SampleSource {
 public:
  Plan(const Model& model, const PageGrip& grip, const PageStart& start, double duration)
      : agent(model, grip, start), duration_(duration) {}
  void at(double t, const Command& c) { plan_.push_back({t, c}); }
  bool sample_at(double t, Sample* out) override {
    while (next_ < plan_.size() && plan_[next_].first <= t + 1e-9) agent.apply(plan_[next_++].second);
    agent.sample(t, out);
    return true;
  }
  double duration() const override { return duration_; }
  PageAgent agent;

 private:
  std::vector<std::pair<double, Command>> plan_;
  size_t next_ = 0;
  double duration_;
};

Command command(CommandKind kind, double squeeze = 0) {
  Command c;
  c.kind = kind;
  c.squeeze = squeeze;
  return c;
}

// The paper's Fig. 17 as a page would drive it: grasp, squeeze, hold,
// carry, squeeze harder.
void plan_tongs(Plan& plan, const PageStart& start) {
  plan.at(0.1, command(CommandKind::grasp));
  plan.at(0.6, command(CommandKind::thumb, 0.020));
  Command move = command(CommandKind::move);
  move.position = {start.hand_position.x(), start.hand_position.y() + 0.1, start.hand_position.z() + 0.08};
  plan.at(2.4, move);
  plan.at(4.4, command(CommandKind::thumb, 0.036));
}

std::vector<std::string> names(const std::vector<Inference>& infs) {
  std::vector<std::string> out;
  for (const Inference& i : infs) out.push_back(i.function);
  return out;
}

TEST(ServePageAgent, DrivesThePaperTongsToEveryFunction) {
  const CompiledSession session = load_session(kSource + "/sessions/paper-tongs.yaml");
  const PageGrip grip = page_grip(session);
  EXPECT_EQ(grip.posture, "medium_wrap");
  EXPECT_NEAR(grip.thumb_distance, 0.130, 1e-9);
  const PageStart start = page_start(session);
  const fs::path dir = test::fresh_dir("serve-test", "agent");
  const CompiledSession trial = write_trial_session(session, "", dir, "p-trial-001");
  Plan plan(trial.model, grip, start, 7.0);
  plan_tongs(plan, start);
  const RunResult r = run_session(trial, *trial.rules, plan);
  EXPECT_THAT(names(r.inferences), ::testing::ElementsAre("pinch", "hold", "carry", "crash"));

  // The same commands give the same run, bit for bit.
  Plan again(trial.model, grip, start, 7.0);
  plan_tongs(again, start);
  const RunResult r2 = run_session(trial, *trial.rules, again);
  ASSERT_EQ(r2.inferences.size(), r.inferences.size());
  for (size_t i = 0; i < r.inferences.size(); ++i) EXPECT_EQ(r2.inferences[i].t, r.inferences[i].t);
  fs::remove_all(dir);
}

TEST(ServePageAgent, ReachesWishesAtBoundedRates) {
  const CompiledSession session = load_session(kSource + "/sessions/paper-tongs.yaml");
  const PageGrip grip = page_grip(session);
  const PageStart start = page_start(session);
  PageAgent agent(session.model, grip, start);
  Sample s;
  agent.sample(0.001, &s);
  EXPECT_EQ(s.hand.translation(), start.hand_position);
  agent.apply(command(CommandKind::thumb, 0.030));  // squeezing while open: remembered
  agent.apply(command(CommandKind::grasp));
  agent.sample(0.101, &s);
  EXPECT_NEAR(agent.squeeze(), 0.1 * PageAgent::kSqueezeRate, 1e-12);
  EXPECT_NEAR(agent.closed(), 0.1 / PageAgent::kCloseTime, 1e-12);
  Command move = command(CommandKind::move);
  move.position = {start.hand_position.x(), start.hand_position.y(), start.hand_position.z() + 0.1};
  agent.apply(move);
  agent.sample(0.201, &s);
  EXPECT_EQ(s.hand.translation(), start.hand_position);  // the hand waits while the fingers close
  agent.sample(0.401, &s);
  EXPECT_EQ(agent.closed(), 1.0);
  EXPECT_GT(s.hand.translation().z(), start.hand_position.z());
  EXPECT_LE(s.hand.translation().z() - start.hand_position.z(), (0.401 - 0.201) * PageAgent::kHandSpeed + 1e-9);
  agent.apply(command(CommandKind::release));
  EXPECT_EQ(agent.squeeze_target(), 0.0);
  EXPECT_FALSE(agent.gripping());
}

TEST(ServePageAgent, LimitsFollowTheTool) {
  const CompiledSession session = load_session(kSource + "/sessions/paper-tongs.yaml");
  const PageGrip grip = page_grip(session);
  const PageStart start = page_start(session);
  const CommandLimits l = command_limits(session.model, grip, start);
  // 130 mm times the angle from rest to closed, and 30 mm more.
  EXPECT_NEAR(l.max_squeeze, 0.130 * (session.model.theta_rest - session.model.theta_min) + 0.03, 1e-12);
  EXPECT_NEAR(l.hand_max[2] - l.hand_min[2], 0.6, 1e-12);
}

// ------------------------------------------------------------ trials and the scene

TEST(ServeTrial, NamesAndNumbers) {
  EXPECT_TRUE(valid_participant("p01"));
  EXPECT_TRUE(valid_participant("Anna_K-2"));
  EXPECT_FALSE(valid_participant(""));
  EXPECT_FALSE(valid_participant("a b"));
  EXPECT_FALSE(valid_participant("../x"));
  EXPECT_FALSE(valid_participant(std::string(33, 'a')));
  EXPECT_EQ(trial_stem("p01", 7), "p01-trial-007");
  const fs::path dir = test::fresh_dir("serve-test", "numbers");
  EXPECT_EQ(next_trial(dir / "missing", "p01"), 1);
  EXPECT_EQ(next_trial(dir, "p01"), 1);
  std::ofstream(dir / "p01-trial-004.afrec") << "x";
  std::ofstream(dir / "p02-trial-009.afrec") << "x";
  std::ofstream(dir / "p01-trial-x.afrec") << "x";
  EXPECT_EQ(next_trial(dir, "p01"), 5);
  EXPECT_EQ(next_trial(dir, "p02"), 10);
  fs::remove_all(dir);
}

TEST(ServeTrial, TakesAnActeeFromTheShelfWhereItFits) {
  const std::vector<ShelfActee> shelf = actee_shelf(kSource + "/actees");
  const std::vector<std::string> all = shelf_names(shelf);
  EXPECT_THAT(all, ::testing::Contains("egg"));
  EXPECT_THAT(all, ::testing::Contains("walnut"));
  EXPECT_TRUE(std::is_sorted(all.begin(), all.end()));
  const CompiledSession session = load_session(kSource + "/sessions/paper-tongs.yaml");
  const fs::path dir = test::fresh_dir("serve-test", "shelf");
  for (const ShelfActee& a : shelf) {
    const CompiledSession t = write_trial_session(session, a.file, dir, "p-trial-" + a.name);
    EXPECT_TRUE(t.model.has_actee) << a.name;
    EXPECT_EQ(t.script.keyframes.size(), 2u);
    EXPECT_EQ(t.model.object_name, session.model.object_name);
  }
  // The walnut sits where the tongs' jaws close on it; the coconut, too
  // large, beside them.
  const CompiledSession walnut = write_trial_session(session, kSource + "/actees/walnut.yaml", dir, "w");
  EXPECT_TRUE(walnut.model.actee_on_jaw);
  const CompiledSession coconut = write_trial_session(session, kSource + "/actees/coconut.yaml", dir, "c");
  EXPECT_FALSE(coconut.model.actee_on_jaw);
  fs::remove_all(dir);
}

// Every shipped session can be served: its grip (from its script, or the
// middle of the emphasis region), its start, its trial file.
TEST(ServeTrial, EveryShippedSessionCanBeServed) {
  const fs::path dir = test::fresh_dir("serve-test", "shipped");
  int sessions = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(kSource + "/sessions")) {
    if (e.path().extension() != ".yaml") continue;
    SCOPED_TRACE(e.path().string());
    const CompiledSession session = load_session(e.path().string());
    const PageGrip grip = page_grip(session);
    EXPECT_GT(grip.thumb_distance, 0);
    const PageStart start = page_start(session);
    const CompiledSession trial = write_trial_session(session, "", dir, e.path().stem().string());
    EXPECT_EQ(trial.model.has_actee, session.model.has_actee);
    EXPECT_EQ(trial.model.actee_name, session.model.actee_name);
    SceneInfo info{1, "p", "r", trial.model.actee_name, {}};
    EXPECT_TRUE(Json::accept(scene_message(trial, grip, start, command_limits(trial.model, grip, start), info)));
    ++sessions;
  }
  EXPECT_GE(sessions, 5);
  fs::remove_all(dir);
}

TEST(ServeScene, HoldsTheEnginesGeometry) {
  const CompiledSession session = load_session(kSource + "/sessions/paper-tongs.yaml");
  const PageGrip grip = page_grip(session);
  const PageStart start = page_start(session);
  SceneInfo info{2, "p01", "out/x.afrec", "egg", kShelf};
  const Json j = Json::parse(scene_message(session, grip, start, command_limits(session.model, grip, start), info));
  EXPECT_EQ(j["type"], "scene");
  EXPECT_EQ(j["trial"], 2);
  ASSERT_EQ(j["parts"].size(), session.model.parts.size());
  for (const Json& p : j["parts"]) {
    EXPECT_GT(p["positions"].size(), 0u);
    EXPECT_EQ(p["positions"].size() % 9, 0u);  // whole triangles
    EXPECT_EQ(p["normals"].size(), p["positions"].size());
    EXPECT_EQ(p["in_arm"].size(), 16u);
  }
  EXPECT_EQ(j["actee"]["limit"], session.model.actee_limit);
  EXPECT_EQ(j["shelf"], Json(kShelf));
  EXPECT_EQ(j["fingertip_radius"].size(), 5u);
}

// An inference's event carries the explanation `afford run` prints.
class EventCollector : public Observer {
 public:
  void on_frame(const Model&, const State&, const RuleSet& rules, const RuleState& rs) override {
    for (const Event* e = events_begin(rs); e != events_end(rs); ++e) {
      if (e->kind != EventKind::inferred) continue;
      const std::vector<Inference> all = inferences(rules, rs);
      messages.push_back(event_message(rules, *e, &all.back()));
    }
  }
  std::vector<std::string> messages;
};

TEST(ServeProtocol, EventsCarryTheExplanation) {
  const CompiledSession session = load_session(kSource + "/sessions/paper-tongs.yaml");
  const PageGrip grip = page_grip(session);
  const PageStart start = page_start(session);
  const fs::path dir = test::fresh_dir("serve-test", "events");
  const CompiledSession trial = write_trial_session(session, "", dir, "p-trial-001");
  Plan plan(trial.model, grip, start, 7.0);
  plan_tongs(plan, start);
  EventCollector events;
  Observer* const observers[] = {&events};
  const RunResult r = run_session(trial, *trial.rules, plan, observers);
  ASSERT_EQ(events.messages.size(), r.inferences.size());
  for (size_t i = 0; i < r.inferences.size(); ++i) {
    const Json j = Json::parse(events.messages[i]);
    EXPECT_EQ(j["kind"], "inferred");
    EXPECT_EQ(j["function"], r.inferences[i].function);
    EXPECT_EQ(j["t"].get<double>(), r.inferences[i].t);
    ASSERT_EQ(j["explanation"].size(), r.inferences[i].nodes.size());
    for (size_t n = 0; n < r.inferences[i].nodes.size(); ++n) {
      EXPECT_EQ(j["explanation"][n]["text"], r.inferences[i].nodes[n].text);
    }
  }
  fs::remove_all(dir);
}

// The frame thread's ring (event_ring.h): every event of a run, pushed as
// it happens and written out later, reads as frame_event_message writes it
// in the frame; the inferences' explanations are `afford run`'s.
class RingFeeder : public Observer {
 public:
  explicit RingFeeder(EventRing& ring) : ring_(ring) {}
  void on_frame(const Model&, const State&, const RuleSet& rules, const RuleState& rs) override {
    for (const Event* e = events_begin(rs); e != events_end(rs); ++e) {
      EXPECT_TRUE(ring_.push(rs, *e));
      in_frame.push_back(frame_event_message(rules, rs, *e));
    }
  }
  std::vector<std::string> in_frame;

 private:
  EventRing& ring_;
};

TEST(ServeEventRing, WritesOutWhatTheFrameSaw) {
  const CompiledSession session = load_session(kSource + "/sessions/paper-tongs.yaml");
  const PageGrip grip = page_grip(session);
  const PageStart start = page_start(session);
  const fs::path dir = test::fresh_dir("serve-test", "ring");
  const CompiledSession trial = write_trial_session(session, "", dir, "p-trial-001");
  Plan plan(trial.model, grip, start, 7.0);
  plan_tongs(plan, start);
  EventRing ring(trial.rules);
  RingFeeder feeder(ring);
  Observer* const observers[] = {&feeder};
  const RunResult r = run_session(trial, *trial.rules, plan, observers);
  std::vector<std::string> out;
  std::string message;
  while (ring.pop(&message)) out.push_back(message);
  EXPECT_EQ(out, feeder.in_frame);
  EXPECT_EQ(ring.dropped(), 0);
  std::vector<Json> inferred;
  for (const std::string& m : out) {
    const Json j = Json::parse(m);
    if (j["kind"] == "inferred") inferred.push_back(j);
  }
  ASSERT_EQ(inferred.size(), r.inferences.size());
  ASSERT_GE(inferred.size(), 4u);  // pinch, hold, carry, crash
  for (size_t i = 0; i < inferred.size(); ++i) {
    ASSERT_EQ(inferred[i]["explanation"].size(), r.inferences[i].nodes.size());
    for (size_t n = 0; n < r.inferences[i].nodes.size(); ++n) {
      EXPECT_EQ(inferred[i]["explanation"][n]["text"], r.inferences[i].nodes[n].text);
      EXPECT_EQ(inferred[i]["explanation"][n]["t"].get<double>(), r.inferences[i].nodes[n].t);
    }
  }
  fs::remove_all(dir);
}

TEST(ServeEventRing, AFullRingDropsAndCounts) {
  const CompiledSession session = load_session(kSource + "/sessions/paper-tongs.yaml");
  EventRing ring(session.rules, 2);
  const RuleStatePtr rs = make_rule_state(*session.rules);
  const Event e{EventKind::node_reached, 0.5, 0, 0};
  EXPECT_TRUE(ring.push(*rs, e));
  EXPECT_TRUE(ring.push(*rs, e));
  EXPECT_FALSE(ring.push(*rs, e));
  EXPECT_EQ(ring.dropped(), 1);
  std::string message;
  EXPECT_TRUE(ring.pop(&message));
  EXPECT_THAT(message, HasSubstr("\"kind\":\"node_reached\""));
  EXPECT_TRUE(ring.push(*rs, e));  // room again
  EXPECT_TRUE(ring.pop(&message));
  EXPECT_TRUE(ring.pop(&message));
  EXPECT_FALSE(ring.pop(&message));
}

}  // namespace
}  // namespace afford::serve
