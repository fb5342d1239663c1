// The libusb path end to end without hardware: a fake device in a umockdev
// test bed (fake_usb_device.h) answers the usbdevfs ioctls, and afford's
// ordinary UsbDevice enumerates it, reads its IN reports, writes force
// commands that the fake checks, sees timeouts when it goes silent, and
// sees it removed (ENODEV, and udev's hot-plug "remove"). Runs under
// umockdev-wrapper (tests/CMakeLists.txt).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <thread>

#include "fake_usb_device.h"
#include "load.h"
#include "recording.h"
#include "report_decoder.h"
#include "run.h"
#include "session.h"
#include "usb_device.h"
#include "usb_live.h"
#include "../test_util.h"

namespace afford {
namespace {
using test::kDeg;

using ::testing::HasSubstr;
using test::FakeUsbDevice;
using namespace std::chrono_literals;


Model hand_model() { return compile_agent_only(load_agent(AFFORD_SOURCE_DIR "/agents/hand.yaml")); }

// A glove report (devices/glove.yaml): every sensor at `centideg`, the
// tracker at x = `x_mm`.
std::vector<std::uint8_t> glove_report(int centideg, int x_mm) {
  std::vector<std::uint8_t> r(64, 0);
  r[0] = 1;
  for (int s = 0; s < 22; ++s) write_raw(&r[1 + 2 * s], 2, false, centideg);
  write_raw(&r[45], 4, false, x_mm * 100);
  return r;
}

template <typename F>
bool wait_for(F done, std::chrono::milliseconds limit = 3000ms) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(1ms);
  }
  return true;
}

class UsbUmockdev : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* preload = std::getenv("LD_PRELOAD");
    if (preload == nullptr || std::string(preload).find("umockdev") == std::string::npos) {
      GTEST_SKIP() << "not under umockdev-wrapper";
    }
  }
};

TEST_F(UsbUmockdev, NoDeviceIsAClearError) {
  const DeviceDescription glove = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  FakeUsbDevice other(glove.vendor, static_cast<std::uint16_t>(glove.product + 1));  // another product
  std::string error;
  EXPECT_EQ(UsbDevice::open(glove, {}, &error), nullptr);
  EXPECT_THAT(error, HasSubstr("no USB device 1d50:6100 (glove) is connected"));
}

TEST_F(UsbUmockdev, WaitsForTheDeviceToArrive) {
  const DeviceDescription glove = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  FakeUsbDevice fake(glove.vendor, glove.product, false);  // the test bed, not yet the device
  std::unique_ptr<UsbDevice> dev;
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  std::thread opener([&] { dev = UsbDevice::wait_and_open(glove, {}, 5.0, &error); });
  std::this_thread::sleep_for(300ms);
  fake.plug();
  opener.join();
  ASSERT_NE(dev, nullptr) << error;
  EXPECT_GE(std::chrono::steady_clock::now() - start, 300ms);
}

TEST_F(UsbUmockdev, EnumeratesOpensAndDecodesInReports) {
  const DeviceDescription glove = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  FakeUsbDevice fake(glove.vendor, glove.product);
  std::string error;
  std::unique_ptr<UsbDevice> dev = UsbDevice::open(glove, {}, &error);
  ASSERT_NE(dev, nullptr) << error;
  fake.send(glove_report(1000, 100));   // 10 deg, 100 mm
  auto wrong = glove_report(0, 0);
  wrong[0] = 2;
  fake.send(wrong);                     // another report id: skipped
  fake.send({1, 2, 3});                 // short: skipped
  fake.send(glove_report(9500, 0));     // 95 deg: beyond the thumb's IP range: skipped
  fake.send(glove_report(2000, 200));   // 20 deg, 200 mm
  dev->start(std::chrono::steady_clock::now());
  const Model m = hand_model();
  ReportDecoder decoder(glove, m);
  UsbSampleStream stream(*dev, decoder);
  std::vector<Sample> got;
  ASSERT_TRUE(wait_for([&] {
    Sample s;
    while (stream.pull(&s) == DeviceStream::Pull::sample) got.push_back(s);
    return got.size() >= 2 && decoder.skipped() >= 3;
  })) << got.size() << " samples, " << decoder.skipped() << " skipped";
  dev->stop();
  ASSERT_EQ(got.size(), 2u);
  EXPECT_NEAR(got[0].joint[1][1], 10 * kDeg, 1e-12);
  EXPECT_NEAR(got[0].hand.translation().x(), 0.1, 1e-12);
  EXPECT_NEAR(got[1].joint[4][0], 20 * kDeg, 1e-12);
  EXPECT_NEAR(got[1].hand.translation().x(), 0.2, 1e-12);
  EXPECT_LE(got[0].t, got[1].t);
  EXPECT_EQ(decoder.count(ReportStatus::wrong_report_id), 1);
  EXPECT_EQ(decoder.count(ReportStatus::short_report), 1);
  EXPECT_EQ(decoder.count(ReportStatus::out_of_range), 1);
  EXPECT_EQ(dev->reports_received(), 5);
  EXPECT_EQ(fake.unknown_ioctls(), 0);
}

