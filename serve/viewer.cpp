// `afford view` (viewer.h): civetweb serving web/, three.js and the recording.
#include "viewer.h"

#include <civetweb.h>

#include "data_dir.h"
#include "recording_view.h"
#include "web_server.h"

namespace afford::serve {

namespace {

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
  const StartedWebServer started = start_web_server(
      {.command = "afford view", .web_dir = web_dir_, .three_dir = options_.three_dir, .bind = options_.bind,
       .port = options_.port});
  ctx_ = started.ctx;
  port_ = started.port;
  mg_set_request_handler(ctx_, "/recording.json$", send_document, this);
}

void Viewer::stop() {
  stop_web_server(ctx_, options_.bind, port_);
  ctx_ = nullptr;
}

}  // namespace afford::serve
