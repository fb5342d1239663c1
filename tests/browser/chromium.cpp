// Headless Chromium over the DevTools protocol (chromium.h).
#include "chromium.h"

#include <civetweb.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <thread>
#include <vector>

#include "png.h"

extern char** environ;

namespace afford::browser {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

bool executable(const fs::path& p) { return ::access(p.c_str(), X_OK) == 0 && fs::is_regular_file(p); }

std::vector<std::uint8_t> base64_decode(const std::string& text) {
  std::vector<std::uint8_t> out;
  unsigned bits = 0;
  int count = 0;
  for (const char c : text) {
    int v = -1;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    else if (c >= '0' && c <= '9') v = c - '0' + 52;
    else if (c == '+') v = 62;
    else if (c == '/') v = 63;
    if (v < 0) continue;  // '=' and line breaks
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<std::uint8_t>((bits >> count) & 0xff));
    }
  }
  return out;
}

}  // namespace

std::string find_chromium() {
  if (const char* given = std::getenv("AFFORD_CHROMIUM")) return executable(given) ? given : "";
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (const char* name : {"chromium", "chromium-browser"}) {
    size_t from = 0;
    while (from <= dirs.size()) {
      const size_t to = std::min(dirs.find(':', from), dirs.size());
      const fs::path candidate = fs::path(dirs.substr(from, to - from)) / name;
      if (executable(candidate)) return candidate.string();
      from = to + 1;
    }
  }
  return "";
}

Chromium::Chromium(const std::string& program, int width, int height) {
  if (!launch(program, width, height)) shut_down();
}

Chromium::~Chromium() { shut_down(); }

bool Chromium::launch(const std::string& program, int width, int height) {
  profile_ = fs::temp_directory_path() / ("afford-chromium-" + std::to_string(::getpid()) + "-" +
                                          std::to_string(Clock::now().time_since_epoch().count()));
  fs::create_directories(profile_);
  const std::vector<std::string> args = {
      program,
      "--headless=new",
      "--no-sandbox",  // containers and root: the page is our own
      "--remote-debugging-port=0",
      "--user-data-dir=" + profile_.string(),
      "--use-angle=swiftshader",  // WebGL in software: no GPU on a CI machine
      "--enable-unsafe-swiftshader",
      "--window-size=" + std::to_string(width) + "," + std::to_string(height),
      "--no-first-run",
      "--no-default-browser-check",
      "--disable-background-timer-throttling",
      "--disable-renderer-backgrounding",
      "--disable-backgrounding-occluded-windows",
      "about:blank"};
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);  // its own group: all its processes end with it
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  const std::string log = (profile_ / "chromium.log").string();
  posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&files, 1, 2);
  const int rc = posix_spawn(&pid_, program.c_str(), &files, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) {
    pid_ = -1;
    error_ = "cannot start " + program + ": " + std::strerror(rc);
    return false;
  }
  // It writes its port and the browser's WebSocket path when it listens.
  const fs::path active = profile_ / "DevToolsActivePort";
  int port = 0;
  std::string path;
  const auto until = Clock::now() + std::chrono::seconds(30);
  while (Clock::now() < until) {
    std::ifstream in(active);
    if (in >> port >> path && port > 0 && !path.empty()) break;
    port = 0;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      error_ = program + " ended before it listened (its log: " + log + ")";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (port == 0) {
    error_ = program + " did not write " + active.string() + " within 30 s";
    return false;
  }
  char text[256] = "";
  conn_ = mg_connect_websocket_client("127.0.0.1", port, 0, text, sizeof text, path.c_str(), nullptr, on_data,
                                      on_close, this);
  if (conn_ == nullptr) {
    error_ = "cannot connect to the DevTools protocol on port " + std::to_string(port) + ": " + text;
    return false;
  }
  return true;
}

