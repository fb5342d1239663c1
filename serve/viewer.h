// `afford view`: the page of `afford serve` (web/) playing a recording
// instead of a live session. The recording is re-run once
// (recording_view.h) and served as /recording.json; the page, opened at
// /?view, plays, pauses, scrubs and jumps to each event by itself. No
// WebSocket: nothing is driven.
#pragma once

#include <cstdint>
#include <string>

struct mg_context;

namespace afford::serve {

struct ViewOptions {
  std::string recording;          // a .afrec (recording_view.h's find_recording resolves folders)
  std::string bind = "127.0.0.1"; // IPv4 address to listen on
  int port = 8080;                // 0: any free port (port() says which)
  std::string web_dir;            // the page's files (default the shipped web/)
  std::string three_dir = "/usr/share/javascript/three";  // Debian's libjs-three, served as /three/
};

class Viewer {
 public:
  // Re-runs the recording (std::runtime_error or DataError naming the file).
  explicit Viewer(ViewOptions options);
  ~Viewer();  // stops
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Listens (std::runtime_error: the port is taken, the address is bad,
  // web/ is missing).
  void start();
  void stop();
  int port() const { return port_; }
  std::string url() const;  // the page in view mode: http://ADDR:PORT/?view
  const std::string& document() const { return document_; }  // /recording.json
  std::int64_t frames() const { return frames_; }
  int inferences() const { return inferences_; }
  bool identical() const { return identical_; }

 private:
  ViewOptions options_;
  std::string web_dir_;
  std::string document_;
  std::int64_t frames_ = 0;
  int inferences_ = 0;
  bool identical_ = false;
  int port_ = 0;
  mg_context* ctx_ = nullptr;
};

}  // namespace afford::serve
