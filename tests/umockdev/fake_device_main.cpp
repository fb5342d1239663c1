// afford_fake_usb_device DEVICE.yaml PERIOD_MS UNPLUG_MS -- COMMAND...:
// builds the device that DEVICE.yaml describes in a umockdev test bed
// (fake_usb_device.h), streams IN reports every PERIOD_MS (the report id,
// then zeros: every channel at its zero, within the hand's ranges), runs
// COMMAND (which inherits the test bed: `afford live ...`), unplugs the
// device (udev "remove" and ENODEV) UNPLUG_MS after the first report, and
// exits with COMMAND's status, or 99 when a device with an OUT report got
// no force command. Run it under umockdev-wrapper. For CLI tests of
// `afford live` against a device without hardware.
#include <spawn.h>
#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "device_description.h"
#include "fake_usb_device.h"

extern char** environ;

int main(int argc, char** argv) {
  if (argc < 6 || std::strcmp(argv[4], "--") != 0) {
    std::fprintf(stderr, "usage: %s DEVICE.yaml PERIOD_MS UNPLUG_MS -- COMMAND...\n", argv[0]);
    return 2;
  }
  const afford::DeviceDescription d = afford::load_device_description(argv[1]);
  const int period_ms = std::atoi(argv[2]);
  const int unplug_ms = std::atoi(argv[3]);
  afford::test::FakeUsbDevice fake(d.vendor, d.product);
  std::atomic<bool> stop{false};
  std::thread producer([&] {
    const auto start = std::chrono::steady_clock::now();
    bool unplugged = false;
    for (int k = 0; !stop.load(); ++k) {
      std::vector<std::uint8_t> r(static_cast<size_t>(d.in_size), 0);
      if (d.in_report_id >= 0) r[0] = static_cast<std::uint8_t>(d.in_report_id);
      if (!unplugged) fake.send(r);
      if (!unplugged && std::chrono::steady_clock::now() - start > std::chrono::milliseconds(unplug_ms)) {
        fake.unplug();
        unplugged = true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(period_ms));
    }
  });
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[5], nullptr, nullptr, argv + 5, environ) != 0) {
    std::perror("posix_spawnp");
    stop.store(true);
    producer.join();
    return 2;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  stop.store(true);
  producer.join();
  const size_t written = fake.written().size();
  std::printf("fake device: %zu force reports written\n", written);
  if (d.has_out && written == 0) return 99;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
