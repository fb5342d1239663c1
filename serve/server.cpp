// `afford serve` (server.h): civetweb, the frame thread and the sender.
#include "server.h"

#include <civetweb.h>
#include <pthread.h>
#include <sched.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <future>
#include <stdexcept>

#include "data_dir.h"
#include "event_ring.h"
#include "files.h"
#include "recording.h"
#include "scene_message.h"
#include "trace.h"
#include "web_server.h"

namespace afford::serve {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// ------------------------------------------------------------ pages

struct Server::Page {
  std::int64_t id = 0;
  mg_connection* conn = nullptr;
  bool driver = false;
  bool ready = false;       // the WebSocket handshake is done: the sender may write
  bool greeted = false;     // hello sent
  bool broken = false;      // a write failed: written to no more
  std::uint64_t scene_seq = 0;  // the scene it has
  std::vector<std::string> outbox;  // errors, role changes
  std::string partial;      // a fragmented message so far (its connection's thread only)
  bool oversize = false;    // the message being received is too large: dropped at its end
  SeqCheck seq;
};

namespace {

int ws_connect(const mg_connection* conn, void* server) { return static_cast<Server*>(server)->on_connect(conn); }
void ws_ready(mg_connection* conn, void* server) { static_cast<Server*>(server)->on_ready(conn); }
int ws_data(mg_connection* conn, int flags, char* data, size_t size, void* server) {
  return static_cast<Server*>(server)->on_data(conn, flags, data, size);
}
void ws_close(const mg_connection* conn, void* server) { static_cast<Server*>(server)->on_close(conn); }

}  // namespace

// ------------------------------------------------------------ a trial

struct Server::Trial {
  int number = 0;
  int actee = -1;  // on the shelf; -1 the session's own
  std::string stem, actee_name, session_file, recording, outputs, scene;
  CompiledSession session;
  std::shared_ptr<EventRing> events;  // the rules' events, to the sender
  std::unique_ptr<Recorder> recorder;
  std::unique_ptr<CheckedFile> timeline_file, trace_file;
  std::unique_ptr<TimelineWriter> timeline;
  std::unique_ptr<TraceWriter> trace;
};

// The page's hand as the session's sample source: paced, fed from the queue.
class Server::Source : public SampleSource {
 public:
  Source(Server& server, const Model& model, double offset, Recorder* recorder)
      : server_(server),
        agent_(model, server.grip_, server.start_),
        offset_(offset),
        timestep_(model.timestep),
        recorder_(recorder) {}

  bool sample_at(double t, Sample* out) override {
    if (server_.stop_.load()) return false;
    pace(t);
    if (server_.stop_.load()) return false;
    const size_t n = server_.pop_commands(commands_.data(), commands_.size());
    for (size_t i = 0; i < n; ++i) {
      const Command& c = commands_[i];
      if (c.kind == CommandKind::actee || c.kind == CommandKind::reset) {
        new_trial_ = true;
        next_actee_ = c.kind == CommandKind::actee ? c.actee : -2;
        return false;  // the trial ends here; the commands after it were meant for it
      }
      agent_.apply(c);
      encode_command(c, t, record_.data());
      recorder_->append(kRecordPageCommand, record_.data(), record_.size());
    }
    agent_.sample(t, out);
    return true;
  }
  double duration() const override { return server_.options_.duration - offset_; }

  const PageAgent& agent() const { return agent_; }
  bool new_trial() const { return new_trial_; }
  int next_actee() const { return next_actee_; }  // -2: the same as now
  std::int64_t misses() const { return misses_; }
  double max_lateness() const { return max_late_; }

