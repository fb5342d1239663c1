// A fake USB device for tests: a umockdev test bed with one device in
// /sys and /dev, whose usbdevfs ioctls (the URBs that libusb submits, reaps
// and discards) are answered here, so that afford's ordinary libusb code
// talks to it as to hardware. Must run under umockdev-wrapper (its
// LD_PRELOAD redirects /sys, /dev and the ioctls into the test bed).
//
// The device has one interface (vendor-specific) with an interrupt IN
// endpoint 0x81 and an interrupt OUT endpoint 0x02, 64-byte packets.
#pragma once

#include <umockdev.h>

#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <vector>

namespace afford::test {

class FakeUsbDevice {
 public:
  // plugged: the device is there from the start; else plug() adds it
  // later (a hot-plug arrival). One fake per process at a time (one test
  // bed).
  FakeUsbDevice(std::uint16_t vendor, std::uint16_t product, bool plugged = true);
  ~FakeUsbDevice();
  FakeUsbDevice(const FakeUsbDevice&) = delete;
  FakeUsbDevice& operator=(const FakeUsbDevice&) = delete;

  void plug();
  // Queues one IN report; a pending IN transfer gets it at its next reap.
  void send(std::vector<std::uint8_t> report);
  // Every OUT report the host wrote, in order.
  std::vector<std::vector<std::uint8_t>> written();
  size_t pending();  // IN reports queued, not yet delivered
  // Unplugged: every ioctl from now fails with ENODEV (what the kernel
  // does), without telling udev.
  void unplug_silently();
  // Unplugged with a udev "remove" event (libusb's hot-plug sees it) and
  // the ioctls failing as above.
  void unplug();
  // Only the udev "remove" event; the ioctls go on working (tells the
  // hot-plug path from the ENODEV path).
  void announce_removal();
  std::int64_t unknown_ioctls();  // requests this fake does not answer

 private:
  static gboolean on_ioctl(UMockdevIoctlBase* handler, UMockdevIoctlClient* client, gpointer self);
  gboolean handle(UMockdevIoctlClient* client);

  struct Urb {
    UMockdevIoctlData* urb = nullptr;     // the struct usbdevfs_urb, resolved
    UMockdevIoctlData* buffer = nullptr;  // its buffer, resolved
  };

  UMockdevTestbed* testbed_ = nullptr;
  UMockdevIoctlBase* handler_ = nullptr;
  std::string sys_path_, record_;
  std::mutex mutex_;  // the handler runs on umockdev's thread
  std::deque<std::vector<std::uint8_t>> in_reports_;
  std::deque<Urb> in_flight_;  // IN URBs waiting for a report
  std::deque<Urb> done_;       // URBs to reap (OUT done, discarded)
  std::vector<std::vector<std::uint8_t>> written_;
  bool gone_ = false;
  std::int64_t unknown_ = 0;
};

}  // namespace afford::test
