// Progress of a long command on stderr, in any output mode. On a terminal:
// "[#####     ] frame 120/211, 58.3 frames/s, 1.6 s left", rewritten in
// place. Otherwise (a pipe, a log) a plain line of the same words every
// kLineSeconds (AFFORD_PROGRESS_SECONDS overrides it), so that a command
// that runs for hours says how far it is without flooding a short one's log.
#pragma once

#include <chrono>

#include "observer.h"

namespace afford::cli {

inline constexpr double kLineSeconds = 5;

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
  Clock::duration every_;  // between two lines (not a terminal) or redraws
  bool shown_ = false;
  Clock::time_point start_, last_;
};

// The frames of a session run, as progress.
class FrameProgress : public Observer {
 public:
  explicit FrameProgress(long long total_frames) : total_(total_frames) {}
  void on_frame(const Model&, const State& state, const RuleSet&, const RuleState&) override;

 private:
  long long total_;
  TerminalProgress progress_;
};

}  // namespace afford::cli