 private:
  void pace(double t) {
    if (!server_.options_.realtime) {
      std::unique_lock lock(server_.pace_mutex_);
      while (offset_ + t > server_.allowed_ + 1e-9 && !server_.stop_.load()) {
        server_.frame_waiting_ = true;
        server_.waiting_for_ = offset_ + t;
        server_.pace_cv_.notify_all();
        server_.pace_cv_.wait(lock);
      }
      server_.frame_waiting_ = false;
      server_.reached_ = offset_ + t;
      return;
    }
    const Clock::time_point now = Clock::now();
    if (!started_) {
      started_ = true;
      zero_ = now - std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(t));
    }
    const Clock::time_point due = zero_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(t));
    if (now < due) {
      std::this_thread::sleep_until(due);
      return;
    }
    const double late = std::chrono::duration<double>(now - due).count();
    if (late > timestep_) {
      ++misses_;
      server_.total_misses_.fetch_add(1);
    }
    max_late_ = std::max(max_late_, late);
    // Far behind (the machine stalled): go on from now, not in a burst.
    if (late > 0.1) zero_ += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(late));
  }

  Server& server_;
  PageAgent agent_;
  double offset_, timestep_;
  Recorder* recorder_;
  std::array<unsigned char, kCommandRecordBytes> record_{};
  std::array<Command, kQueue> commands_{};
  bool new_trial_ = false;
  int next_actee_ = -2;
  bool started_ = false;
  Clock::time_point zero_{};
  std::int64_t misses_ = 0;
  double max_late_ = 0;
};

// After each frame: the state for the pages every 1/60 s of session time,
// and the frame's events, into fixed buffers (nothing is allocated: the
// sender thread writes the events' text).
class Poster : public Observer {
 public:
  using PostState = void (*)(void*, const char*, size_t);
  using Wake = void (*)(void*);
  Poster(void* server, PostState post_state, Wake wake, EventRing& events, const PageAgent& agent, int trial,
         const std::atomic<std::int64_t>& misses)
      : server_(server), post_state_(post_state), wake_(wake), events_(events), agent_(agent), misses_(misses) {
    message_.trial = trial;
  }
  void on_start(const Model& model, const State&, const RuleSet&) override {
    every_ = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::lround(1.0 / 60.0 / model.timestep)));
  }
  void on_frame(const Model& model, const State& state, const RuleSet&, const RuleState& rs) override {
    const bool events = events_begin(rs) != events_end(rs);
    for (const Event* e = events_begin(rs); e != events_end(rs); ++e) events_.push(rs, *e);
    // A frame that applied a page's command posts at once: the page's
    // drag shows on its bars without waiting for the next 1/60 s.
    const bool applied = agent_.applied_seq() != posted_seq_;
    if (state.frame % every_ != 0 && !events && !applied) return;
    posted_seq_ = agent_.applied_seq();
    fill_state_message(state, model, &message_);
    message_.squeeze = agent_.squeeze();
    message_.squeeze_target = agent_.squeeze_target();
    message_.gripping = agent_.gripping();
    message_.deadline_misses = misses_.load();
    message_.applied_seq = agent_.applied_seq();
    const size_t n = format_state(message_, buffer_.data(), buffer_.size());
    if (n > 0) {
      post_state_(server_, buffer_.data(), n);  // wakes the sender
    } else if (events) {
      wake_(server_);
    }
  }

 private:
  void* server_;
  PostState post_state_;
  Wake wake_;
  EventRing& events_;
  const PageAgent& agent_;
  const std::atomic<std::int64_t>& misses_;
  std::int64_t every_ = 17;
  std::int64_t posted_seq_ = -1;  // the applied_seq of the last state posted
  StateMessage message_;
  std::array<char, kStateMessageBytes> buffer_{};
};

// ------------------------------------------------------------ the server

namespace {

// The frame thread as a real-time thread (SCHED_FIFO, low among real-time
// priorities, above every ordinary thread): a busy machine then delays
// its wake-ups less. It sleeps most of each 1 ms frame, so it takes little
// from the rest. False where the system does not allow it (no
// CAP_SYS_NICE, no rtprio limit).
bool raise_to_real_time() {
  sched_param p{};
  p.sched_priority = 10;
  return pthread_setschedparam(pthread_self(), SCHED_FIFO, &p) == 0;
}

}  // namespace


Server::Server(ServeOptions options) : options_(std::move(options)) {
  if (!valid_participant(options_.participant)) {
    throw std::invalid_argument("a participant id of 1 to 32 letters, digits, '-' and '_', not '" +
                                options_.participant + "'");
  }
  session_ = load_session(options_.session_file);
  grip_ = page_grip(session_);
  start_ = page_start(session_);
  limits_ = command_limits(session_.model, grip_, start_);
  shelf_ = actee_shelf(options_.actees_dir.empty() ? shipped_path("actees") : options_.actees_dir,
                       options_.user_actees_dir);
  shelf_names_ = shelf_names(shelf_);
  guides_ = compute_guides(session_.model, load_guides(options_.guides_file.empty() ? shipped_path("rules/guides.yaml")
                                                                                    : options_.guides_file));
  out_dir_ = options_.out_dir.empty() ? fs::path("out") / ("serve-" + session_.name) : fs::path(options_.out_dir);
  web_dir_ = options_.web_dir.empty() ? shipped_path("web") : options_.web_dir;
}

