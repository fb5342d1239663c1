#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "state.h"

namespace afford::cli {

namespace {

constexpr std::chrono::milliseconds kRedraw{100};  // at most 10 redraws a second: the terminal is slow

// Seconds between two lines when not on a terminal: kLineSeconds, or
// AFFORD_PROGRESS_SECONDS when it is a number above 0.
std::chrono::steady_clock::duration line_every() {
  double seconds = kLineSeconds;
  if (const char* text = std::getenv("AFFORD_PROGRESS_SECONDS")) {
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end != text && *end == '\0' && v > 0 && v < 1e6) seconds = v;
  }
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
}

}  // namespace

TerminalProgress::TerminalProgress(const char* unit)
    : unit_(unit),
      tty_(::isatty(STDERR_FILENO) == 1),
      every_(tty_ ? std::chrono::duration_cast<Clock::duration>(kRedraw) : line_every()),
      start_(Clock::now()),
      last_(start_) {}

TerminalProgress::~TerminalProgress() {
  if (shown_ && tty_) std::fputs("\r\033[K", stderr);
}

void TerminalProgress::update(long long done, long long total) {
  const Clock::time_point now = Clock::now();
  // On a terminal the first update shows at once; in a log, the first
  // line comes after a whole interval (a short command writes none).
  if ((shown_ || !tty_) && now - last_ < every_) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0;
  total = std::max(total, done);
  const double left = rate > 0 ? static_cast<double>(total - done) / rate : 0;
  if (tty_) {
    constexpr int kBar = 20;  // characters
    const int filled = total > 0 ? static_cast<int>(kBar * done / total) : kBar;
    std::fprintf(stderr, "\r\033[K[%.*s%*s] %s %lld/%lld, %.1f %ss/s, %.1f s left", filled, "####################",
                 kBar - filled, "", unit_, done, total, rate, unit_, left);
  } else {
    std::fprintf(stderr, "%s %lld/%lld, %.1f %ss/s, %.1f s left\n", unit_, done, total, rate, unit_, left);
  }
  std::fflush(stderr);
  shown_ = true;
}

void FrameProgress::on_frame(const Model&, const State& state, const RuleSet&, const RuleState&) {
  progress_.update(state.frame, total_);
}

}  // namespace afford::cli
