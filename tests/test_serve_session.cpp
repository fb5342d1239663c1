// afford serve over real sockets: a server on an ephemeral port, pages
// played by a small WebSocket client (civetweb's), driving the paper-tongs
// experiment through pinch, hold, carry and crash; its recording replays
// to the same verdicts. The frames run by session time (advance()), never
// by the clock: the waits below are for the other threads, with generous
// limits, and nothing asserts on a duration.
#include <civetweb.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "guides.h"
#include "recording_source.h"
#include "run.h"
#include "server.h"
#include "test_util.h"

namespace afford::serve {
namespace {
using test::kSource;

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using Json = nlohmann::json;
namespace fs = std::filesystem;

constexpr double kPatience = 120;  // s: how long a wait for another thread may take before the test fails

// Waits until `done` holds (polling); false after kPatience seconds.
bool eventually(const std::function<bool()>& done) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(kPatience);
  while (!done()) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

// A page: civetweb's WebSocket client, keeping every JSON message it gets.
class Page {
 public:
  explicit Page(int port) {
    char error[256] = "";
    conn_ = mg_connect_websocket_client("127.0.0.1", port, 0, error, sizeof error, "/ws", nullptr, on_data, on_close,
                                        this);
    if (conn_ == nullptr) ADD_FAILURE() << "cannot connect: " << error;
  }
  ~Page() { close(); }
  Page(const Page&) = delete;
  Page& operator=(const Page&) = delete;

  void send(const std::string& text, int opcode = MG_WEBSOCKET_OPCODE_TEXT) {
    ASSERT_NE(conn_, nullptr);
    ASSERT_GT(mg_websocket_client_write(conn_, opcode, text.data(), text.size()), 0);
  }
  void close() {
    if (conn_ != nullptr) mg_close_connection(conn_);
    conn_ = nullptr;
  }
  // The first message (from the `from`th on) that `match` accepts, waiting for it.
  std::optional<Json> wait_for(const std::function<bool(const Json&)>& match, size_t from = 0) {
    std::unique_lock lock(mutex_);
    std::optional<Json> found;
    const auto look = [&] {
      for (size_t i = from; i < messages_.size(); ++i) {
        if (match(messages_[i])) {
          found = messages_[i];
          return true;
        }
      }
      return false;
    };
    cv_.wait_for(lock, std::chrono::duration<double>(kPatience), look);
    return found;
  }
  std::optional<Json> wait_type(const std::string& type, size_t from = 0) {
    return wait_for([&](const Json& j) { return j["type"] == type; }, from);
  }
  std::vector<Json> messages() const {
    std::lock_guard lock(mutex_);
    return messages_;
  }
  size_t count() const {
    std::lock_guard lock(mutex_);
    return messages_.size();
  }

 private:
  static int on_data(mg_connection*, int flags, char* data, size_t size, void* self) {
    Page& page = *static_cast<Page*>(self);
    if ((flags & 0x0f) != MG_WEBSOCKET_OPCODE_TEXT) return 1;
    Json j = Json::parse(std::string(data, size), nullptr, false);
    if (j.is_discarded()) {
      ADD_FAILURE() << "the server sent text that is not JSON";
      return 1;
    }
    std::lock_guard lock(page.mutex_);
    page.messages_.push_back(std::move(j));
    page.cv_.notify_all();
    return 1;
  }
  static void on_close(const mg_connection*, void*) {}

