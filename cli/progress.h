// Progress of a long command on a terminal: "[#####     ] frame 120/211,
// 58.3 frames/s, 1.6 s left", rewritten in place on stderr. Nothing when stderr is not a
// terminal, so logs and pipes get only the results.
#pragma once

#include <chrono>

namespace afford::cli {

class TerminalProgress {
 public:
  explicit TerminalProgress(const char* unit = "frame");  // what is counted, singular
  ~TerminalProgress();  // clears the line
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  void update(long long done, long long total);

 private:
  using Clock = std::chrono::steady_clock;
  const char* unit_;
  bool tty_;
  bool shown_ = false;
  Clock::time_point start_, last_;
};

}  // namespace afford::cli