TEST_F(UsbUmockdev, WritesForceCommandsTheDeviceChecks) {
  const DeviceDescription ff = load_device_description(AFFORD_SOURCE_DIR "/devices/force_feedback.yaml");
  FakeUsbDevice fake(ff.vendor, ff.product);
  std::string error;
  std::unique_ptr<UsbDevice> dev = UsbDevice::open(ff, {}, &error);
  ASSERT_NE(dev, nullptr) << error;
  dev->start(std::chrono::steady_clock::now());
  dev->post_forces({5.0, 1.25, 0.0, -3.0, 25.0});
  ASSERT_TRUE(wait_for([&] { return !fake.written().empty(); }));
  dev->post_forces({0, 0, 0, 0, 0});
  dev->stop();  // sends the last forces first
  const auto w = fake.written();
  ASSERT_GE(w.size(), 2u);
  const std::vector<std::uint8_t>& first = w.front();
  ASSERT_EQ(first.size(), 16u);
  EXPECT_EQ(first[0], 4);                                // report id
  EXPECT_EQ(read_raw(&first[1], 2, false, false), 500);  // 5 N at 100 counts/N
  EXPECT_EQ(read_raw(&first[3], 2, false, false), 125);
  EXPECT_EQ(read_raw(&first[5], 2, false, false), 0);
  EXPECT_EQ(read_raw(&first[7], 2, false, false), 0);     // negative: none
  EXPECT_EQ(read_raw(&first[9], 2, false, false), 2000);  // saturated at 20 N
  const std::vector<std::uint8_t>& last = w.back();
  for (size_t i = 1; i < last.size(); ++i) EXPECT_EQ(last[i], 0) << i;
  EXPECT_EQ(dev->send_errors(), 0);
  EXPECT_EQ(fake.unknown_ioctls(), 0);
}

TEST_F(UsbUmockdev, SilentDeviceTimesOutThenEnds) {
  const DeviceDescription glove = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  FakeUsbDevice fake(glove.vendor, glove.product);
  UsbOptions options;
  options.read_timeout_ms = 20;
  options.silence_limit_s = 0.2;
  std::string error;
  std::unique_ptr<UsbDevice> dev = UsbDevice::open(glove, options, &error);
  ASSERT_NE(dev, nullptr) << error;
  fake.send(glove_report(0, 0));
  dev->start(std::chrono::steady_clock::now());
  ASSERT_TRUE(wait_for([&] { return dev->ended(); }));
  EXPECT_GE(dev->read_timeouts(), 5);
  EXPECT_THAT(dev->end_reason(), HasSubstr("silent"));
  EXPECT_EQ(dev->reports_received(), 1);
  // The stream gives the report that came, then ends.
  const Model m = hand_model();
  ReportDecoder decoder(glove, m);
  UsbSampleStream stream(*dev, decoder);
  Sample s;
  EXPECT_EQ(stream.pull(&s), DeviceStream::Pull::sample);
  EXPECT_EQ(stream.pull(&s), DeviceStream::Pull::ended);
}

TEST_F(UsbUmockdev, UnpluggedDeviceEndsWithNoDevice) {
  const DeviceDescription glove = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  FakeUsbDevice fake(glove.vendor, glove.product);
  std::string error;
  std::unique_ptr<UsbDevice> dev = UsbDevice::open(glove, {}, &error);
  ASSERT_NE(dev, nullptr) << error;
  dev->start(std::chrono::steady_clock::now());
  fake.send(glove_report(0, 0));
  ASSERT_TRUE(wait_for([&] { return dev->reports_received() == 1; }));
  fake.unplug_silently();
  ASSERT_TRUE(wait_for([&] { return dev->ended(); }));
  EXPECT_EQ(dev->end_reason(), "device removed");
}

