#include "fake_usb_device.h"

#include <linux/ioctl.h>
#include <linux/usbdevice_fs.h>
#include <sys/ioctl.h>

#include <cerrno>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace afford::test {
namespace {

std::string hex16le(std::uint16_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%02x%02x", v & 0xff, v >> 8);
  return buf;
}

void unref(UMockdevIoctlData* d) {
  if (d != nullptr) umockdev_ioctl_data_unref(d);
}

}  // namespace

FakeUsbDevice::FakeUsbDevice(std::uint16_t vendor, std::uint16_t product, bool plugged) {
  testbed_ = umockdev_testbed_new();
  handler_ = umockdev_ioctl_base_new();
  g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(on_ioctl), this);
  GError* error = nullptr;
  if (!umockdev_testbed_attach_ioctl(testbed_, "/dev/bus/usb/001/011", handler_, &error)) {
    const std::string m = error != nullptr ? error->message : "?";
    g_clear_error(&error);
    throw std::runtime_error("umockdev: cannot attach the ioctl handler: " + m);
  }
  // Device descriptor (18 bytes), configuration (9), interface (9), two
  // endpoints (7 each): 0x81 interrupt IN and 0x02 interrupt OUT, 64 bytes,
  // every 1 ms.
  const std::string descriptors = "120100020000004" "0" + hex16le(vendor) + hex16le(product) +
                                  "000100000001"
                                  "09022000010100803209040000" "02ff000000"
                                  "07058103400001"
                                  "07050203400001";
  record_ =
      "P: /devices/pci0000:00/usb1/1-1\n"
      "N: bus/usb/001/011\n"
      "E: SUBSYSTEM=usb\n"
      "E: DEVTYPE=usb_device\n"
      "E: DRIVER=usb\n"
      "E: BUSNUM=001\n"
      "E: DEVNUM=011\n"
      "E: DEVNAME=/dev/bus/usb/001/011\n"
      "A: busnum=1\\n\n"
      "A: devnum=11\\n\n"
      "A: bConfigurationValue=1\\n\n"
      "A: speed=12\\n\n"
      "H: descriptors=" + descriptors + "\n";
  sys_path_ = "/sys/devices/pci0000:00/usb1/1-1";
  if (plugged) plug();
}

void FakeUsbDevice::plug() {
  GError* error = nullptr;
  if (!umockdev_testbed_add_from_string(testbed_, record_.c_str(), &error)) {
    const std::string m = error != nullptr ? error->message : "?";
    g_clear_error(&error);
    throw std::runtime_error("umockdev: cannot add the device: " + m);
  }
}

FakeUsbDevice::~FakeUsbDevice() {
  {
    std::lock_guard lock(mutex_);
    for (Urb& u : in_flight_) unref(u.urb), unref(u.buffer);
    for (Urb& u : done_) unref(u.urb), unref(u.buffer);
    in_flight_.clear();
    done_.clear();
  }
  g_clear_object(&handler_);
  g_clear_object(&testbed_);
}

void FakeUsbDevice::send(std::vector<std::uint8_t> report) {
  std::lock_guard lock(mutex_);
  in_reports_.push_back(std::move(report));
}

std::vector<std::vector<std::uint8_t>> FakeUsbDevice::written() {
  std::lock_guard lock(mutex_);
  return written_;
}

size_t FakeUsbDevice::pending() {
  std::lock_guard lock(mutex_);
  return in_reports_.size();
}

std::int64_t FakeUsbDevice::unknown_ioctls() {
  std::lock_guard lock(mutex_);
  return unknown_;
}

void FakeUsbDevice::unplug_silently() {
  std::lock_guard lock(mutex_);
  gone_ = true;
}

void FakeUsbDevice::unplug() {
  unplug_silently();
  announce_removal();
}

void FakeUsbDevice::announce_removal() { umockdev_testbed_uevent(testbed_, sys_path_.c_str(), "remove"); }

gboolean FakeUsbDevice::on_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  return static_cast<FakeUsbDevice*>(self)->handle(client);
}

