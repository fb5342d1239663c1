// The lock-free pieces of the USB backend that need no device: the report
// ring (single producer, single consumer) and the sample stream over it,
// and the haptic forces of a frame.
#include <gtest/gtest.h>

#include <thread>

#include "load.h"
#include "state.h"
#include "usb_device.h"
#include "usb_live.h"

namespace afford {
namespace {

TEST(UsbRing, FifoFullAndEmpty) {
  SpscRing<int, 4> ring;
  EXPECT_EQ(ring.front(), nullptr);
  for (int i = 0; i < 4; ++i) {
    int* slot = ring.claim();
    ASSERT_NE(slot, nullptr);
    *slot = i;
    ring.commit();
  }
  EXPECT_EQ(ring.claim(), nullptr);  // full: the caller counts a drop
  EXPECT_EQ(ring.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    ASSERT_NE(ring.front(), nullptr);
    EXPECT_EQ(*ring.front(), i);
    ring.release();
  }
  EXPECT_EQ(ring.front(), nullptr);
}

TEST(UsbRing, TwoThreadsKeepOrderAndLoseNothing) {
  SpscRing<long, 64> ring;
  constexpr long kN = 20000;
  std::thread producer([&] {
    for (long i = 0; i < kN;) {
      if (long* slot = ring.claim()) {
        *slot = i++;
        ring.commit();
      }
    }
  });
  long expected = 0;
  while (expected < kN) {
    if (const long* v = ring.front()) {
      ASSERT_EQ(*v, expected);
      ++expected;
      ring.release();
    }
  }
  producer.join();
}

// The stream over a ring: decodes, skips bad reports, ends only when the
// producer says so and the ring is drained.
TEST(UsbSampleStream, DecodesSkipsAndEndsAfterTheLastReport) {
  const DeviceDescription glove = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  Model m;  // no agent: no range check
  ReportDecoder decoder(glove, m);
  ReportRing ring;
  std::atomic<bool> ended{false};
  UsbSampleStream stream(ring, ended, decoder);
  Sample s;
  EXPECT_EQ(stream.pull(&s), DeviceStream::Pull::empty);
  auto push = [&](int id, int size, double t) {
    UsbReport* r = ring.claim();
    ASSERT_NE(r, nullptr);
    r->bytes.fill(0);
    r->bytes[0] = static_cast<std::uint8_t>(id);
    r->size = size;
    r->t = t;
    r->arrival_ns = steady_now_ns();
    ring.commit();
  };
  push(1, 64, 0.01);
  push(2, 64, 0.02);  // wrong id
  push(1, 10, 0.03);  // short
  push(1, 64, 0.04);
  ended.store(true);
  ASSERT_EQ(stream.pull(&s), DeviceStream::Pull::sample);
  EXPECT_EQ(s.t, 0.01);
  ASSERT_EQ(stream.pull(&s), DeviceStream::Pull::sample);
  EXPECT_EQ(s.t, 0.04);
  EXPECT_EQ(stream.pull(&s), DeviceStream::Pull::ended);
  EXPECT_EQ(decoder.count(ReportStatus::wrong_report_id), 1);
  EXPECT_EQ(decoder.count(ReportStatus::short_report), 1);
  EXPECT_GE(stream.last_latency_ns(), 0);
}

TEST(HapticForces, ThumbGetsTheEffortForceHoldingFingersShareTheReaction) {
  State s;
  s.effort_force = 12;
  s.finger_on_arm = {2, 1, 1, 0, 1};  // thumb on the moving arm; index, middle, little on the fixed one
  const auto f = haptic_forces(s);
  EXPECT_EQ(f[0], 12);
  EXPECT_EQ(f[1], 4);
  EXPECT_EQ(f[2], 4);
  EXPECT_EQ(f[3], 0);
  EXPECT_EQ(f[4], 4);
  s.finger_on_arm = {0, 0, 0, 0, 0};
  s.effort_force = -3;  // never a pull
  const auto g = haptic_forces(s);
  for (double v : g) EXPECT_EQ(v, 0);
}

}  // namespace
}  // namespace afford
