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

// Stops a started server (ctx may be null) and releases civetweb, within
// a few milliseconds: civetweb's listening thread sleeps in poll() for up
// to 2 s (its SOCKET_TIMEOUT_QUANTUM) before it sees the stop, so while
// mg_stop() waits for it, this connects to the server's own address every
// 5 ms to wake it, and shuts down the connections it accepted (a page's
// WebSocket thread polls in the same 2 s slices). `bind` and `port` are
// where it listens.
void stop_web_server(mg_context* ctx, const std::string& bind, int port);

}  // namespace afford::serve
