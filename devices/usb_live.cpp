#include "usb_live.h"

#include <algorithm>
#include <thread>

#include "state.h"

namespace afford {

RealTimeSource::RealTimeSource(UsbDevice& device, UsbSampleStream& stream, Resample mode, double device_rate_hz,
                               double duration_s, const std::atomic<bool>* stop, double first_sample_timeout_s)
    : device_(device),
      stream_(stream),
      // Interpolation needs the sample after the frame's time: read the
      // device one period in the past.
      resampled_(stream, mode, mode == Resample::interpolate ? 1.0 / device_rate_hz : 0.0),
      duration_(duration_s),
      first_timeout_(first_sample_timeout_s),
      stop_(stop) {}

bool RealTimeSource::sample_at(double t, Sample* out) {
  using clock = std::chrono::steady_clock;
  if (!started_) {
    // Wait for the first report; the session's clock starts with it.
    const auto deadline = clock::now() + std::chrono::duration<double>(first_timeout_);
    while (device_.reports().front() == nullptr) {
      if (device_.ended()) {
        end_reason_ = "device ended before its first report";
        return false;
      }
      if ((stop_ != nullptr && stop_->load()) || clock::now() > deadline) {
        end_reason_ = stop_ != nullptr && stop_->load() ? "interrupted" : "no report from the device";
        return false;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    device_zero_ = device_.reports().front()->t;
    zero_ = clock::now();
    started_ = true;
  }
  const auto due = zero_ + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(t));
  const auto now = clock::now();
  if (now < due) {
    std::this_thread::sleep_until(due);
  } else if (std::chrono::duration<double>(now - due).count() > 0.001) {
    ++late_frames_;
  }
  if (stop_ != nullptr && stop_->load()) {
    end_reason_ = "interrupted";
    return false;
  }
  if (!resampled_.sample_at(device_zero_ + t, out)) {
    end_reason_ = "device ended";
    return false;
  }
  if (resampled_.ended() && device_.ended()) {
    // Drained everything the device sent before it went: end now rather
    // than hold its last sample.
    end_reason_ = "device ended";
    return false;
  }
  if (stream_.last_latency_ns() != last_latency_seen_) {
    last_latency_seen_ = stream_.last_latency_ns();
    const double l = static_cast<double>(last_latency_seen_) * 1e-9;
    max_latency_s_ = std::max(max_latency_s_, l);
    latency_sum_s_ += l;
    ++latency_n_;
  }
  out->t = t;
  return true;
}

std::array<double, kFingers> haptic_forces(const State& s) {
  std::array<double, kFingers> f{};
  const double fag = std::max(0.0, s.effort_force);
  f[0] = fag;
  int holding = 0;
  for (int i = 1; i < kFingers; ++i) holding += (s.finger_on_arm[i] & 1) != 0;
  if (holding > 0) {
    for (int i = 1; i < kFingers; ++i) {
      if ((s.finger_on_arm[i] & 1) != 0) f[i] = fag / holding;
    }
  }
  return f;
}

void HapticObserver::on_frame(const Model&, const State& state, const RuleSet&, const RuleState&) {
  const std::array<double, kFingers> f = haptic_forces(state);
  peak_ = std::max(peak_, *std::max_element(f.begin(), f.end()));
  device_.post_forces(f);
}

void HapticObserver::on_end(const Model&, const State&, const RuleSet&, const RuleState&) {
  device_.post_forces({0, 0, 0, 0, 0});
}

}  // namespace afford