TEST_F(UsbUmockdev, HotplugRemovalIsSeen) {
  const DeviceDescription glove = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  FakeUsbDevice fake(glove.vendor, glove.product);
  std::string error;
  std::unique_ptr<UsbDevice> dev = UsbDevice::open(glove, {}, &error);
  ASSERT_NE(dev, nullptr) << error;
  if (!dev->hotplug_supported()) GTEST_SKIP() << "libusb has no hot-plug support here";
  dev->start(std::chrono::steady_clock::now());
  fake.unplug();
  ASSERT_TRUE(wait_for([&] { return dev->ended(); }));
  // Either path may win the race: the hot-plug callback or ENODEV.
  EXPECT_THAT(dev->end_reason(), HasSubstr("device removed"));
}

TEST_F(UsbUmockdev, HotplugAloneEndsTheStream) {
  const DeviceDescription glove = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  FakeUsbDevice fake(glove.vendor, glove.product);
  std::string error;
  std::unique_ptr<UsbDevice> dev = UsbDevice::open(glove, {}, &error);
  ASSERT_NE(dev, nullptr) << error;
  if (!dev->hotplug_supported()) GTEST_SKIP() << "libusb has no hot-plug support here";
  dev->start(std::chrono::steady_clock::now());
  fake.send(glove_report(0, 0));
  ASSERT_TRUE(wait_for([&] { return dev->reports_received() == 1; }));
  fake.announce_removal();  // udev says it left; its ioctls still answer
  ASSERT_TRUE(wait_for([&] { return dev->ended(); }));
  EXPECT_EQ(dev->end_reason(), "device removed (hot-plug)");
}

// A live session (RealTimeSource, the haptic observer, the recorder) at
// 1 kHz against the fake force-feedback device streaming at 1 kHz; the
// device is pulled out mid-session: the session ends cleanly, says why,
// and the recording holds every frame it ran.
TEST_F(UsbUmockdev, LiveSessionEndsCleanlyWhenTheDeviceIsRemoved) {
  const CompiledSession session = load_session(AFFORD_SOURCE_DIR "/sessions/paper-tongs.yaml");
  const DeviceDescription ff = load_device_description(AFFORD_SOURCE_DIR "/devices/force_feedback.yaml");
  FakeUsbDevice fake(ff.vendor, ff.product);
  std::string error;
  std::unique_ptr<UsbDevice> dev = UsbDevice::open(ff, {}, &error);
  ASSERT_NE(dev, nullptr) << error;
  std::atomic<bool> stop_producer{false};
  std::thread producer([&] {
    for (int k = 0; !stop_producer.load(); ++k) {
      std::vector<std::uint8_t> r(16, 0);
      r[0] = 3;
      write_raw(&r[3], 2, false, 450 + (k % 100));  // index MCP from 0 deg
      write_raw(&r[11], 4, false, k);
      fake.send(r);
      if (k == 300) fake.unplug();
      std::this_thread::sleep_for(1ms);
    }
  });
  const std::string rec = (std::filesystem::temp_directory_path() / "afford_usb_live_test.afrec").string();
  ReportDecoder decoder(ff, session.model);
  UsbSampleStream stream(*dev, decoder);
  RealTimeSource source(*dev, stream, ff.resample, ff.rate, 5.0, nullptr, 2.0);
  HapticObserver haptic(*dev);
  Recorder recorder(rec, session, "device " + ff.name);
  Observer* const observers[] = {&haptic, &recorder};
  dev->start(std::chrono::steady_clock::now());
  const RunResult result = run_session(session.model, *session.rules, source, observers);
  stop_producer.store(true);
  producer.join();
  dev->stop();
  EXPECT_THAT(dev->end_reason(), HasSubstr("device removed"));
  EXPECT_STREQ(source.end_reason(), "device ended");
  EXPECT_GT(result.frames, 100);
  EXPECT_LT(result.end_time, 2.0);  // not the 5 s asked for
  EXPECT_EQ(recorder.frames(), result.frames);
  EXPECT_TRUE(recorder.error().empty());
  EXPECT_GT(decoder.count(ReportStatus::ok), 100);
  EXPECT_FALSE(fake.written().empty());
  std::filesystem::remove(rec);
}

}  // namespace
}  // namespace afford
