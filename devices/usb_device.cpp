#include "usb_device.h"

#include <libusb.h>

#include <algorithm>
#include <cstring>

namespace afford {
namespace {

int LIBUSB_CALL on_left(libusb_context*, libusb_device* device, libusb_hotplug_event, void* user) {
  static_cast<UsbDevice*>(user)->notify_removed(device);
  return 0;
}

int LIBUSB_CALL on_arrived(libusb_context*, libusb_device*, libusb_hotplug_event, void* user) {
  static_cast<std::atomic<bool>*>(user)->store(true);
  return 0;
}

std::string usb_id(const DeviceDescription& d) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04x:%04x", d.vendor, d.product);
  return buf;
}

}  // namespace

std::int64_t steady_now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

UsbDevice::UsbDevice(const DeviceDescription& device, const UsbOptions& options)
    : device_(device), options_(options) {}

std::unique_ptr<UsbDevice> UsbDevice::open(const DeviceDescription& device, const UsbOptions& options,
                                           std::string* error) {
  return wait_and_open(device, options, 0, error);
}

std::unique_ptr<UsbDevice> UsbDevice::wait_and_open(const DeviceDescription& device, const UsbOptions& options,
                                                    double wait_s, std::string* error) {
  std::unique_ptr<UsbDevice> d(new UsbDevice(device, options));
  int r = libusb_init(&d->ctx_);
  if (r != 0) {
    d->ctx_ = nullptr;
    *error = std::string("cannot initialise libusb: ") + libusb_error_name(r);
    return nullptr;
  }
  const bool hotplug = libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG) != 0;
  std::atomic<bool> arrived{false};
  libusb_hotplug_callback_handle arrival = 0;
  if (wait_s > 0 && hotplug) {
    libusb_hotplug_register_callback(d->ctx_, LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED, LIBUSB_HOTPLUG_NO_FLAGS,
                                     device.vendor, device.product, LIBUSB_HOTPLUG_MATCH_ANY, on_arrived, &arrived,
                                     &arrival);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
  std::string why = "no USB device " + usb_id(device) + " (" + device.name + ") is connected";
  while (true) {
    libusb_device** list = nullptr;
    const ssize_t n = libusb_get_device_list(d->ctx_, &list);
    libusb_device* found = nullptr;
    for (ssize_t i = 0; i < n; ++i) {
      libusb_device_descriptor desc{};
      if (libusb_get_device_descriptor(list[i], &desc) != 0) continue;
      if (desc.idVendor == device.vendor && desc.idProduct == device.product) {
        found = list[i];
        break;
      }
    }
    if (found != nullptr) {
      r = libusb_open(found, &d->handle_);
      if (r != 0) {
        d->handle_ = nullptr;
        why = "cannot open USB device " + usb_id(device) + ": " + libusb_error_name(r) +
              (r == LIBUSB_ERROR_ACCESS ? " (permissions: add a udev rule or run as a member of its group)" : "");
      }
    }
    if (list != nullptr) libusb_free_device_list(list, 1);
    if (d->handle_ != nullptr || std::chrono::steady_clock::now() >= deadline) break;
    // Wait for an arrival (hot-plug) or poll again in 100 ms.
    timeval tv{0, 100000};
    if (hotplug) {
      libusb_handle_events_timeout_completed(d->ctx_, &tv, nullptr);
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  if (arrival != 0) libusb_hotplug_deregister_callback(d->ctx_, arrival);
  if (d->handle_ == nullptr) {
    *error = why;
    return nullptr;
  }
  libusb_set_auto_detach_kernel_driver(d->handle_, 1);  // LIBUSB_ERROR_NOT_SUPPORTED elsewhere: fine
  r = libusb_claim_interface(d->handle_, d->device_.interface);
  if (r != 0) {
    *error = "cannot claim interface " + std::to_string(device.interface) + " of USB device " + usb_id(device) +
             ": " + libusb_error_name(r);
    return nullptr;
  }
  d->claimed_ = true;
  // Ask each IN transfer for a whole packet when the report is shorter (a
  // padded report then fits; a short packet still ends the transfer).
  const int packet = libusb_get_max_packet_size(libusb_get_device(d->handle_), device.in_endpoint);
  d->read_length_ = std::min(kMaxReportBytes, std::max(device.in_size, packet > device.in_size ? packet : 0));
  if (hotplug) {
    libusb_hotplug_callback_handle h = 0;
    if (libusb_hotplug_register_callback(d->ctx_, LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT, LIBUSB_HOTPLUG_NO_FLAGS,
                                         device.vendor, device.product, LIBUSB_HOTPLUG_MATCH_ANY, on_left, d.get(),
                                         &h) == 0) {
      d->hotplug_ = h;
    }
  }
  return d;
}

UsbDevice::~UsbDevice() {
  stop();
  if (handle_ != nullptr) {
    if (claimed_) libusb_release_interface(handle_, device_.interface);
    libusb_close(handle_);
  }
  if (ctx_ != nullptr) {
    if (hotplug_ != 0) libusb_hotplug_deregister_callback(ctx_, hotplug_);
    libusb_exit(ctx_);
  }
}

void UsbDevice::start(std::chrono::steady_clock::time_point origin) {
  origin_ = origin;
  reader_ = std::thread([this] { read_loop(); });
  if (device_.has_out) writer_ = std::thread([this] { write_loop(); });
}

void UsbDevice::stop() {
  // Let the writer send the last forces posted (the zero of the session's
  // end) before it stops: at most 100 ms.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(100);
  while (writer_.joinable() && !ended() && sent_seq_.load() != force_seq_.load() &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  stopping_.store(true);
  if (reader_.joinable()) reader_.join();
  if (writer_.joinable()) writer_.join();
}

void UsbDevice::end(const char* reason) {
  const char* expected = nullptr;
  reason_.compare_exchange_strong(expected, reason);
  ended_.store(true, std::memory_order_release);
}

void UsbDevice::notify_removed(libusb_device* device) {
  if (handle_ != nullptr && device == libusb_get_device(handle_)) end("device removed (hot-plug)");
}

std::string UsbDevice::end_reason() const {
  const char* r = reason_.load();
  return r != nullptr ? r : "";
}

void UsbDevice::read_loop() {
  const unsigned timeout = static_cast<unsigned>(options_.read_timeout_ms);
  const int length = read_length_;
  std::array<std::uint8_t, kMaxReportBytes> scratch{};
  auto last_report = std::chrono::steady_clock::now();
  int errors_in_a_row = 0;
  while (!stopping_.load(std::memory_order_relaxed) && !ended_.load(std::memory_order_acquire)) {
    UsbReport* slot = ring_.claim();
    std::uint8_t* buf = slot != nullptr ? slot->bytes.data() : scratch.data();
    int got = 0;
    const int r = device_.transfer == Transfer::bulk
                      ? libusb_bulk_transfer(handle_, device_.in_endpoint, buf, length, &got, timeout)
                      : libusb_interrupt_transfer(handle_, device_.in_endpoint, buf, length, &got, timeout);
    const auto now = std::chrono::steady_clock::now();
    if (r == 0 || (r == LIBUSB_ERROR_TIMEOUT && got > 0)) {
      errors_in_a_row = 0;
      last_report = now;
      received_.fetch_add(1, std::memory_order_relaxed);
      if (slot == nullptr) {
        dropped_.fetch_add(1, std::memory_order_relaxed);
        continue;
      }
      slot->size = got;
      slot->arrival_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(now.time_since_epoch()).count();
      slot->t = std::chrono::duration<double>(now - origin_).count();
      ring_.commit();
    } else if (r == LIBUSB_ERROR_TIMEOUT) {
      timeouts_.fetch_add(1, std::memory_order_relaxed);
      if (std::chrono::duration<double>(now - last_report).count() > options_.silence_limit_s) {
        end("device went silent (no report within the silence limit)");
      }
    } else if (r == LIBUSB_ERROR_NO_DEVICE) {
      end("device removed");
    } else if (r == LIBUSB_ERROR_INTERRUPTED) {
      continue;
    } else {
      read_errors_.fetch_add(1, std::memory_order_relaxed);
      if (++errors_in_a_row >= 20) end("too many USB transfer errors in a row");
    }
  }
}

void UsbDevice::post_forces(const std::array<double, kFingers>& force_n) {
  const std::uint64_t s = force_seq_.load(std::memory_order_relaxed);
  force_seq_.store(s + 1, std::memory_order_relaxed);  // odd: being written
  std::atomic_thread_fence(std::memory_order_release);
  for (int f = 0; f < kFingers; ++f) force_[f].store(force_n[f], std::memory_order_relaxed);
  force_seq_.store(s + 2, std::memory_order_release);
}

void UsbDevice::write_loop() {
  std::array<std::uint8_t, kMaxReportBytes> report{};
  std::array<double, kFingers> forces{};
  std::uint64_t sent_seq = 0;
  const int ep = device_.out_endpoint;
  const unsigned timeout = static_cast<unsigned>(options_.write_timeout_ms);
  while (!stopping_.load(std::memory_order_relaxed) && !ended_.load(std::memory_order_acquire)) {
    const std::uint64_t s1 = force_seq_.load(std::memory_order_acquire);
    if (s1 == sent_seq || (s1 & 1) != 0) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      continue;
    }
    for (int f = 0; f < kFingers; ++f) forces[f] = force_[f].load(std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_acquire);
    if (force_seq_.load(std::memory_order_relaxed) != s1) continue;  // torn: read again
    encode_forces(device_, forces, std::span<std::uint8_t>(report.data(), static_cast<size_t>(device_.out_size)));
    int done = 0;
    const int r = device_.transfer == Transfer::bulk
                      ? libusb_bulk_transfer(handle_, static_cast<unsigned char>(ep), report.data(),
                                             device_.out_size, &done, timeout)
                      : libusb_interrupt_transfer(handle_, static_cast<unsigned char>(ep), report.data(),
                                                  device_.out_size, &done, timeout);
    sent_seq = s1;
    sent_seq_.store(s1);
    if (r == 0) {
      sent_.fetch_add(1, std::memory_order_relaxed);
    } else if (r == LIBUSB_ERROR_NO_DEVICE) {
      end("device removed");
    } else {
      send_errors_.fetch_add(1, std::memory_order_relaxed);
    }
  }
}

DeviceStream::Pull UsbSampleStream::pull(Sample* out) {
  ReportRing& ring = ring_;
  while (true) {
    // Read `ended` first: every report committed before it is then visible.
    const bool ended = ended_.load(std::memory_order_acquire);
    const UsbReport* r = ring.front();
    if (r == nullptr) return ended ? Pull::ended : Pull::empty;
    last_latency_ns_ = steady_now_ns() - r->arrival_ns;
    const ReportStatus s =
        decoder_.decode(std::span<const std::uint8_t>(r->bytes.data(), static_cast<size_t>(r->size)), r->t, out);
    ring.release();
    if (s == ReportStatus::ok) return Pull::sample;
  }
}

}  // namespace afford