Server::~Server() { stop(); }

std::string Server::url() const { return "http://" + options_.bind + ":" + std::to_string(port_) + "/"; }

void Server::start() {
  const StartedWebServer started = start_web_server(
      {.command = "afford serve", .web_dir = web_dir_, .three_dir = options_.three_dir, .bind = options_.bind,
       .port = options_.port, .threads = options_.max_pages + 8, .websocket = true});
  ctx_ = started.ctx;
  port_ = started.port;
  mg_set_websocket_handler(ctx_, "/ws", ws_connect, ws_ready, ws_data, ws_close, this);
  try {
    next_trial_ = next_trial(out_dir_, options_.participant);
    first_trial_ = begin_trial(-1);
  } catch (...) {
    stop_web_server(ctx_, options_.bind, port_);
    ctx_ = nullptr;
    throw;
  }
  sender_thread_ = std::thread([this] { sender_loop(); });
  std::promise<bool> raised;
  std::future<bool> priority = raised.get_future();
  frame_thread_ = std::thread([this, raised = std::move(raised)]() mutable {
    raised.set_value(options_.realtime && raise_to_real_time());
    frame_loop();
  });
  real_time_priority_ = priority.get();
}

void Server::stop() {
  stop_.store(true);
  {
    std::lock_guard lock(pace_mutex_);
    pace_cv_.notify_all();
  }
  if (frame_thread_.joinable()) frame_thread_.join();
  {
    std::lock_guard lock(post_mutex_);
    sender_stop_ = true;
    post_cv_.notify_all();
  }
  if (sender_thread_.joinable()) sender_thread_.join();
  close_pages();
  stop_web_server(ctx_, options_.bind, port_);
  ctx_ = nullptr;
  finished_.store(true);
  std::lock_guard lock(finish_mutex_);
  finish_cv_.notify_all();
}

void Server::close_pages() {
  // A close frame (1001, going away) tells each page the session ended;
  // stop_web_server then ends the connections themselves.
  static constexpr char kGoingAway[] = "\x03\xe9" "afford serve stopped";
  std::lock_guard lock(pages_mutex_);
  for (const std::unique_ptr<Page>& p : pages_) {
    if (p->ready && !p->broken) {
      mg_websocket_write(p->conn, MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE, kGoingAway, sizeof kGoingAway - 1);
      p->broken = true;
    }
  }
}

bool Server::wait(double timeout_s) {
  std::unique_lock lock(finish_mutex_);
  const auto done = [this] { return finished_.load(); };
  if (!std::isfinite(timeout_s)) {
    finish_cv_.wait(lock, done);
    return true;
  }
  return finish_cv_.wait_for(lock, std::chrono::duration<double>(timeout_s), done);
}

void Server::advance(double seconds) {
  std::unique_lock lock(pace_mutex_);
  allowed_ += seconds;
  pace_cv_.notify_all();
  // Until the frame thread waits for a frame beyond what is allowed (it
  // may start a new trial on the way), or the session ends.
  pace_cv_.wait(lock, [this] {
    return finished_.load() || stop_.load() || (frame_waiting_ && waiting_for_ > allowed_ + 1e-9);
  });
}

std::vector<TrialSummary> Server::trials() const {
  std::lock_guard lock(summary_mutex_);
  return summaries_;
}

std::string Server::last_error() const {
  std::lock_guard lock(summary_mutex_);
  return last_error_;
}

MessageCounts Server::messages() const {
  std::lock_guard lock(pages_mutex_);
  return counts_;
}

int Server::pages() const {
  std::lock_guard lock(pages_mutex_);
  return static_cast<int>(pages_.size());
}

bool Server::push_command(const Command& c) {
  std::lock_guard lock(queue_mutex_);
  if (queue_size_ == kQueue) return false;
  queue_[(queue_head_ + queue_size_) % kQueue] = c;
  ++queue_size_;
  return true;
}

