// Device descriptions, the report decoder and encoder, and the resampler,
// on plain bytes: no USB involved (the libusb path: test_usb_umockdev.cpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "device_description.h"
#include "load.h"
#include "report_decoder.h"
#include "resample.h"
#include "test_util.h"

namespace afford {
namespace {
using test::kDeg;

using ::testing::HasSubstr;


Model hand_model() { return compile_agent_only(load_agent(AFFORD_SOURCE_DIR "/agents/hand.yaml")); }

const char* const kSmall = R"(device: small
description: test device
usb: {vendor: 0x1234, product: 0x5678, interface: 0, in_endpoint: 0x81, out_endpoint: 0x02, transfer: interrupt}
rate: 100
resample: hold
in_report:
  size: 12
  report_id: 7
  fields:
    - {name: ip, offset: 1, width: 2, endian: little, signed: true, scale: 0.01, unit: deg, to: thumb.distal}
    - {name: mcp, offset: 3, width: 2, endian: big, signed: false, scale: 0.1, value_offset: -45, unit: deg, to: index.metacarpal}
    - {name: x, offset: 5, width: 4, endian: little, signed: true, scale: 0.01, unit: mm, to: hand.x}
    - {name: spare, offset: 9, width: 1}
out_report:
  size: 8
  report_id: 9
  actuators:
    - {finger: thumb, offset: 1, width: 2, endian: little, signed: false, counts_per_newton: 100, saturation: 20 N}
    - {finger: index, offset: 3, width: 1, counts_per_newton: 10, saturation: 30 N}
)";

DeviceDescription small_device() { return read_device_description(load_yaml_string(kSmall, "small.yaml")); }

std::string decoder_error(const std::string& text) {
  try {
    read_device_description(load_yaml_string(text, "dev.yaml"));
  } catch (const DataError& e) {
    return e.what();
  }
  return "no error";
}

TEST(DeviceDescription, ShippedGloveAndForceFeedbackLoad) {
  const DeviceDescription g = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  EXPECT_EQ(g.name, "glove");
  int joints = 0, sensors = 0;
  for (const Field& f : g.fields) {
    if (f.dimension == dim::angle && f.name.rfind("tracker", 0) != 0) ++sensors;
    if (f.target.kind == TargetKind::joint) ++joints;
  }
  EXPECT_GE(sensors, 18);
  EXPECT_LE(sensors, 22);
  EXPECT_EQ(joints, 15);
  EXPECT_TRUE(g.hand_pos_mapped && g.hand_rot_mapped);
  EXPECT_EQ(g.rate, 100);
  EXPECT_EQ(g.resample, Resample::interpolate);
  const DeviceDescription ff = load_device_description(AFFORD_SOURCE_DIR "/devices/force_feedback.yaml");
  EXPECT_TRUE(ff.has_out);
  EXPECT_EQ(ff.actuators.size(), 5u);
  EXPECT_EQ(ff.out_endpoint, 0x02);
}

TEST(DeviceDescription, ReadsEveryField) {
  const DeviceDescription d = small_device();
  EXPECT_EQ(d.vendor, 0x1234);
  EXPECT_EQ(d.product, 0x5678);
  EXPECT_EQ(d.in_endpoint, 0x81);
  EXPECT_EQ(d.in_report_id, 7);
  ASSERT_EQ(d.fields.size(), 4u);
  EXPECT_TRUE(d.fields[1].big_endian);
  EXPECT_DOUBLE_EQ(d.fields[1].value_offset, -45);
  EXPECT_DOUBLE_EQ(d.fields[2].unit_si, 0.001);
  EXPECT_EQ(d.fields[2].target.kind, TargetKind::hand_pos);
  EXPECT_EQ(d.fields[3].target.kind, TargetKind::none);
}

TEST(DeviceDescription, UnknownJointSaysDidYouMean) {
  const std::string e = decoder_error(test::replace_once(kSmall, "to: thumb.distal", "to: thumb.distl"));
  EXPECT_THAT(e, HasSubstr("dev.yaml:10:"));
  EXPECT_THAT(e, HasSubstr("found 'thumb.distl' (did you mean 'thumb.distal'?)"));
}

TEST(DeviceDescription, OverlappingFieldsAreAnError) {
  const std::string e = decoder_error(test::replace_once(kSmall, "{name: mcp, offset: 3", "{name: mcp, offset: 2"));
  EXPECT_THAT(e, HasSubstr("dev.yaml:11:"));
  EXPECT_THAT(e, HasSubstr("found byte 2, already used by field 'ip'"));
}

TEST(DeviceDescription, FieldOnTheReportIdIsAnError) {
  const std::string e = decoder_error(test::replace_once(kSmall, "{name: ip, offset: 1", "{name: ip, offset: 0"));
  EXPECT_THAT(e, HasSubstr("already used by the report id"));
}

TEST(DeviceDescription, FieldBeyondTheReportIsAnError) {
  const std::string e = decoder_error(test::replace_once(kSmall, "{name: x, offset: 5", "{name: x, offset: 9"));
  EXPECT_THAT(e, HasSubstr("dev.yaml:12:"));
  EXPECT_THAT(e, HasSubstr("within the report's 12 bytes"));
}

TEST(DeviceDescription, UnitDimensionMustFitTheTarget) {
  const std::string e = decoder_error(test::replace_once(kSmall, "scale: 0.01, unit: mm, to: hand.x", "scale: 0.01, unit: deg, to: hand.x"));
  EXPECT_THAT(e, HasSubstr("dev.yaml:12:"));
  EXPECT_THAT(e, HasSubstr("expected a channel whose unit is a length"));
}

TEST(DeviceDescription, BadWidthEndianUnitKeyAndTransfer) {
  EXPECT_THAT(decoder_error(test::replace_once(kSmall, "offset: 9, width: 1", "offset: 9, width: 3")),
              HasSubstr("a width of 1, 2 or 4 bytes"));
  EXPECT_THAT(decoder_error(test::replace_once(kSmall, "endian: big", "endian: bgi")), HasSubstr("(did you mean 'big'?)"));
  EXPECT_THAT(decoder_error(test::replace_once(kSmall, "unit: mm", "unit: furlong")), HasSubstr("expected a unit"));
  EXPECT_THAT(decoder_error(test::replace_once(kSmall, "value_offset: -45", "valu_offset: -45")),
              HasSubstr("(did you mean 'value_offset'?)"));
  EXPECT_THAT(decoder_error(test::replace_once(kSmall, "transfer: interrupt", "transfer: isochronous")),
              HasSubstr("expected one of interrupt, bulk"));
  EXPECT_THAT(decoder_error(test::replace_once(kSmall, "finger: index", "finger: indx")),
              HasSubstr("(did you mean 'index'?)"));
  EXPECT_THAT(decoder_error(test::replace_once(kSmall, "in_endpoint: 0x81", "in_endpoint: 0x01")),
              HasSubstr("dev.yaml:3:"));
  EXPECT_THAT(decoder_error(test::replace_once(kSmall, "to: index.metacarpal", "to: thumb.distal")),
              HasSubstr("filled by 'ip'"));
}

// The bytes of one IN report of `small`.
std::vector<std::uint8_t> small_report(int ip_centideg, int mcp_count, int x_hundredth_mm) {
  std::vector<std::uint8_t> r(12, 0);
  r[0] = 7;
  write_raw(&r[1], 2, false, ip_centideg);
  write_raw(&r[3], 2, true, mcp_count);
  write_raw(&r[5], 4, false, x_hundredth_mm);
  return r;
}

TEST(ReportDecoder, DecodesEndiannessSignScaleAndOffset) {
  const DeviceDescription d = small_device();
  const Model m = hand_model();
  ReportDecoder dec(d, m);
  Sample s;
  const auto r = small_report(-1234, 900, -250000);  // -12.34 deg, 90-45 = 45 deg, -2.5 m
  ASSERT_EQ(dec.decode(r, 0.25, &s), ReportStatus::ok);
  EXPECT_DOUBLE_EQ(s.t, 0.25);
  EXPECT_NEAR(s.joint[0][0], -12.34 * kDeg, 1e-12);
  EXPECT_NEAR(s.joint[1][2], 45 * kDeg, 1e-12);
  EXPECT_NEAR(s.hand.translation().x(), -2.5, 1e-12);
  EXPECT_NEAR(dec.channels()[0], -12.34 * kDeg, 1e-12);
  // A joint the device does not sense is neutral, within its range.
  EXPECT_EQ(s.joint[2][1], 0.0);
  // A fingertip the device neither senses nor derives from a chain sits
  // at the wrist, not at whatever the decoder's memory held.
  for (int fi = 0; fi < kFingers; ++fi) EXPECT_EQ(s.fingertip[fi], s.hand.translation()) << fi;
  EXPECT_EQ(dec.count(ReportStatus::ok), 1);
}

TEST(ReportDecoder, RawIntegers) {
  const std::uint8_t b[4] = {0xfe, 0xff, 0xff, 0x7f};
  EXPECT_EQ(read_raw(b, 1, false, false), 0xfe);
  EXPECT_EQ(read_raw(b, 1, false, true), -2);
  EXPECT_EQ(read_raw(b, 2, false, true), -2);
  EXPECT_EQ(read_raw(b, 2, true, false), 0xfeff);
  EXPECT_EQ(read_raw(b, 4, false, true), 0x7ffffffe);
  EXPECT_EQ(read_raw(b, 4, true, true), static_cast<std::int32_t>(0xfeffff7f));
}

TEST(ReportDecoder, ShortWrongIdAndOutOfRangeAreCountedAndSkipped) {
  const DeviceDescription d = small_device();
  const Model m = hand_model();
  ReportDecoder dec(d, m);
  Sample s;
  s.t = -1;
  auto r = small_report(100, 900, 0);
  EXPECT_EQ(dec.decode(std::span(r).first(11), 0, &s), ReportStatus::short_report);
  EXPECT_EQ(dec.decode({}, 0, &s), ReportStatus::short_report);
  r[0] = 8;
  EXPECT_EQ(dec.decode(r, 0, &s), ReportStatus::wrong_report_id);
  const auto bad_ip = small_report(9000, 900, 0);  // 90 deg: the thumb's IP reaches 80
  EXPECT_EQ(dec.decode(bad_ip, 0, &s), ReportStatus::out_of_range);
  const auto bad_mcp = small_report(0, 0, 0);  // -45 deg: at the limit, fine
  EXPECT_EQ(dec.decode(bad_mcp, 0, &s), ReportStatus::ok);
  const auto worse_mcp = small_report(0, 1400, 0);  // 95 deg > 90
  EXPECT_EQ(dec.decode(worse_mcp, 0, &s), ReportStatus::out_of_range);
  EXPECT_EQ(dec.count(ReportStatus::short_report), 2);
  EXPECT_EQ(dec.count(ReportStatus::wrong_report_id), 1);
  EXPECT_EQ(dec.count(ReportStatus::out_of_range), 2);
  EXPECT_EQ(dec.skipped(), 5);
  EXPECT_EQ(dec.count(ReportStatus::ok), 1);
  // A longer report than described is read (HID pads), not skipped.
  auto longer = small_report(0, 900, 0);
  longer.resize(64, 0xff);
  EXPECT_EQ(dec.decode(longer, 0, &s), ReportStatus::ok);
}

TEST(ReportDecoder, RandomAndTruncatedStreamsNeverCrash) {
  const DeviceDescription d = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  const Model m = hand_model();
  ReportDecoder dec(d, m);
  std::mt19937 rng(42);
  std::vector<std::uint8_t> buf(100);
  Sample s;
  int n = 0;
  for (int i = 0; i < 20000; ++i) {
    const size_t len = rng() % buf.size();
    for (size_t k = 0; k < len; ++k) buf[k] = static_cast<std::uint8_t>(rng());
    if (i % 2 == 0 && len > 0) buf[0] = 1;  // the right id, random body
    dec.decode(std::span(buf).first(len), 0, &s);
    ++n;
  }
  std::int64_t total = 0;
  for (int k = 0; k < kReportStatuses; ++k) total += dec.count(static_cast<ReportStatus>(k));
  EXPECT_EQ(total, n);
  EXPECT_GT(dec.count(ReportStatus::short_report), 0);
  EXPECT_GT(dec.count(ReportStatus::wrong_report_id), 0);
  EXPECT_GT(dec.count(ReportStatus::out_of_range), 0);
}

TEST(ReportDecoder, GloveFingertipsFollowTheChain) {
  const DeviceDescription d = load_device_description(AFFORD_SOURCE_DIR "/devices/glove.yaml");
  const Model m = hand_model();
  ReportDecoder dec(d, m);
  std::vector<std::uint8_t> r(64, 0);
  r[0] = 1;
  write_raw(&r[45], 4, false, 10000);  // x = 100 mm
  write_raw(&r[7], 2, false, 9000);    // index MCP (4th sensor, bytes 7-8) at 90 deg
  Sample s;
  ASSERT_EQ(dec.decode(r, 0, &s), ReportStatus::ok);
  EXPECT_NEAR(s.joint[1][2], 90 * kDeg, 1e-12);
  // Straight middle finger: base + all segments along +x, moved by the hand.
  EXPECT_NEAR(s.fingertip[2].x(), 0.1 + 0.082 + 0.045 + 0.028 + 0.021, 1e-12);
  // Index bent 90 deg at its MCP: the chain goes down -z from the base.
  EXPECT_NEAR(s.fingertip[1].x(), 0.1 + 0.080, 1e-12);
  EXPECT_NEAR(s.fingertip[1].z(), -(0.040 + 0.025 + 0.020), 1e-12);
}

TEST(ReportEncoder, ForcesToCountsClampedAndSaturated) {
  const DeviceDescription d = small_device();
  std::array<std::uint8_t, 8> out{};
  encode_forces(d, {12.345, 100.0, 0, 0, 0}, out);
  EXPECT_EQ(out[0], 9);
  EXPECT_EQ(read_raw(&out[1], 2, false, false), 1235);  // 12.345 N * 100, rounded
  EXPECT_EQ(out[3], 255);                               // 30 N saturation * 10 = 300 > 255: clamped
  encode_forces(d, {-5.0, std::nan(""), 0, 0, 0}, out);
  EXPECT_EQ(read_raw(&out[1], 2, false, false), 0);  // negative and NaN send 0
  EXPECT_EQ(out[3], 0);
  encode_forces(d, {25.0, 3.0, 0, 0, 0}, out);
  EXPECT_EQ(read_raw(&out[1], 2, false, false), 2000);  // saturates at 20 N
  EXPECT_EQ(out[3], 30);
  EXPECT_EQ(out[5] + out[6] + out[7], 0);
}

// A device sample whose every value is v.
Sample flat(double t, double v) {
  Sample s;
  s.t = t;
  s.hand.translation() = Eigen::Vector3d(v, 2 * v, 3 * v);
  for (int f = 0; f < kFingers; ++f) {
    s.fingertip[f] = Eigen::Vector3d::Constant(v + f);
    for (int j = 0; j < kJoints; ++j) s.joint[f][j] = v * (j + 1);
  }
  return s;
}

std::vector<Sample> hundred_hz(int n) {
  std::vector<Sample> out;
  for (int i = 0; i < n; ++i) out.push_back(flat(i * 0.01, i * 1.0));
  return out;
}

TEST(Resample, HoldAt1kHzFrom100Hz) {
  const std::vector<Sample> dev = hundred_hz(5);  // 0, 10, ... 40 ms
  SpanStream stream(dev);
  ResampledSource src(stream, Resample::hold);
  Sample s;
  for (int k = 0; k <= 40; ++k) {
    const double t = k * 0.001;
    ASSERT_TRUE(src.sample_at(t, &s)) << k;
    EXPECT_EQ(s.t, t);
    const int i = k / 10;
    EXPECT_EQ(s.joint[0][0], i * 1.0) << k;
    EXPECT_EQ(src.device_time(), i * 0.01) << k;
  }
  EXPECT_FALSE(src.sample_at(0.041, &s));  // past the last sample, the stream over
}

TEST(Resample, InterpolateAt1kHzFrom100Hz) {
  const std::vector<Sample> dev = hundred_hz(5);
  SpanStream stream(dev);
  ResampledSource src(stream, Resample::interpolate);
  Sample s;
  for (int k = 0; k <= 40; ++k) {
    const double t = k * 0.001;
    ASSERT_TRUE(src.sample_at(t, &s)) << k;
    EXPECT_EQ(s.t, t);
    const double v = k * 0.1;  // 1 per 10 ms
    EXPECT_NEAR(s.joint[2][1], 2 * v, 1e-12) << k;
    EXPECT_NEAR(s.hand.translation().z(), 3 * v, 1e-12) << k;
    EXPECT_NEAR(s.fingertip[4].y(), v + 4, 1e-12) << k;
    EXPECT_NEAR(src.device_time(), t, 1e-15) << k;
  }
}

TEST(Resample, InterpolateSlerpsTheHand) {
  std::vector<Sample> dev = {flat(0, 0), flat(0.01, 0)};
  dev[1].hand.linear() = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  SpanStream stream(dev);
  ResampledSource src(stream, Resample::interpolate);
  Sample s;
  ASSERT_TRUE(src.sample_at(0.005, &s));
  EXPECT_NEAR(Eigen::AngleAxisd(s.hand.linear()).angle(), std::numbers::pi / 4, 1e-12);
}

TEST(Resample, DelayAndBeforeTheFirstSample) {
  const std::vector<Sample> dev = {flat(0.5, 1), flat(0.51, 2)};
  SpanStream stream(dev);
  ResampledSource src(stream, Resample::interpolate, 0.01);
  Sample s;
  ASSERT_TRUE(src.sample_at(0.001, &s));  // before the first: the first
  EXPECT_EQ(s.joint[0][0], 1);
  ASSERT_TRUE(src.sample_at(0.515, &s));  // reads the device at 0.505
  EXPECT_NEAR(s.joint[0][0], 1.5, 1e-12);
}

TEST(Resample, EmptyStreamGivesNothing) {
  SpanStream stream({});
  ResampledSource src(stream, Resample::hold);
  Sample s;
  EXPECT_FALSE(src.sample_at(0, &s));
}

}  // namespace
}  // namespace afford
