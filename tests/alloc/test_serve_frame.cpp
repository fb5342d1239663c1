// afford serve's frame thread allocates nothing, frame after frame, with
// two pages connected and one driving through grasp, squeeze, carry and
// crash: the page's commands, the step, the rules, the timeline, trace and
// recording, the state for the pages and the events with their
// explanations (whose text the sender thread writes). Counted per thread
// by the replaced operator new of bench/alloc_counter.cpp (its own test
// program, so that the replacement touches no other test); the other
// threads allocate freely.
#include <civetweb.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>

#include "alloc_counter.h"
#include "server.h"
#include "../test_util.h"

namespace afford::serve {
namespace {
using test::kSource;

namespace fs = std::filesystem;
constexpr double kPatience = 120;  // s: the longest wait for another thread

// Watches the frame thread: the allocations between one frame's end and
// the next's, i.e. of a whole frame (the source's sample, the step, the
// rules and the observers before this one).
class AllocationsPerFrame : public Observer {
 public:
  void on_start(const Model&, const State&, const RuleSet&) override { last_ = -1; }
  void on_frame(const Model&, const State&, const RuleSet&, const RuleState& rs) override {
    const long now = thread_allocation_count();
    if (last_ >= 0) {  // the first frame of a trial opens its files
      ++frames;
      if (now != last_) {
        ++frames_allocating;
        allocations += now - last_;
      }
      if (events_begin(rs) != events_end(rs)) ++frames_with_events;
    }
    last_ = thread_allocation_count();  // after this observer's own arithmetic
  }
  std::atomic<long> frames{0}, frames_allocating{0}, allocations{0}, frames_with_events{0};

 private:
  long last_ = -1;
};

// A page: civetweb's WebSocket client, counting what it gets.
class Page {
 public:
  explicit Page(int port) {
    char error[256] = "";
    conn_ = mg_connect_websocket_client("127.0.0.1", port, 0, error, sizeof error, "/ws", nullptr, on_data, nullptr,
                                        this);
    if (conn_ == nullptr) ADD_FAILURE() << "cannot connect: " << error;
  }
  ~Page() {
    if (conn_ != nullptr) mg_close_connection(conn_);
  }
  void send(const std::string& text) { mg_websocket_client_write(conn_, MG_WEBSOCKET_OPCODE_TEXT, text.data(), text.size()); }
  bool wait_for(const std::string& text) {
    std::unique_lock lock(mutex_);
    return cv_.wait_for(lock, std::chrono::duration<double>(kPatience),
                        [&] { return received_.find(text) != std::string::npos; });
  }

 private:
  static int on_data(mg_connection*, int flags, char* data, size_t size, void* self) {
    Page& page = *static_cast<Page*>(self);
    if ((flags & 0x0f) != MG_WEBSOCKET_OPCODE_TEXT) return 1;
    std::lock_guard lock(page.mutex_);
    if (std::string_view(data, size).find("\"type\":\"state\"") == std::string_view::npos) page.received_.append(data, size);
    page.cv_.notify_all();
    return 1;
  }
  mg_connection* conn_ = nullptr;
  std::mutex mutex_;
  std::condition_variable cv_;
  std::string received_;  // every message but the states
};

// Sends a command and waits until the server has queued it for the frame
// thread, so that the next advance() applies it at its first frame (under
// load civetweb's thread may read it late, and the trial would go
// otherwise).
void command(Server& server, Page& page, const std::string& text) {
  const std::int64_t before = server.messages().accepted;
  page.send(text);
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(kPatience);
  while (server.messages().accepted == before && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_GT(server.messages().accepted, before) << text;
}

TEST(ServeFrame, AllocatesNothingWithPagesDriving) {
  const fs::path out = fs::temp_directory_path() / ("afford-serve-alloc-" + std::to_string(::getpid()));
  fs::remove_all(out);
  AllocationsPerFrame counter;
  ServeOptions o;
  o.session_file = kSource + "/sessions/paper-tongs.yaml";
  o.port = 0;
  o.out_dir = out.string();
  o.web_dir = kSource + "/web";
  o.actees_dir = kSource + "/actees";
  o.participant = "a01";
  o.realtime = false;  // frames by advance()
  o.observers = {&counter};
  Server server(o);
  server.start();
  Page driver(server.port());
  ASSERT_TRUE(driver.wait_for("\"type\":\"scene\""));
  Page watcher(server.port());
  ASSERT_TRUE(watcher.wait_for("\"type\":\"scene\""));

  // The paper-tongs experiment (as tests/test_serve_session.cpp drives it).
  server.advance(0.1);
  command(server, driver, R"({"type":"grasp","seq":1})");
  server.advance(0.5);
  command(server, driver, R"({"type":"thumb","squeeze":0.02,"seq":2})");
  server.advance(1.8);
  command(server, driver, R"({"type":"move","position":[0.05,0.1,0.13],"seq":3})");
  server.advance(2.0);
  command(server, driver, R"({"type":"thumb","squeeze":0.036,"seq":4})");
  server.advance(2.6);
  for (Page* p : {&driver, &watcher}) {
    EXPECT_TRUE(p->wait_for("\"function\":\"crash\"")) << "no crash reached a page";
    EXPECT_TRUE(p->wait_for("\"explanation\"")) << "no explanation reached a page";
  }
  server.stop();
  ASSERT_EQ(server.trials().size(), 1u);
  EXPECT_GT(counter.frames.load(), 6000);
  EXPECT_GE(counter.frames_with_events.load(), 4);  // pinch, hold, carry, crash and their nodes
  EXPECT_EQ(counter.allocations.load(), 0) << counter.frames_allocating.load() << " of " << counter.frames.load()
                                           << " frames allocated";
  fs::remove_all(out);
}

}  // namespace
}  // namespace afford::serve