size_t Server::pop_commands(Command* out, size_t max) {
  std::lock_guard lock(queue_mutex_);
  size_t n = 0;
  while (n < max && queue_size_ > 0) {
    out[n++] = queue_[queue_head_];
    queue_head_ = (queue_head_ + 1) % kQueue;
    --queue_size_;
  }
  return n;
}

std::unique_ptr<Server::Trial> Server::begin_trial(int actee) {
  auto t = std::make_unique<Trial>();
  t->number = next_trial_;
  t->actee = actee;
  t->stem = trial_stem(options_.participant, t->number);
  t->session = write_trial_session(session_, actee < 0 ? std::string() : shelf_[static_cast<size_t>(actee)].file,
                                   out_dir_, t->stem);
  t->actee_name = t->session.model.has_actee ? t->session.model.actee_name : "";
  t->session_file = (out_dir_ / (t->stem + ".yaml")).string();
  t->recording = (out_dir_ / (t->stem + ".afrec")).string();
  const fs::path outputs = out_dir_ / t->stem;
  std::error_code ec;
  fs::create_directories(outputs, ec);
  if (ec) throw std::runtime_error("cannot create " + outputs.string() + ": " + ec.message());
  t->outputs = outputs.string();
  t->recorder = std::make_unique<Recorder>(t->recording, t->session,
                                           "page (afford serve), participant " + options_.participant + ", trial " +
                                               std::to_string(t->number));
  t->timeline_file = std::make_unique<CheckedFile>((outputs / "timeline.jsonl").string());
  t->trace_file = std::make_unique<CheckedFile>((outputs / "trace.csv").string());
  t->timeline = std::make_unique<TimelineWriter>(t->timeline_file->file);
  t->trace = std::make_unique<TraceWriter>(t->trace_file->file);
  SceneInfo info{t->number, options_.participant, t->recording, t->actee_name, shelf_names_, &guides_};
  t->scene = scene_message(t->session, grip_, start_, limits_, info);
  t->events = std::make_shared<EventRing>(t->session.rules);
  ++next_trial_;
  return t;
}

void Server::frame_loop() {
  std::unique_ptr<Trial> trial = std::move(first_trial_);
  double offset = 0;  // s of session time before this trial
  while (trial) {
    current_trial_.store(trial->number);
    trials_started_.fetch_add(1);
    post_scene(trial->scene, trial->events);
    Source source(*this, trial->session.model, offset, trial->recorder.get());
    Poster poster(
        this, [](void* s, const char* text, size_t n) {
          Server& server = *static_cast<Server*>(s);
          std::lock_guard lock(server.post_mutex_);
          std::memcpy(server.state_.data(), text, n);
          server.state_bytes_ = n;
          ++server.state_seq_;
          server.post_cv_.notify_one();
        },
        [](void* s) {
          Server& server = *static_cast<Server*>(s);
          std::lock_guard lock(server.post_mutex_);
          server.wake_ = true;
          server.post_cv_.notify_one();
        },
        *trial->events, source.agent(), trial->number, total_misses_);
    std::vector<Observer*> observers = {trial->timeline.get(), trial->trace.get(), trial->recorder.get(), &poster};
    observers.insert(observers.end(), options_.observers.begin(), options_.observers.end());
    const RunResult result = run_session(trial->session, *trial->session.rules, source, observers);

    TrialSummary summary;
    summary.number = trial->number;
    summary.actee = trial->actee_name;
    summary.session_file = trial->session_file;
    summary.recording = trial->recording;
    summary.outputs = trial->outputs;
    summary.frames = result.frames;
    summary.end_time = result.end_time;
    summary.inferences = result.inferences;
    summary.deadline_misses = source.misses();
    summary.max_lateness = source.max_lateness();
    try {
      trial->timeline_file->close();
      trial->trace_file->close();
    } catch (const std::exception& e) {
      summary.error = e.what();
    }
    if (!trial->recorder->error().empty()) summary.error = "recording: " + trial->recorder->error();
    trial->recorder.reset();  // closed: the next trial's recording begins
    {
      std::lock_guard lock(summary_mutex_);
      summaries_.push_back(summary);
    }
    offset += result.end_time;
    if (stop_.load() || !source.new_trial() || offset >= options_.duration) break;

    const int previous = trial->actee;
    const int wanted = source.next_actee() == -2 ? previous : source.next_actee();
    trial.reset();
    try {
      trial = begin_trial(wanted);
    } catch (const std::exception& e) {
      const std::string what = wanted >= 0 ? "cannot take " + shelf_names_[static_cast<size_t>(wanted)] : "cannot begin a trial";
      std::fprintf(stderr, "afford serve: %s: %s\n", what.c_str(), e.what());
      post_event(error_message(what + ": " + e.what()));
      {
        std::lock_guard lock(summary_mutex_);
        last_error_ = what + ": " + e.what();
      }
      try {
        if (wanted != previous) trial = begin_trial(previous);
      } catch (const std::exception& again) {
        std::fprintf(stderr, "afford serve: cannot begin a trial: %s\n", again.what());
      }
    }
  }
  finished_.store(true);
  {
    std::lock_guard lock(pace_mutex_);
    pace_cv_.notify_all();
  }
  std::lock_guard lock(finish_mutex_);
  finish_cv_.notify_all();
}

