#include "web_server.h"

#include <arpa/inet.h>
#include <civetweb.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <thread>
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
  // Small messages go out at once: without it a state written while the
  // page has not yet acknowledged the last one waits for its delayed ACK
  // (Nagle's algorithm; up to 40 ms on Linux).
  config.insert(config.end(), {"tcp_nodelay", "1"});
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

namespace {

// Opens and closes a TCP connection to address:port (errors ignored: the
// knock only wakes a poll()).
void knock(const std::string& address, int port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  if (inet_pton(AF_INET, address.c_str(), &a.sin_addr) != 1) return;
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return;
  (void)::connect(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a);
  ::close(fd);
}

// Shuts down this process's connections accepted on `port` (the sockets
// whose own port is `port` and that have a peer: not the listening one,
// not a client's), so that the civetweb threads polling them (a page's
// WebSocket, in 2 s slices) see the end at once. Stopping only.
void end_connections(int port) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/proc/self/fd", ec)) {
    const std::string name = entry.path().filename().string();
    char* end = nullptr;
    const long fd = std::strtol(name.c_str(), &end, 10);
    if (*end != '\0' || fd < 0) continue;
    sockaddr_in self{}, peer{};
    socklen_t n = sizeof self, m = sizeof peer;
    if (::getsockname(static_cast<int>(fd), reinterpret_cast<sockaddr*>(&self), &n) != 0 || self.sin_family != AF_INET ||
        ntohs(self.sin_port) != port) {
      continue;
    }
    if (::getpeername(static_cast<int>(fd), reinterpret_cast<sockaddr*>(&peer), &m) != 0) continue;
    ::shutdown(static_cast<int>(fd), SHUT_RDWR);
  }
}

}  // namespace

void stop_web_server(mg_context* ctx, const std::string& bind, int port) {
  if (ctx == nullptr) return;
  // Listening on every address: knock on this machine's.
  const std::string address = bind == "0.0.0.0" || bind == "localhost" ? "127.0.0.1" : bind;
  std::atomic<bool> stopped{false};
  std::thread knocker([&] {
    // mg_stop() raises its stop flag first, then waits: the first knock
    // after that ends the listening thread's poll().
    while (!stopped.load()) {
      end_connections(port);
      knock(address, port);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  mg_stop(ctx);
  stopped.store(true);
  knocker.join();
  mg_exit_library();
}

}  // namespace afford::serve
