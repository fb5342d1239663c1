// A live session against a USB device (`afford live`): the frame loop paced
// to the wall clock, device samples resampled to the frame rate, and the
// haptic force sent back after every frame.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>

#include "observer.h"
#include "resample.h"
#include "usb_device.h"

namespace afford {

// Paces run_session() in real time: frame time t is served no earlier than
// t after the first device sample (the session's t = 0 is the first
// report's arrival). Ends when the device ends (removed, silent), when
// `stop` is set (Ctrl-C), or at the duration. No allocation per frame.
class RealTimeSource : public SampleSource {
 public:
  // first_sample_timeout_s: how long to wait for the first report.
  RealTimeSource(UsbDevice& device, UsbSampleStream& stream, Resample mode, double device_rate_hz,
                 double duration_s, const std::atomic<bool>* stop, double first_sample_timeout_s);

  bool sample_at(double t, Sample* out) override;
  double duration() const override { return duration_; }

  // Why it ended: "" while running or at the duration; "interrupted";
  // "no report within N s" before the first; the device's reason.
  const char* end_reason() const { return end_reason_; }
  // The device timestamp (s, on the session clock) of the sample the last
  // frame used: the frame's t minus the resampling delay, for hold the
  // time of the held report.
  double device_time() const { return resampled_.device_time() - device_zero_; }
  std::int64_t late_frames() const { return late_frames_; }  // served more than one frame late
  double max_latency_s() const { return max_latency_s_; }   // report arrival to the frame reading it
  double mean_latency_s() const { return latency_n_ > 0 ? latency_sum_s_ / static_cast<double>(latency_n_) : 0; }

 private:
  UsbDevice& device_;
  UsbSampleStream& stream_;
  ResampledSource resampled_;
  double duration_, first_timeout_;
  const std::atomic<bool>* stop_;
  bool started_ = false;
  std::chrono::steady_clock::time_point zero_{};  // wall time of frame t = 0
  double device_zero_ = 0;                        // device time (s) at frame t = 0
  const char* end_reason_ = "";
  std::int64_t late_frames_ = 0, latency_n_ = 0;
  double max_latency_s_ = 0, latency_sum_s_ = 0;
  std::int64_t last_latency_seen_ = -1;
};

// The haptic output of one frame, N per finger (thumb first): the paper's
// F_agr, the effort force at the emphasis, to the thumb; the same force in
// reaction to the fingers that hold the fixed arm (state.finger_on_arm bit
// 0), shared equally among them; nothing to a finger off the tool. The
// actee's reaction F_acr reaches the hand only through the lever, so it is
// already in F_agr (eq. 1's balance): it is not added a second time.
std::array<double, kFingers> haptic_forces(const State& state);

// After each frame, posts haptic_forces() to the device's OUT report.
class HapticObserver : public Observer {
 public:
  explicit HapticObserver(UsbDevice& device) : device_(device) {}
  void on_frame(const Model&, const State& state, const RuleSet&, const RuleState&) override;
  void on_end(const Model&, const State&, const RuleSet&, const RuleState&) override;  // sends zero force
  double peak_force() const { return peak_; }  // N, largest force posted

 private:
  UsbDevice& device_;
  double peak_ = 0;
};

}  // namespace afford