void Chromium::shut_down() {
  if (conn_ != nullptr) {
    call("Browser.close", Json::object(), "", 5);
    mg_close_connection(conn_);
    conn_ = nullptr;
  }
  if (pid_ > 0) {
    // Its whole group: the renderers and the GPU process too.
    const auto reaped = [this](double seconds) {
      const auto until = Clock::now() + std::chrono::duration<double>(seconds);
      int status = 0;
      while (Clock::now() < until) {
        if (::waitpid(pid_, &status, WNOHANG) == pid_) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
      return false;
    };
    if (!reaped(5)) {
      ::kill(-pid_, SIGTERM);
      if (!reaped(5)) {
        ::kill(-pid_, SIGKILL);
        reaped(5);
      }
    }
    ::kill(-pid_, SIGKILL);  // any child left behind in the group
    pid_ = -1;
  }
  if (!profile_.empty()) {
    std::error_code ec;
    fs::remove_all(profile_, ec);
    profile_.clear();
  }
}

int Chromium::on_data(mg_connection*, int flags, char* data, size_t size, void* self) {
  Chromium& c = *static_cast<Chromium*>(self);
  const int opcode = flags & 0x0f;
  if (opcode == MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE) return 0;
  if (opcode != MG_WEBSOCKET_OPCODE_TEXT && opcode != MG_WEBSOCKET_OPCODE_CONTINUATION) return 1;
  std::lock_guard lock(c.mutex_);
  if (opcode == MG_WEBSOCKET_OPCODE_TEXT) c.partial_.clear();
  c.partial_.append(data, size);
  if ((flags & 0x80) == 0) return 1;  // more fragments follow
  Json j = Json::parse(c.partial_, nullptr, false);
  c.partial_.clear();
  if (!j.is_discarded() && j.is_object() && j.contains("id") && j["id"].is_number_integer()) {
    const long long id = j["id"].get<long long>();  // before the move: `a = b` evaluates b first
    c.replies_[id] = std::move(j);
    c.cv_.notify_all();
  }
  return 1;  // events (no id) are not needed
}

void Chromium::on_close(const mg_connection*, void* self) {
  Chromium& c = *static_cast<Chromium*>(self);
  std::lock_guard lock(c.mutex_);
  c.closed_ = true;
  c.cv_.notify_all();
}

Json Chromium::call(const std::string& method, const Json& params, const std::string& session, double timeout_s) {
  if (conn_ == nullptr) return nullptr;
  long long id = 0;
  {
    std::lock_guard lock(mutex_);
    id = ++next_id_;
  }
  Json message{{"id", id}, {"method", method}, {"params", params}};
  if (!session.empty()) message["sessionId"] = session;
  const std::string text = message.dump();
  if (mg_websocket_client_write(conn_, MG_WEBSOCKET_OPCODE_TEXT, text.data(), text.size()) <= 0) {
    error_ = method + ": the connection to Chromium is broken";
    return nullptr;
  }
  std::unique_lock lock(mutex_);
  const bool answered = cv_.wait_for(lock, std::chrono::duration<double>(timeout_s),
                                     [&] { return closed_ || replies_.count(id) > 0; });
  if (!answered || replies_.count(id) == 0) {
    error_ = method + ": no answer within " + std::to_string(timeout_s) + " s";
    return nullptr;
  }
  Json reply = std::move(replies_[id]);
  replies_.erase(id);
  if (reply.contains("error")) {
    error_ = method + ": " + reply["error"].dump();
    return nullptr;
  }
  return reply["result"];
}

std::string Chromium::open(const std::string& url) {
  const Json target = call("Target.createTarget", {{"url", "about:blank"}});
  if (target.is_null()) return "";
  const Json attached = call("Target.attachToTarget", {{"targetId", target["targetId"]}, {"flatten", true}});
  if (attached.is_null()) return "";
  const std::string session = attached["sessionId"];
  if (call("Page.navigate", {{"url", url}}, session).is_null()) return "";
  return session;
}

Json Chromium::evaluate(const std::string& session, const std::string& expression) {
  const Json r = call("Runtime.evaluate",
                      {{"expression", expression}, {"returnByValue", true}, {"awaitPromise", true}}, session);
  if (r.is_null()) return nullptr;
  if (r.contains("exceptionDetails")) {
    error_ = "JavaScript: " + r["exceptionDetails"].dump();
    return nullptr;
  }
  return r["result"].value("value", Json());
}

bool Chromium::wait_until(const std::string& session, const std::string& condition, double timeout_s) {
  const auto until = Clock::now() + std::chrono::duration<double>(timeout_s);
  while (Clock::now() < until) {
    const Json v = evaluate(session, "Boolean(" + condition + ")");
    if (v.is_boolean() && v.get<bool>()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

void Chromium::mouse(const std::string& session, const std::string& type, double x, double y) {
  Json params{{"type", type}, {"x", x}, {"y", y}, {"button", "left"}, {"clickCount", 1}};
  if (type == "mouseMoved") params["buttons"] = 1;  // the left button held: a drag
  call("Input.dispatchMouseEvent", params, session, 10);
}

void Chromium::click(const std::string& session, double x, double y) {
  mouse(session, "mousePressed", x, y);
  mouse(session, "mouseReleased", x, y);
}

void Chromium::key(const std::string& session, const std::string& name, int code) {
  for (const char* type : {"rawKeyDown", "keyUp"}) {
    call("Input.dispatchKeyEvent", {{"type", type}, {"key", name}, {"code", name}, {"windowsVirtualKeyCode", code}},
         session, 10);
  }
}

render::Image Chromium::screenshot(const std::string& session) {
  const Json r = call("Page.captureScreenshot", {{"format", "png"}}, session, 60);
  if (r.is_null() || !r.contains("data")) return {};
  return render::decode_png(base64_decode(r["data"].get<std::string>()));
}

}  // namespace afford::browser
