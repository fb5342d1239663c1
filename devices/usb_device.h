// USB devices through libusb-1.0: enumerate by vendor/product, open, claim
// the interface, read IN reports (interrupt or bulk) on a reader thread
// into a lock-free ring buffer, write OUT reports (force commands) on a
// writer thread, notice removal (libusb hot-plug where the platform has it,
// LIBUSB_ERROR_NO_DEVICE otherwise) and silence (read timeouts).
//
// The frame thread only pops reports from the ring and posts forces: no
// allocation, no lock, no system call (UsbSampleStream, below).
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

#include "device_description.h"
#include "report_decoder.h"
#include "resample.h"

struct libusb_context;
struct libusb_device;
struct libusb_device_handle;

namespace afford {

inline constexpr int kMaxReportBytes = 512;

// One IN report as it arrived: its bytes and its arrival time on the
// session clock (s since UsbDevice::start()'s origin).
struct UsbReport {
  double t = 0;
  std::int64_t arrival_ns = 0;  // steady clock, ns (latency measurement)
  int size = 0;
  std::array<std::uint8_t, kMaxReportBytes> bytes{};
};

// Single producer, single consumer, fixed capacity (a power of two); push
// fails (and the caller counts a drop) when full. No allocation after
// construction, no lock.
template <typename T, size_t N>
class SpscRing {
  static_assert((N & (N - 1)) == 0, "capacity must be a power of two");

 public:
  SpscRing() : slots_(std::make_unique<T[]>(N)) {}
  // Producer: the slot to fill, or nullptr when full; then commit().
  T* claim() {
    const size_t h = head_.load(std::memory_order_relaxed);
    if (h - tail_.load(std::memory_order_acquire) >= N) return nullptr;
    return &slots_[h & (N - 1)];
  }
  void commit() { head_.store(head_.load(std::memory_order_relaxed) + 1, std::memory_order_release); }
  // Consumer: the oldest element, or nullptr when empty; then release().
  const T* front() const {
    const size_t t = tail_.load(std::memory_order_relaxed);
    if (t == head_.load(std::memory_order_acquire)) return nullptr;
    return &slots_[t & (N - 1)];
  }
  void release() { tail_.store(tail_.load(std::memory_order_relaxed) + 1, std::memory_order_release); }
  size_t size() const { return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire); }

 private:
  std::unique_ptr<T[]> slots_;
  alignas(64) std::atomic<size_t> head_{0};
  alignas(64) std::atomic<size_t> tail_{0};
};

using ReportRing = SpscRing<UsbReport, 256>;

struct UsbOptions {
  int read_timeout_ms = 100;     // one IN transfer's timeout; each expiry is counted
  double silence_limit_s = 2.0;  // no report for this long ends the stream ("went silent")
  int write_timeout_ms = 50;
};

class UsbDevice {
 public:
  // Enumerates devices with the description's vendor/product, opens the
  // first one, detaches a kernel driver if one is bound, claims the
  // interface. nullptr with *error set when there is none or it cannot be
  // opened (permissions, busy).
  static std::unique_ptr<UsbDevice> open(const DeviceDescription& device, const UsbOptions& options,
                                         std::string* error);
  // Waits up to `wait_s` for the device to be plugged in (hot-plug arrival
  // when libusb supports it, polling otherwise), then opens it.
  static std::unique_ptr<UsbDevice> wait_and_open(const DeviceDescription& device, const UsbOptions& options,
                                                  double wait_s, std::string* error);
  ~UsbDevice();
  UsbDevice(const UsbDevice&) = delete;
  UsbDevice& operator=(const UsbDevice&) = delete;

  // Starts the reader (and writer, with an OUT report) threads; report
  // times count from `origin`.
  void start(std::chrono::steady_clock::time_point origin);
  // Stops the threads, releases the interface, closes. Idempotent.
  void stop();

  // Frame thread: the ring of IN reports.
  ReportRing& reports() { return ring_; }
  // Frame thread: the forces to send (N per finger, thumb first); the
  // writer sends the latest when it differs. No allocation, no lock.
  void post_forces(const std::array<double, kFingers>& force_n);

  // Set once the device is gone or silent (the stream ends when the ring
  // is drained); the reason in words.
  bool ended() const { return ended_.load(std::memory_order_acquire); }
  const std::atomic<bool>& ended_flag() const { return ended_; }
  std::string end_reason() const;

  // Counters (any thread).
  std::int64_t reports_received() const { return received_.load(); }
  std::int64_t reports_dropped() const { return dropped_.load(); }   // ring full
  std::int64_t read_timeouts() const { return timeouts_.load(); }
  std::int64_t reports_sent() const { return sent_.load(); }
  std::int64_t send_errors() const { return send_errors_.load(); }
  std::int64_t read_errors() const { return read_errors_.load(); }  // failed IN transfers (not timeouts)
  bool hotplug_supported() const { return hotplug_ != 0; }

  // From libusb's hot-plug callback: a device with our ids left; ends the
  // stream when it is ours.
  void notify_removed(libusb_device* device);

 private:
  UsbDevice(const DeviceDescription& device, const UsbOptions& options);
  void read_loop();
  void write_loop();
  void end(const char* reason);

  const DeviceDescription& device_;
  UsbOptions options_;
  libusb_context* ctx_ = nullptr;
  libusb_device_handle* handle_ = nullptr;
  bool claimed_ = false;
  int hotplug_ = 0;  // callback handle, 0: none
  std::chrono::steady_clock::time_point origin_{};
  ReportRing ring_;
  std::thread reader_, writer_;
  std::atomic<bool> stopping_{false}, ended_{false};
  std::atomic<const char*> reason_{nullptr};
  std::atomic<std::int64_t> received_{0}, dropped_{0}, timeouts_{0}, sent_{0}, send_errors_{0}, read_errors_{0};
  int read_length_ = 0;  // bytes asked of each IN transfer

  // The force mailbox: a seqlock over the latest forces.
  std::atomic<std::uint64_t> force_seq_{0};
  std::atomic<std::uint64_t> sent_seq_{0};  // the force_seq_ last sent
  std::array<std::atomic<double>, kFingers> force_{};

};

// The frame thread's side: pops reports, decodes them (skipping and
// counting bad ones), and gives timestamped samples to a ResampledSource.
class UsbSampleStream : public DeviceStream {
 public:
  UsbSampleStream(UsbDevice& device, ReportDecoder& decoder)
      : UsbSampleStream(device.reports(), device.ended_flag(), decoder) {}
  // Any producer: a ring and the flag it sets (after its last commit) when
  // it will commit no more.
  UsbSampleStream(ReportRing& ring, const std::atomic<bool>& ended, ReportDecoder& decoder)
      : ring_(ring), ended_(ended), decoder_(decoder) {}
  Pull pull(Sample* out) override;
  // ns from the last popped report's arrival to its pop (latency).
  std::int64_t last_latency_ns() const { return last_latency_ns_; }

 private:
  ReportRing& ring_;
  const std::atomic<bool>& ended_;
  ReportDecoder& decoder_;
  std::int64_t last_latency_ns_ = 0;
};

std::int64_t steady_now_ns();

}  // namespace afford