gboolean FakeUsbDevice::handle(UMockdevIoctlClient* client) {
  std::lock_guard lock(mutex_);
  const gulong request = umockdev_ioctl_client_get_request(client);
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  if (gone_) {
    // As the kernel after a disconnect: URBs in flight complete with
    // -ESHUTDOWN and can still be reaped (USBDEVFS_CAP_REAP_AFTER_DISCONNECT);
    // everything else fails with ENODEV.
    for (Urb& u : in_flight_) {
      reinterpret_cast<usbdevfs_urb*>(u.urb->data)->status = -ESHUTDOWN;
      reinterpret_cast<usbdevfs_urb*>(u.urb->data)->actual_length = 0;
      done_.push_back(u);
    }
    in_flight_.clear();
    const bool reap = request == USBDEVFS_REAPURB || request == USBDEVFS_REAPURBNDELAY;
    if (request != USBDEVFS_RELEASEINTERFACE && request != USBDEVFS_DISCARDURB && !(reap && !done_.empty())) {
      umockdev_ioctl_client_complete(client, -1, ENODEV);
      return TRUE;
    }
  }
  switch (request) {
    case USBDEVFS_GET_CAPABILITIES: {
      UMockdevIoctlData* d = umockdev_ioctl_data_resolve(arg, 0, sizeof(guint32), nullptr);
      const guint32 caps = USBDEVFS_CAP_BULK_CONTINUATION | USBDEVFS_CAP_NO_PACKET_SIZE_LIM |
                           USBDEVFS_CAP_REAP_AFTER_DISCONNECT | USBDEVFS_CAP_ZERO_PACKET;
      std::memcpy(d->data, &caps, sizeof caps);
      unref(d);
      umockdev_ioctl_client_complete(client, 0, 0);
      return TRUE;
    }
    case USBDEVFS_GETDRIVER:
    case USBDEVFS_IOCTL:  // detaching a kernel driver: there is none
      umockdev_ioctl_client_complete(client, -1, ENODATA);  // no kernel driver bound
      return TRUE;
    case USBDEVFS_CLAIMINTERFACE:
    case USBDEVFS_RELEASEINTERFACE:
    case USBDEVFS_DISCONNECT_CLAIM:
    case USBDEVFS_SETINTERFACE:
    case USBDEVFS_CLEAR_HALT:
    case USBDEVFS_RESET:
    case USBDEVFS_RESETEP:
      umockdev_ioctl_client_complete(client, 0, 0);
      return TRUE;
    case USBDEVFS_SUBMITURB: {
      Urb u;
      u.urb = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_urb), nullptr);
      auto* urb = reinterpret_cast<usbdevfs_urb*>(u.urb->data);
      u.buffer = umockdev_ioctl_data_resolve(u.urb, G_STRUCT_OFFSET(usbdevfs_urb, buffer),
                                             static_cast<gsize>(urb->buffer_length), nullptr);
      if ((urb->endpoint & 0x80) != 0) {
        in_flight_.push_back(u);
      } else {
        written_.emplace_back(u.buffer->data, u.buffer->data + urb->buffer_length);
        urb->actual_length = urb->buffer_length;
        urb->status = 0;
        done_.push_back(u);
      }
      umockdev_ioctl_client_complete(client, 0, 0);
      return TRUE;
    }
    case USBDEVFS_REAPURB:
    case USBDEVFS_REAPURBNDELAY: {
      Urb u;
      if (!done_.empty()) {
        u = done_.front();
        done_.pop_front();
      } else if (!in_flight_.empty() && !in_reports_.empty()) {
        u = in_flight_.front();
        in_flight_.pop_front();
        const std::vector<std::uint8_t> report = std::move(in_reports_.front());
        in_reports_.pop_front();
        auto* urb = reinterpret_cast<usbdevfs_urb*>(u.urb->data);
        const int n = std::min<int>(static_cast<int>(report.size()), urb->buffer_length);
        std::memcpy(u.buffer->data, report.data(), static_cast<size_t>(n));
        urb->actual_length = n;
        urb->status = 0;
      } else {
        umockdev_ioctl_client_complete(client, -1, EAGAIN);
        return TRUE;
      }
      UMockdevIoctlData* ptr = umockdev_ioctl_data_resolve(arg, 0, sizeof(gpointer), nullptr);
      umockdev_ioctl_data_set_ptr(ptr, 0, u.urb);
      umockdev_ioctl_client_complete(client, 0, 0);
      unref(ptr);
      unref(u.urb);
      unref(u.buffer);
      return TRUE;
    }
    case USBDEVFS_DISCARDURB: {
      const gulong addr = reinterpret_cast<gulong>(*reinterpret_cast<void**>(arg->data));
      for (auto it = in_flight_.begin(); it != in_flight_.end(); ++it) {
        if (it->urb->client_addr == addr) {
          reinterpret_cast<usbdevfs_urb*>(it->urb->data)->status = -ENOENT;
          reinterpret_cast<usbdevfs_urb*>(it->urb->data)->actual_length = 0;
          done_.push_back(*it);
          in_flight_.erase(it);
          umockdev_ioctl_client_complete(client, 0, 0);
          return TRUE;
        }
      }
      umockdev_ioctl_client_complete(client, -1, EINVAL);
      return TRUE;
    }
    default:
      ++unknown_;
      std::fprintf(stderr, "fake usb device: unanswered ioctl 0x%lx\n", request);
      return FALSE;
  }
}

}  // namespace afford::test
