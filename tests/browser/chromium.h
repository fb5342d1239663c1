// Headless Chromium (Debian's `chromium`) driven over the Chrome DevTools
// Protocol, for the browser tests: launched in a process group of its own
// with a temporary profile, talked to through civetweb's WebSocket client
// (the one the serve tests use), and on destruction closed, killed if it
// lingers, reaped and its profile removed. Every call has a time limit: a
// test fails, it never hangs.
#pragma once

#include <sys/types.h>

#include <condition_variable>
#include <filesystem>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

#include "image.h"

struct mg_connection;

namespace afford::browser {

using Json = nlohmann::json;

// The Chromium to drive: $AFFORD_CHROMIUM, else chromium (or
// chromium-browser) on the PATH; "" when there is none.
std::string find_chromium();

class Chromium {
 public:
  // Launches it (headless, software WebGL, a view of width x height CSS
  // pixels) and connects. error() says why when it could not.
  Chromium(const std::string& program, int width, int height);
  ~Chromium();
  Chromium(const Chromium&) = delete;
  Chromium& operator=(const Chromium&) = delete;

  const std::string& error() const { return error_; }

  // A DevTools method, on the browser (session "") or on a page's session;
  // its result, or null after timeout_s (and error() says why).
  Json call(const std::string& method, const Json& params, const std::string& session = "", double timeout_s = 30);

  // Opens a new tab at url; its session id ("" on failure).
  std::string open(const std::string& url);
  // JavaScript in the page; its value (awaiting a promise), null on an exception.
  Json evaluate(const std::string& session, const std::string& expression);
  // Polls a JavaScript condition until it is true; false after timeout_s.
  bool wait_until(const std::string& session, const std::string& condition, double timeout_s);
  // A mouse event at (x, y), CSS pixels: "mousePressed", "mouseMoved", "mouseReleased".
  void mouse(const std::string& session, const std::string& type, double x, double y);
  void click(const std::string& session, double x, double y);
  // A key pressed and released: its DOM key name and Windows key code ("ArrowUp", 38).
  void key(const std::string& session, const std::string& name, int code);
  // The page as it is drawn (Page.captureScreenshot, PNG decoded).
  render::Image screenshot(const std::string& session);

 private:
  static int on_data(mg_connection* conn, int flags, char* data, size_t size, void* self);
  static void on_close(const mg_connection* conn, void* self);
  bool launch(const std::string& program, int width, int height);
  void shut_down();

  std::filesystem::path profile_;
  pid_t pid_ = -1;
  mg_connection* conn_ = nullptr;
  std::string error_;
  std::mutex mutex_;
  std::condition_variable cv_;
  std::map<long long, Json> replies_;
  std::string partial_;  // a fragmented message so far
  bool closed_ = false;
  long long next_id_ = 0;
};

}  // namespace afford::browser
