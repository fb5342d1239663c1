// `afford view` (viewer.h): civetweb serving web/, three.js and the recording.
#include "viewer.h"

#include <civetweb.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "data_dir.h"
#include "recording_view.h"

namespace afford::serve {

namespace fs = std::filesystem;

namespace {

int log_message(const mg_connection*, const char* message) {
  std::fprintf(stderr, "afford view: web server: %s\n", message);
  return 1;
}

// GET /recording.json: the document, built once before listening.
int send_document(mg_connection* conn, void* viewer) {
  const std::string& doc = static_cast<const Viewer*>(viewer)->document();
  mg_send_http_ok(conn, "application/json", static_cast<long long>(doc.size()));
  mg_write(conn, doc.data(), doc.size());
  return 200;
}

}  // namespace

Viewer::Viewer(ViewOptions options) : options_(std::move(options)) {
  web_dir_ = options_.web_dir.empty() ? shipped_path("web") : options_.web_dir;
  RecordingView view = recording_view(options_.recording);
  document_ = std::move(view.json);
  frames_ = view.frames;
  inferences_ = view.inferences;
  identical_ = view.identical;
}

Viewer::~Viewer() { stop(); }

std::string Viewer::url() const { return "http://" + options_.bind + ":" + std::to_string(port_) + "/?view"; }

void Viewer::start() {
  if (!fs::is_regular_file(fs::path(web_dir_) / "index.html")) {
    throw std::runtime_error("the page's files are not in " + web_dir_ + " (no index.html)");
  }
  if (!fs::is_regular_file(fs::path(options_.three_dir) / "build" / "three.module.js")) {
    std::fprintf(stderr,
                 "afford view: warning: three.js is not in %s (Debian's libjs-three): the page cannot draw the "
                 "scene\n",
                 options_.three_dir.c_str());
  }
  mg_init_library(0);
  const std::string ports = options_.bind + ":" + std::to_string(options_.port);
  const std::string three = "/three/=" + options_.three_dir + "/";  // /three/x is three_dir/x
  const char* config[] = {"document_root", web_dir_.c_str(), "listening_ports", ports.c_str(), "num_threads", "4",
                          "enable_directory_listing", "no", "url_rewrite_patterns", three.c_str(),
                          "request_timeout_ms", "10000", nullptr};
  mg_callbacks callbacks{};
  callbacks.log_message = log_message;
  mg_init_data init{&callbacks, this, config};
  char text[256] = "";
  unsigned code = 0;
  mg_error_data error{&code, text, sizeof text};
  ctx_ = mg_start2(&init, &error);
  if (ctx_ == nullptr) {
    mg_exit_library();
    throw std::runtime_error("cannot serve on " + ports + ": " + (text[0] ? text : "the web server did not start"));
  }
  mg_set_request_handler(ctx_, "/recording.json$", send_document, this);
  mg_server_port listening[4]{};
  const int n = mg_get_server_ports(ctx_, 4, listening);
  port_ = n > 0 ? listening[0].port : options_.port;
}

void Viewer::stop() {
  if (ctx_ == nullptr) return;
  mg_stop(ctx_);
  ctx_ = nullptr;
  mg_exit_library();
}

}  // namespace afford::serve