  mg_connection* conn_ = nullptr;
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  std::vector<Json> messages_;
};

fs::path absent_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("afford-serve-session-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

ServeOptions options(const fs::path& out) {
  ServeOptions o;
  o.session_file = kSource + "/sessions/paper-tongs.yaml";
  o.port = 0;  // any free port
  o.out_dir = out.string();
  o.web_dir = kSource + "/web";
  o.actees_dir = kSource + "/actees";
  o.participant = "t01";
  o.realtime = false;  // frames by advance()
  return o;
}

// Sends a command from the driver and waits until the server has queued it.
void command(Server& server, Page& page, const Json& message) {
  const std::int64_t before = server.messages().accepted;
  page.send(message.dump());
  ASSERT_TRUE(eventually([&] { return server.messages().accepted > before; })) << message.dump();
}

std::vector<std::string> names(const std::vector<Inference>& infs) {
  std::vector<std::string> out;
  for (const Inference& i : infs) out.push_back(i.function);
  return out;
}

// `afford replay`'s check: the recording re-run from its own files gives
// the same events, frame by frame, bit for bit; returns the re-run.
RunResult replayed(const std::string& file) {
  const Recording rec = read_recording(file);
  EXPECT_EQ(rec.tail, RecordingTail::end) << rec.summary();
  const CompiledSession session = load_recorded_session(rec);
  RecordingSource source(rec);
  ReplayChecker checker(rec, true);
  Observer* const observers[] = {&checker};
  const RunResult r = run_session(session, *session.rules, source, observers);
  EXPECT_TRUE(checker.identical()) << checker.describe(*session.rules);
  return r;
}

TEST(ServeSession, DrivesThePaperTongsOverAWebSocket) {
  const fs::path out = absent_dir("tongs");
  Server server(options(out));
  server.start();
  ASSERT_GT(server.port(), 0);
  Page driver(server.port());
  ASSERT_TRUE(driver.wait_type("hello").has_value());
  EXPECT_EQ((*driver.wait_type("hello"))["role"], "driver");
  const std::optional<Json> scene = driver.wait_type("scene");
  ASSERT_TRUE(scene.has_value());
  EXPECT_EQ((*scene)["actee_name"], "egg");
  EXPECT_EQ((*scene)["trial"], 1);
  Page watcher(server.port());
  ASSERT_TRUE(watcher.wait_type("hello").has_value());
  EXPECT_EQ((*watcher.wait_type("hello"))["role"], "watcher");
  ASSERT_TRUE(watcher.wait_type("scene").has_value());

  const std::vector<double> hand = (*scene)["hand_start"].get<std::vector<double>>();
  server.advance(0.1);
  command(server, driver, {{"type", "grasp"}, {"seq", 1}});
  server.advance(0.5);
  command(server, driver, {{"type", "thumb"}, {"squeeze", 0.020}, {"seq", 2}});
  server.advance(1.8);
  command(server, driver, {{"type", "move"}, {"position", {hand[0], hand[1] + 0.1, hand[2] + 0.08}}, {"seq", 3}});
  server.advance(2.0);
  // A watcher's command is refused, and changes nothing.
  const size_t watcher_seen = watcher.count();
  watcher.send(R"({"type":"release"})");
  ASSERT_TRUE(eventually([&] { return server.messages().from_watchers == 1; }));
  const std::optional<Json> refused = watcher.wait_type("error", watcher_seen);
  ASSERT_TRUE(refused.has_value());
  EXPECT_THAT((*refused)["message"].get<std::string>(), HasSubstr("only the driver"));
  command(server, driver, {{"type", "thumb"}, {"squeeze", 0.036}, {"seq", 4}});
  server.advance(2.6);

  // Every page sees the functions as they are inferred, with the explanation.
  for (Page* page : {&driver, &watcher}) {
    const std::optional<Json> crash =
        page->wait_for([](const Json& j) { return j["type"] == "event" && j["function"] == "crash" && j["kind"] == "inferred"; });
    ASSERT_TRUE(crash.has_value());
    EXPECT_GT((*crash)["explanation"].size(), 0u);
  }
  // The states show the broken egg, and the last command applied.
  const std::optional<Json> broken =
      driver.wait_for([](const Json& j) { return j["type"] == "state" && j["condition"] == "broken"; });
  ASSERT_TRUE(broken.has_value());
  EXPECT_EQ((*broken)["applied_seq"], 4);

  // A new trial: the first is closed, recorded, and replays bit for bit.
  command(server, driver, {{"type", "reset"}, {"seq", 5}});
  server.advance(0.01);
  ASSERT_TRUE(eventually([&] { return server.trials().size() == 1; }));
  EXPECT_EQ(server.trial(), 2);
  ASSERT_TRUE(driver.wait_for([](const Json& j) { return j["type"] == "scene" && j["trial"] == 2; }));
  const TrialSummary first = server.trials().front();
  EXPECT_THAT(names(first.inferences), ElementsAre("pinch", "hold", "carry", "crash"));
  EXPECT_EQ(first.recording, (out / "t01-trial-001.afrec").string());
  EXPECT_TRUE(fs::is_regular_file(out / "t01-trial-001" / "timeline.jsonl"));
  EXPECT_TRUE(fs::is_regular_file(out / "t01-trial-001" / "trace.csv"));
  EXPECT_TRUE(first.error.empty()) << first.error;

  const RunResult again = replayed(first.recording);
  EXPECT_EQ(read_recording(first.recording).skipped_records, 4);  // the four commands applied, as 'P' records
  ASSERT_EQ(names(again.inferences), names(first.inferences));
  for (size_t i = 0; i < again.inferences.size(); ++i) EXPECT_EQ(again.inferences[i].t, first.inferences[i].t);

  // The pages' events were the recording's.
  std::vector<Json> inferred;
  for (const Json& j : driver.messages()) {
    if (j["type"] == "event" && j["kind"] == "inferred") inferred.push_back(j);
  }
  ASSERT_EQ(inferred.size(), first.inferences.size());
  for (size_t i = 0; i < inferred.size(); ++i) {
    EXPECT_EQ(inferred[i]["function"], first.inferences[i].function);
    EXPECT_EQ(inferred[i]["t"].get<double>(), first.inferences[i].t);
    ASSERT_EQ(inferred[i]["explanation"].size(), first.inferences[i].nodes.size());
    EXPECT_EQ(inferred[i]["explanation"][0]["text"], first.inferences[i].nodes[0].text);
  }
  EXPECT_EQ(server.messages().rejected, 0);
  server.stop();
  // The second trial, ended by stop(), is closed cleanly too.
  ASSERT_EQ(server.trials().size(), 2u);
  replayed(server.trials()[1].recording);
  fs::remove_all(out);
}

TEST(ServeSession, ThePageThatDrivesLeavesMidSession) {
  const fs::path out = absent_dir("leaves");
  Server server(options(out));
  server.start();
  auto driver = std::make_unique<Page>(server.port());
  ASSERT_TRUE(driver->wait_type("scene").has_value());
  Page watcher(server.port());
  ASSERT_TRUE(watcher.wait_type("scene").has_value());
  EXPECT_EQ((*watcher.wait_type("hello"))["role"], "watcher");
  command(server, *driver, {{"type", "grasp"}});
  server.advance(0.4);
  command(server, *driver, {{"type", "thumb"}, {"squeeze", 0.01}});
  server.advance(0.2);  // squeezing when it goes
  driver->close();
  driver.reset();
  ASSERT_TRUE(eventually([&] { return server.pages() == 1; }));
  const std::optional<Json> promoted = watcher.wait_type("role");
  ASSERT_TRUE(promoted.has_value());
  EXPECT_EQ((*promoted)["role"], "driver");
  command(server, watcher, {{"type", "thumb"}, {"squeeze", 0.02}});  // the watcher drives now
  server.advance(1.0);
  ASSERT_TRUE(watcher.wait_for([](const Json& j) { return j["type"] == "event" && j["function"] == "pinch"; }));
  server.stop();
  ASSERT_EQ(server.trials().size(), 1u);
  EXPECT_THAT(names(server.trials()[0].inferences), ::testing::Contains("pinch"));
  replayed(server.trials()[0].recording);
  fs::remove_all(out);
}

// Ctrl-C must end a session at once, pages or not: civetweb's threads
// sleep in 2 s slices of poll() unless they are woken (web_server.h,
// Server::close_pages). The bound is ten times what it takes, and far
// below the 2 s it took before; the time is printed.
TEST(ServeSession, StopsPromptlyWithPagesConnected) {
  const fs::path out = absent_dir("stop");
  ServeOptions o = options(out);
  o.realtime = true;
  Server server(o);
  server.start();
  Page driver(server.port()), watcher(server.port());
  for (Page* p : {&driver, &watcher}) ASSERT_TRUE(p->wait_type("scene").has_value());
  const auto start = std::chrono::steady_clock::now();
  server.stop();
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ measured ] stop() with two pages connected took %.1f ms\n", ms);
  EXPECT_LT(ms, 1000) << "civetweb's threads were not woken";
  ASSERT_EQ(server.trials().size(), 1u);
  EXPECT_EQ(server.trials()[0].error, "");
  fs::remove_all(out);
}

TEST(ServeSession, BadMessagesAreLoggedAndDropped) {
  const fs::path out = absent_dir("bad");
  Server server(options(out));
  server.start();
  Page page(server.port());
  ASSERT_TRUE(page.wait_type("scene").has_value());
  const std::vector<std::string> bad = {
      "not json",
      R"({"type":"thumb","squeeze":)",  // truncated
      R"({"type":"fly"})",
      R"({"type":"thumb","squeeze":"hard"})",
      R"({"type":"move","position":[1,2]})",
      R"({"type":"actee","name":"anvil"})",
      R"({"type":"grasp","extra":true})",
      std::string(20000, '{'),  // huge
      "",
  };
  for (size_t i = 0; i < bad.size(); ++i) {
    const size_t seen = page.count();
    page.send(bad[i]);
    ASSERT_TRUE(eventually([&] { return server.messages().rejected == static_cast<std::int64_t>(i + 1); })) << i;
    const std::optional<Json> error = page.wait_type("error", seen);
    ASSERT_TRUE(error.has_value()) << i;
    EXPECT_THAT((*error)["message"].get<std::string>(), HasSubstr("dropped: ")) << i;
  }
  page.send("\x01\x02\x03", MG_WEBSOCKET_OPCODE_BINARY);
  ASSERT_TRUE(eventually([&] { return server.messages().rejected == static_cast<std::int64_t>(bad.size() + 1); }));
  // Out of order: a seq not above the last one is stale.
  command(server, page, {{"type", "grasp"}, {"seq", 10}});
  page.send(R"({"type":"release","seq":9})");
  ASSERT_TRUE(eventually([&] { return server.messages().stale == 1; }));
  // The session goes on, and still obeys.
  server.advance(0.5);
  command(server, page, {{"type", "thumb"}, {"squeeze", 0.02}, {"seq", 11}});
  server.advance(1.0);
  ASSERT_TRUE(page.wait_for([](const Json& j) { return j["type"] == "event" && j["function"] == "pinch"; }));
  EXPECT_EQ(server.messages().accepted, 2);
  server.stop();
  replayed(server.trials()[0].recording);
  fs::remove_all(out);
}

TEST(ServeSession, TakesAnActeeFromTheShelf) {
  const fs::path out = absent_dir("shelf");
  Server server(options(out));
  server.start();
  Page page(server.port());
  const std::optional<Json> scene = page.wait_type("scene");
  ASSERT_TRUE(scene.has_value());
  EXPECT_THAT((*scene)["shelf"].get<std::vector<std::string>>(), ::testing::Contains("walnut"));
  server.advance(0.2);
  command(server, page, {{"type", "actee"}, {"name", "walnut"}});
  server.advance(0.2);
  const std::optional<Json> next = page.wait_for([](const Json& j) { return j["type"] == "scene" && j["trial"] == 2; });
  ASSERT_TRUE(next.has_value());
  EXPECT_EQ((*next)["actee_name"], "walnut");
  EXPECT_EQ((*next)["recording"], (out / "t01-trial-002.afrec").string());
  server.stop();
  ASSERT_EQ(server.trials().size(), 2u);
  EXPECT_EQ(server.trials()[0].actee, "egg");
  EXPECT_EQ(server.trials()[1].actee, "walnut");
  for (const TrialSummary& t : server.trials()) replayed(t.recording);
  // A later serve of the same participant goes on numbering.
  Server later(options(out));
  later.start();
  later.stop();
  EXPECT_EQ(later.trials().front().number, 3);
  fs::remove_all(out);
}

// The message of what `make` throws ("" when it does not).
template <typename F>
std::string thrown(F make) {
  try {
    make();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// --actees DIR: the user's actees on the shelf after the shipped ones, a
// trial with one of them replays, and a mistake in the folder stops the
// start, located.
TEST(ServeSession, TheShelfHoldsTheUsersActees) {
  const fs::path out = absent_dir("user-actees");
  const fs::path mine = out / "my-actees";
  fs::create_directories(mine);
  {
    std::ifstream egg(kSource + "/actees/egg.yaml");
    std::ofstream quail(mine / "quail_egg.yaml");
    for (std::string line; std::getline(egg, line);) {
      quail << (line == "actee: egg" ? "actee: quail_egg" : line) << "\n";
    }
  }
  ServeOptions o = options(out / "trials");
  o.user_actees_dir = mine.string();
  Server server(o);
  const size_t shipped = actee_shelf(kSource + "/actees").size();
  ASSERT_EQ(server.shelf().size(), shipped + 1);  // the shipped ones first
  EXPECT_EQ(server.shelf().back().name, "quail_egg");
  server.start();
  Page page(server.port());
  const std::optional<Json> scene = page.wait_type("scene");
  ASSERT_TRUE(scene.has_value());
  EXPECT_THAT((*scene)["shelf"].get<std::vector<std::string>>(), ::testing::Contains("quail_egg"));
  server.advance(0.1);
  command(server, page, {{"type", "actee"}, {"name", "quail_egg"}});
  server.advance(0.1);
  ASSERT_TRUE(page.wait_for([](const Json& j) { return j["type"] == "scene" && j["trial"] == 2; }).has_value());
  server.stop();
  ASSERT_EQ(server.trials().size(), 2u);
  EXPECT_EQ(server.trials()[1].actee, "quail_egg");
  replayed(server.trials()[1].recording);

  // A mistake in a file of the folder: file:line:col at start.
  {
    std::ofstream bad(mine / "bad.yaml");
    bad << "actee: bad\nshape: {sphere: {radius: 10 mm}}\nmass: 5 g\nyolk: yellow\n";
  }
  const std::string located = thrown([&] { Server s(o); });
  EXPECT_THAT(located, HasSubstr((mine / "bad.yaml").string() + ":"));
  EXPECT_THAT(located, HasSubstr("yolk"));
  fs::remove(mine / "bad.yaml");
  // A name a shipped actee has: both files named.
  fs::copy_file(kSource + "/actees/egg.yaml", mine / "egg.yaml");
  const std::string twice = thrown([&] { Server s(o); });
  EXPECT_THAT(twice, HasSubstr((mine / "egg.yaml").string() + ": an actee named 'egg' is already on the shelf"));
  // A folder that is not there.
  o.user_actees_dir = (out / "nowhere").string();
  EXPECT_THAT(thrown([&] { Server s(o); }), HasSubstr("nowhere: not a folder"));
  fs::remove_all(out);
}

// The scene holds `afford guide`'s guides of the tool: the same guides,
// primitives and numbers as compute_guides, which `afford guide` prints.
TEST(ServeSession, TheSceneHoldsTheGuides) {
  const fs::path out = absent_dir("guides");
  Server server(options(out));
  server.start();
  Page page(server.port());
  const std::optional<Json> scene = page.wait_type("scene");
  ASSERT_TRUE(scene.has_value());
  server.stop();
  const Json& g = (*scene)["guides"];
  ASSERT_TRUE(g.is_object()) << g.dump();
  const CompiledSession session = load_session(kSource + "/sessions/paper-tongs.yaml");
  const Guides expected = compute_guides(session.model, load_guides(kSource + "/rules/guides.yaml"));
  ASSERT_EQ(g["guides"].size(), expected.guides.size());
  for (size_t i = 0; i < expected.guides.size(); ++i) {
    EXPECT_EQ(g["guides"][i]["name"], expected.guides[i].name);
    EXPECT_EQ(g["guides"][i]["kind"], guide_kind_name(expected.guides[i].kind));
  }
  std::vector<std::string> kinds;
  for (const GuideSpec& s : expected.guides) kinds.push_back(guide_kind_name(s.kind));
  EXPECT_THAT(kinds, ::testing::IsSupersetOf({"symmetry_plane", "interaction_space", "emphasis", "advantage"}));
  EXPECT_EQ(g["rects"].size(), expected.rects.size());
  EXPECT_EQ(g["meshes"].size(), expected.meshes.size());
  EXPECT_EQ(g["segments"].size(), expected.segments.size());
  EXPECT_GT(g["rects"].size() + g["meshes"].size() + g["segments"].size(), 0u);
  const GuideFacts& f = expected.facts;
  const Json& facts = g["facts"];
  EXPECT_EQ(facts["pattern"], pattern_name(f.pattern));
  EXPECT_EQ(facts["interaction_space"]["from"].get<double>(), f.space.from);
  EXPECT_EQ(facts["interaction_space"]["to"].get<double>(), f.space.to);
  EXPECT_EQ(facts["interaction_space"]["gap_from"].get<double>(), f.space.gap_from);
  EXPECT_EQ(facts["interaction_space"]["gap_to"].get<double>(), f.space.gap_to);
  EXPECT_EQ(facts["emphasis"]["from"].get<double>(), f.emphasis_from);
  EXPECT_EQ(facts["emphasis"]["to"].get<double>(), f.emphasis_to);
  EXPECT_EQ(facts["advantage"]["ma_min"].get<double>(), f.ma_min);
  EXPECT_EQ(facts["advantage"]["ma_max"].get<double>(), f.ma_max);
  EXPECT_EQ(facts["symmetry_plane"]["normal"][2].get<double>(), f.symmetry_normal.z());
  for (size_t i = 0; i < expected.segments.size(); ++i) {
    EXPECT_EQ(g["segments"][i]["value"].get<double>(), expected.segments[i].value);
    EXPECT_EQ(g["segments"][i]["frame"], expected.segments[i].frame == Arm::moving ? "moving" : "fixed");
  }
  fs::remove_all(out);
}

TEST(ServeSession, RefusesWhatCannotServe) {
  const fs::path out = absent_dir("refuse");
  ServeOptions bad_web = options(out);
  bad_web.web_dir = (out / "nowhere").string();
  Server a(bad_web);
  EXPECT_THAT([&] {
    try {
      a.start();
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  }(), HasSubstr("no index.html"));
  ServeOptions bad_id = options(out);
  bad_id.participant = "../up";
  EXPECT_THROW(Server{bad_id}, std::invalid_argument);
  // A port in use.
  Server first(options(out));
  first.start();
  ServeOptions same = options(out);
  same.port = first.port();
  Server second(same);
  EXPECT_THROW(second.start(), std::runtime_error);
  first.stop();
  fs::remove_all(out);
}

// Not a timed test: runs in real time with a driver and two watchers and
// reports the frames that missed their deadline (AFFORD_SERVE_MEASURE_S
// seconds, default 2). Asserts only that the session ran its frames.
TEST(ServeSession, RealTimeWithTwoWatchersReportsDeadlineMisses) {
  const fs::path out = absent_dir("realtime");
  ServeOptions o = options(out);
  o.realtime = true;
  o.duration = 2;
  if (const char* s = std::getenv("AFFORD_SERVE_MEASURE_S")) o.duration = std::atof(s);
  Server server(o);
  server.start();
  Page driver(server.port()), watcher1(server.port()), watcher2(server.port());
  for (Page* p : {&driver, &watcher1, &watcher2}) ASSERT_TRUE(p->wait_type("scene").has_value());
  driver.send(R"({"type":"grasp"})");
  driver.send(R"({"type":"thumb","squeeze":0.02})");
  ASSERT_TRUE(server.wait(o.duration + kPatience));
  server.stop();
  ASSERT_EQ(server.trials().size(), 1u);
  const TrialSummary t = server.trials()[0];
  EXPECT_EQ(t.frames, static_cast<std::int64_t>(std::llround(o.duration / 1e-3)));
  const size_t states = watcher2.count();
  std::printf("[ measured ] %lld frames in real time with a driver and two watchers: %lld missed their deadline "
              "(latest %.3f ms); %zu messages to a watcher\n",
              static_cast<long long>(t.frames), static_cast<long long>(t.deadline_misses), t.max_lateness * 1e3,
              states);
  ::testing::Test::RecordProperty("deadline_misses", static_cast<int>(t.deadline_misses));
  replayed(t.recording);
  fs::remove_all(out);
}

}  // namespace
}  // namespace afford::serve
