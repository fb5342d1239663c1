#include "web_server.h"

#include <civetweb.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace afford::serve {
namespace fs = std::filesystem;

namespace {

// civetweb's own log lines go to stderr, named by the command (the
// context's user data: a string literal, so it outlives the server).
int log_message(const mg_connection* conn, const char* message) {
  const auto* command = static_cast<const char*>(mg_get_user_data(mg_get_context(conn)));
  std::fprintf(stderr, "%s: web server: %s\n", command != nullptr ? command : "afford", message);
  return 1;
}

}  // namespace

StartedWebServer start_web_server(const WebServerOptions& o) {
  if (!fs::is_regular_file(fs::path(o.web_dir) / "index.html")) {
    throw std::runtime_error("the page's files are not in " + o.web_dir + " (no index.html)");
  }
  if (!fs::is_regular_file(fs::path(o.three_dir) / "build" / "three.module.js")) {
    std::fprintf(stderr, "%s: warning: three.js is not in %s (Debian's libjs-three): the page cannot draw the scene\n",
                 o.command, o.three_dir.c_str());
  }
  mg_init_library(0);
  const std::string ports = o.bind + ":" + std::to_string(o.port);
  const std::string threads = std::to_string(o.threads);
  const std::string three = "/three/=" + o.three_dir + "/";  // /three/x is three_dir/x
  std::vector<const char*> config = {"document_root", o.web_dir.c_str(), "listening_ports", ports.c_str(),
                                     "num_threads", threads.c_str(), "enable_directory_listing", "no",
                                     "url_rewrite_patterns", three.c_str(), "request_timeout_ms", "10000"};
  if (o.websocket) config.insert(config.end(), {"websocket_timeout_ms", "86400000"});  // a page stays a day
  config.push_back(nullptr);
  mg_callbacks callbacks{};
  callbacks.log_message = log_message;
  mg_init_data init{&callbacks, const_cast<char*>(o.command), config.data()};
  char text[256] = "";
  unsigned code = 0;
  mg_error_data error{&code, text, sizeof text};
  StartedWebServer started;
  started.ctx = mg_start2(&init, &error);
  if (started.ctx == nullptr) {
    mg_exit_library();
    throw std::runtime_error("cannot serve on " + ports + ": " + (text[0] ? text : "the web server did not start"));
  }
  mg_server_port listening[4]{};
  const int n = mg_get_server_ports(started.ctx, 4, listening);
  started.port = n > 0 ? listening[0].port : o.port;
  return started;
}

void stop_web_server(mg_context* ctx) {
  if (ctx == nullptr) return;
  mg_stop(ctx);
  mg_exit_library();
}

}  // namespace afford::serve
