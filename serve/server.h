// `afford serve`: a session's frame loop (the same engine, rules, recorder
// and outputs as `afford live`) behind a local web page.
//
// Threads:
//   - the frame thread runs the trials one after another (run_session at
//     the session's timestep, paced to the wall clock): each frame takes
//     the driver's queued commands (a fixed ring under a mutex), steps,
//     records, and every 1/60 s of session time posts the state (formatted
//     into a fixed buffer) for the pages; a frame with events of the rules
//     copies them, with what an inference's explanation needs, into the
//     trial's EventRing (event_ring.h). A frame allocates nothing
//     (tests/alloc/test_serve_frame.cpp);
//   - civetweb's threads accept pages (HTTP for web/ and three.js, one
//     WebSocket per page), check every message (protocol.h) and queue the
//     driver's; a bad message is logged and answered with an error, never
//     applied;
//   - the sender thread writes to the pages: hello and the scene to a new
//     page, then the states and events (writing the events' text); it
//     alone writes to sockets, so the frame thread never waits for a page.
// The first page drives; the others watch until the driver leaves, when
// the longest-connected watcher takes over. A page's "actee" or "reset"
// ends the trial; the next starts with a new recording.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "event_ring.h"
#include "guides.h"
#include "observer.h"
#include "page_agent.h"
#include "protocol.h"
#include "session.h"
#include "trial.h"

struct mg_context;
struct mg_connection;

namespace afford::serve {

struct ServeOptions {
  std::string session_file;             // the session served
  std::string bind = "127.0.0.1";       // IPv4 address to listen on
  int port = 8080;                      // 0: any free port (port() says which)
  std::string participant = "p01";      // in the trials' file names
  std::string out_dir;                  // where trials go (default out/serve-<session>)
  double duration = std::numeric_limits<double>::infinity();  // s of session time over all trials
  std::string web_dir;                  // the page's files (default the shipped web/)
  std::string three_dir = "/usr/share/javascript/three";  // Debian's libjs-three, served as /three/
  std::string actees_dir;               // the shipped shelf (default the shipped actees/)
  std::string guides_file;              // the guides drawn (default the shipped rules/guides.yaml)
  std::string user_actees_dir;          // a user's actees, on the shelf after the shipped ones ("" none)
  // true: frames at the session's timestep in real time. false: a frame
  // runs only when advance() allows it (tests drive by session time).
  bool realtime = true;
  int max_pages = 8;                    // pages connected at once; more are refused
  // More observers of every frame of every trial, after the server's own,
  // on the frame thread (tests: allocations per frame).
  std::vector<Observer*> observers;
};

// One trial, when it has ended.
struct TrialSummary {
  int number = 0;
  std::string actee;                   // its name ("" none)
  std::string session_file;            // DIR/P-trial-NNN.yaml
  std::string recording;               // DIR/P-trial-NNN.afrec
  std::string outputs;                 // DIR/P-trial-NNN/ (timeline.jsonl, trace.csv)
  std::int64_t frames = 0;
  double end_time = 0;                 // s
  std::vector<Inference> inferences;   // as `afford run` reports them
  std::int64_t deadline_misses = 0;    // frames served more than one timestep late
  double max_lateness = 0;             // s, the latest frame
  std::string error;                   // a recording or output that failed ("" none)
};

// Counts of what the pages sent.
struct MessageCounts {
  std::int64_t accepted = 0;   // queued for the frame thread
  std::int64_t rejected = 0;   // bad JSON, unknown type, wrong fields, too large, binary
  std::int64_t stale = 0;      // seq not above the page's last
  std::int64_t from_watchers = 0;
  std::int64_t queue_full = 0;
};

class Server {
 public:
  // Loads the session (DataError naming file:line:col), the shelf and the
  // grip. Nothing listens yet.
  explicit Server(ServeOptions options);
  ~Server();  // stops
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Listens, starts the first trial and the threads. Throws
  // std::runtime_error (the port is taken, the address is bad, web/ is
  // missing, the first trial cannot be written).
  void start();
  int port() const { return port_; }
  std::string url() const;
  // Whether the frame thread runs at real-time priority (SCHED_FIFO; in
  // real time only, where the system allows it): fewer late frames on a
  // busy machine. Known once start() returns.
  bool real_time_priority() const { return real_time_priority_; }
  // Ends the session: the trial in progress ends cleanly (its recording
  // closed with its end record), the pages are closed.
  void stop();
  // Waits until the session ends (its duration, stop()); true when it did
  // within timeout_s.
  bool wait(double timeout_s = std::numeric_limits<double>::infinity());
  bool running() const { return !finished_.load(); }