void Server::post_scene(const std::string& scene, std::shared_ptr<EventRing> events) {
  auto message = std::make_shared<const std::string>(scene);
  std::lock_guard lock(post_mutex_);
  scene_ = std::move(message);
  ring_ = std::move(events);
  ++scene_seq_;
  post_cv_.notify_one();
}

void Server::post_event(std::string message) {
  std::lock_guard lock(post_mutex_);
  events_.push_back(std::move(message));
  post_cv_.notify_one();
}

void Server::sender_loop() {
  std::array<char, kStateMessageBytes> state{};
  size_t state_bytes = 0;
  std::uint64_t sent_state = 0;
  std::deque<std::string> events;
  std::shared_ptr<const std::string> scene;
  std::shared_ptr<EventRing> ring;  // the trial's events
  std::uint64_t scene_seq = 0;
  const auto drain = [&](EventRing* r) {
    std::string message;
    while (r != nullptr && r->pop(&message)) events.push_back(std::move(message));
  };
  for (;;) {
    bool new_state = false;
    {
      std::unique_lock lock(post_mutex_);
      post_cv_.wait_for(lock, std::chrono::milliseconds(20), [&] {
        return sender_stop_ || wake_ || state_seq_ != sent_state || !events_.empty() || scene_seq_ != scene_seq;
      });
      if (sender_stop_) return;
      wake_ = false;
      if (state_seq_ != sent_state) {
        std::memcpy(state.data(), state_.data(), state_bytes_);
        state_bytes = state_bytes_;
        sent_state = state_seq_;
        new_state = true;
      }
      for (std::string& m : events_) events.push_back(std::move(m));
      events_.clear();
      scene = scene_;
      scene_seq = scene_seq_;
      if (ring_ != ring) {
        drain(ring.get());  // the last of the trial that ended, before the next one's scene
        ring = ring_;
      }
    }
    drain(ring.get());
    std::lock_guard lock(pages_mutex_);
    for (const std::unique_ptr<Page>& p : pages_) {
      Page& page = *p;
      if (!page.ready || page.broken) continue;
      const auto send = [&](const char* text, size_t n) {
        if (page.broken) return;
        if (mg_websocket_write(page.conn, MG_WEBSOCKET_OPCODE_TEXT, text, n) <= 0) page.broken = true;
      };
      if (!page.greeted) {
        const std::string hello = hello_message(page.driver);
        send(hello.data(), hello.size());
        page.greeted = true;
      }
      if (scene && page.scene_seq != scene_seq) {
        send(scene->data(), scene->size());
        page.scene_seq = scene_seq;
      }
      for (const std::string& m : page.outbox) send(m.data(), m.size());
      page.outbox.clear();
      if (page.scene_seq == 0) continue;  // no scene yet: nothing to draw states in
      for (const std::string& m : events) send(m.data(), m.size());
      if (new_state) {
        send(state.data(), state_bytes);
        states_sent_.fetch_add(1);
      }
    }
    events.clear();
  }
}

