#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace afford::cli {

namespace {
constexpr std::chrono::milliseconds kEvery{100};  // redraws a second at most 10 times: the terminal is slow
}

TerminalProgress::TerminalProgress(const char* unit) : unit_(unit), tty_(::isatty(STDERR_FILENO) == 1), start_(Clock::now()), last_(start_) {}

TerminalProgress::~TerminalProgress() {
  if (shown_) std::fputs("\r\033[K", stderr);
}

void TerminalProgress::update(long long done, long long total) {
  if (!tty_) return;
  const Clock::time_point now = Clock::now();
  if (shown_ && now - last_ < kEvery) return;  // the first frame shows at once
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0;
  total = std::max(total, done);
  const double left = rate > 0 ? static_cast<double>(total - done) / rate : 0;
  constexpr int kBar = 20;  // characters
  const int filled = total > 0 ? static_cast<int>(kBar * done / total) : kBar;
  std::fprintf(stderr, "\r\033[K[%.*s%*s] %s %lld/%lld, %.1f %ss/s, %.1f s left", filled, "####################",
               kBar - filled, "", unit_, done, total, rate, unit_, left);
  std::fflush(stderr);
  shown_ = true;
}

}  // namespace afford::cli