  // Tests (realtime false): lets the frames run for `seconds` more of
  // session time and waits until they have (or a trial ends, or the session).
  void advance(double seconds);

  int trial() const { return current_trial_.load(); }      // the trial running now
  int trials_started() const { return trials_started_.load(); }
  std::vector<TrialSummary> trials() const;                 // the ended ones
  MessageCounts messages() const;
  int pages() const;
  std::int64_t states_sent() const { return states_sent_.load(); }
  const std::filesystem::path& out_dir() const { return out_dir_; }
  const std::vector<ShelfActee>& shelf() const { return shelf_; }
  // The first trial's error when start() could not begin one, or a later
  // trial's that failed to start ("" none).
  std::string last_error() const;

  // civetweb's callbacks (server.cpp).
  struct Page;
  int on_connect(const mg_connection* conn);
  void on_ready(mg_connection* conn);
  int on_data(mg_connection* conn, int flags, const char* data, size_t size);
  void on_close(const mg_connection* conn);

 private:
  class Source;
  struct Trial;

  void frame_loop();
  void sender_loop();
  std::unique_ptr<Trial> begin_trial(int actee);  // -1: the session's own
  void post_scene(const std::string& scene, std::shared_ptr<EventRing> events);
  void post_event(std::string message);
  void reject(Page& page, const std::string& why);
  void close_pages();  // a close frame to each page: the session ended

  ServeOptions options_;
  CompiledSession session_;     // as served (its script gives the start and the grip)
  PageGrip grip_;
  PageStart start_;
  CommandLimits limits_;
  std::vector<ShelfActee> shelf_;
  std::vector<std::string> shelf_names_;
  Guides guides_;  // `afford guide`'s, of the served tool, sent with each scene
  std::filesystem::path out_dir_;
  std::string web_dir_;
  int port_ = 0;
  mg_context* ctx_ = nullptr;

  // Commands from the driver to the frame thread: a fixed ring.
  static constexpr size_t kQueue = 256;
  std::mutex queue_mutex_;
  std::array<Command, kQueue> queue_{};
  size_t queue_head_ = 0, queue_size_ = 0;
  bool push_command(const Command& c);
  size_t pop_commands(Command* out, size_t max);

  // The frame thread's posts to the sender thread.
  std::mutex post_mutex_;
  std::condition_variable post_cv_;
  std::array<char, kStateMessageBytes> state_{};
  size_t state_bytes_ = 0;
  std::uint64_t state_seq_ = 0;
  std::deque<std::string> events_;
  std::shared_ptr<const std::string> scene_;
  std::shared_ptr<EventRing> ring_;  // the trial's events (event_ring.h)
  std::uint64_t scene_seq_ = 0;
  bool sender_stop_ = false;
  bool wake_ = false;  // a page connected or has something in its outbox

  // The pages (civetweb's threads and the sender).
  mutable std::mutex pages_mutex_;
  std::vector<std::unique_ptr<Page>> pages_;
  std::int64_t next_page_id_ = 0;
  MessageCounts counts_;
  std::int64_t log_budget_ = 50;  // messages logged before the log goes quiet

  // Pacing by advance() (tests).
  std::mutex pace_mutex_;
  std::condition_variable pace_cv_;
  double allowed_ = 0;         // s of session time (over all trials) the frames may reach
  double reached_ = 0;         // s reached
  bool frame_waiting_ = false; // the frame thread waits for advance()
  double waiting_for_ = 0;     // s, the frame it waits to run

  std::atomic<bool> stop_{false}, finished_{false};
  bool real_time_priority_ = false;
  std::atomic<int> current_trial_{0}, trials_started_{0};
  std::atomic<std::int64_t> states_sent_{0};
  std::atomic<std::int64_t> total_misses_{0};
  mutable std::mutex summary_mutex_;
  std::vector<TrialSummary> summaries_;
  std::string last_error_;
  std::unique_ptr<Trial> first_trial_;  // begun by start(), run by the frame thread
  int next_trial_ = 1;
  std::thread frame_thread_, sender_thread_;
  std::mutex finish_mutex_;
  std::condition_variable finish_cv_;
};

}  // namespace afford::serve