int Server::on_connect(const mg_connection* conn) {
  std::lock_guard lock(pages_mutex_);
  if (static_cast<int>(pages_.size()) >= options_.max_pages) {
    std::fprintf(stderr, "afford serve: refused a page: %d are connected already\n", options_.max_pages);
    return 1;
  }
  auto page = std::make_unique<Page>();
  page->id = ++next_page_id_;
  page->conn = const_cast<mg_connection*>(conn);
  bool driven = false;
  for (const std::unique_ptr<Page>& p : pages_) driven = driven || p->driver;
  page->driver = !driven;
  pages_.push_back(std::move(page));
  return 0;
}

void Server::on_ready(mg_connection* conn) {
  {
    std::lock_guard lock(pages_mutex_);
    for (const std::unique_ptr<Page>& p : pages_) {
      if (p->conn == conn) p->ready = true;
    }
  }
  std::lock_guard lock(post_mutex_);
  wake_ = true;
  post_cv_.notify_one();
}

void Server::on_close(const mg_connection* conn) {
  std::lock_guard lock(pages_mutex_);
  for (size_t i = 0; i < pages_.size(); ++i) {
    if (pages_[i]->conn != conn) continue;
    const bool was_driver = pages_[i]->driver;
    pages_.erase(pages_.begin() + static_cast<std::ptrdiff_t>(i));
    if (was_driver && !pages_.empty()) {
      pages_.front()->driver = true;  // the longest connected
      pages_.front()->outbox.push_back(role_message(true));
    }
    return;
  }
}

void Server::reject(Page& page, const std::string& why) {
  // pages_mutex_ held.
  ++counts_.rejected;
  if (log_budget_ > 0) {
    std::fprintf(stderr, "afford serve: page %lld: dropped a message: %s\n", static_cast<long long>(page.id),
                 why.c_str());
    if (--log_budget_ == 0) std::fprintf(stderr, "afford serve: further dropped messages are counted, not logged\n");
  }
  page.outbox.push_back(error_message("dropped: " + why));
}

int Server::on_data(mg_connection* conn, int flags, const char* data, size_t size) {
  const int opcode = flags & 0x0f;
  const bool fin = (flags & 0x80) != 0;
  if (opcode == MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE) return 0;
  if (opcode == MG_WEBSOCKET_OPCODE_PING || opcode == MG_WEBSOCKET_OPCODE_PONG) return 1;
  Page* page = nullptr;
  {
    std::lock_guard lock(pages_mutex_);
    for (const std::unique_ptr<Page>& p : pages_) {
      if (p->conn == conn) page = p.get();
    }
  }
  if (page == nullptr) return 0;
  // Only this connection's thread touches partial and oversize.
  if (opcode == MG_WEBSOCKET_OPCODE_TEXT || opcode == MG_WEBSOCKET_OPCODE_BINARY) {
    page->partial.clear();
    page->oversize = false;
  }
  bool binary = opcode == MG_WEBSOCKET_OPCODE_BINARY;
  if (!page->oversize) {
    if (page->partial.size() + size > kMaxMessageBytes) {
      page->oversize = true;
      page->partial.clear();
      page->partial.shrink_to_fit();
    } else {
      page->partial.append(data, size);
    }
  }
  if (!fin) return 1;
  std::string why;
  Command c;
  bool ok = false;
  if (binary) {
    why = "a text message (JSON), found a binary one";
  } else if (page->oversize) {
    why = "a message of at most " + std::to_string(kMaxMessageBytes) + " bytes, found a larger one";
  } else {
    ok = parse_command(page->partial, limits_, shelf_names_, &c, &why);
  }
  page->partial.clear();
  page->oversize = false;
  {
    std::lock_guard lock(pages_mutex_);
    if (!ok) {
      reject(*page, why);
    } else if (!page->driver) {
      ++counts_.from_watchers;
      page->outbox.push_back(error_message("this page watches: only the driver (the first page) drives"));
    } else if (!page->seq.accept(c)) {
      ++counts_.stale;
      page->outbox.push_back(error_message("dropped a stale message: seq " + std::to_string(c.seq) +
                                           " is not above " + std::to_string(page->seq.last())));
    } else if (!push_command(c)) {
      ++counts_.queue_full;
      page->outbox.push_back(error_message("dropped: the server is busy (its queue is full)"));
    } else {
      ++counts_.accepted;
    }
  }
  std::lock_guard lock(post_mutex_);
  wake_ = true;
  post_cv_.notify_one();
  return 1;
}

}  // namespace afford::serve
