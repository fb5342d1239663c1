// Starting civetweb for a page of ours: the page's folder as the document
// root, three.js under /three/, and the listening port read back (port 0:
// the system's choice). Shared by afford serve and afford view.
#pragma once

#include <string>

struct mg_context;

namespace afford::serve {

struct WebServerOptions {
  const char* command = "afford";  // a string literal ("afford serve"): names the warnings and the log lines
  std::string web_dir;    // the page: must hold index.html
  std::string three_dir;  // Debian's libjs-three; a warning where it is missing
  std::string bind;       // the address to listen on
  int port = 0;           // 0: any free port
  int threads = 4;        // civetweb's worker threads
  bool websocket = false; // keep WebSocket connections open (a day)
};

struct StartedWebServer {
  mg_context* ctx = nullptr;
  int port = 0;  // the port listened on
};

// Initialises civetweb and starts it; std::runtime_error naming the address
// and the reason when it cannot. The caller adds its handlers, and ends it
// with stop_web_server.
StartedWebServer start_web_server(const WebServerOptions& o);

// Stops a started server (ctx may be null) and releases civetweb.
void stop_web_server(mg_context* ctx);

}  // namespace afford::serve
