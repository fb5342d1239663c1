#include "report_decoder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace afford {

const char* report_status_name(ReportStatus s) {
  switch (s) {
    case ReportStatus::ok: return "ok";
    case ReportStatus::short_report: return "short";
    case ReportStatus::wrong_report_id: return "wrong report id";
    case ReportStatus::out_of_range: return "out of range";
  }
  return "?";
}

std::int64_t read_raw(const std::uint8_t* bytes, int width, bool big_endian, bool is_signed) {
  std::uint64_t u = 0;
  for (int i = 0; i < width; ++i) {
    const std::uint64_t b = bytes[big_endian ? i : width - 1 - i];
    u = (u << 8) | b;
  }
  if (is_signed && width < 8 && (u >> (8 * width - 1)) != 0) {
    u |= ~std::uint64_t{0} << (8 * width);  // sign-extend
  }
  return static_cast<std::int64_t>(u);
}

void write_raw(std::uint8_t* bytes, int width, bool big_endian, std::int64_t value) {
  auto u = static_cast<std::uint64_t>(value);
  for (int i = 0; i < width; ++i) {
    bytes[big_endian ? width - 1 - i : i] = static_cast<std::uint8_t>(u & 0xff);
    u >>= 8;
  }
}

ReportDecoder::ReportDecoder(const DeviceDescription& device, const Model& model)
    : device_(device), model_(model), channels_(device.fields.size(), 0.0) {}

std::int64_t ReportDecoder::skipped() const {
  std::int64_t n = 0;
  for (int i = 1; i < kReportStatuses; ++i) n += counts_[i];
  return n;
}

ReportStatus ReportDecoder::decode(std::span<const std::uint8_t> report, double t, Sample* out) {
  auto done = [this](ReportStatus s) {
    ++counts_[static_cast<int>(s)];
    return s;
  };
  if (report.size() < static_cast<size_t>(device_.in_size)) return done(ReportStatus::short_report);
  if (device_.in_report_id >= 0 && report[0] != device_.in_report_id) return done(ReportStatus::wrong_report_id);

  // Channels, then the sample's parts; nothing is written to *out until
  // every value is known to be good.
  Eigen::Vector3d hand_pos = Eigen::Vector3d::Zero(), hand_rot = Eigen::Vector3d::Zero();
  FingerPoints tip = finger_origins();  // m, hand frame; a finger the device does not sense stays at the wrist
  std::array<std::array<double, kJoints>, kFingers> joint{};
  for (size_t i = 0; i < device_.fields.size(); ++i) {
    const Field& f = device_.fields[i];
    const auto raw = read_raw(report.data() + f.offset, f.width, f.big_endian, f.is_signed);
    const double v = (static_cast<double>(raw) * f.scale + f.value_offset) * f.unit_si;
    if (!std::isfinite(v)) return done(ReportStatus::out_of_range);
    channels_[i] = v;
    switch (f.target.kind) {
      case TargetKind::joint: joint[f.target.finger][f.target.index] = v; break;
      case TargetKind::hand_pos: hand_pos[f.target.index] = v; break;
      case TargetKind::hand_rot: hand_rot[f.target.index] = v; break;
      case TargetKind::tip_pos: tip[f.target.finger][f.target.index] = v; break;
      case TargetKind::none: break;
    }
  }
  if (model_.has_agent) {
    for (int fi = 0; fi < kFingers; ++fi) {
      for (int j = 0; j < kJoints; ++j) {
        const double lo = model_.joint_min[fi][j], hi = model_.joint_max[fi][j];
        if (device_.joint_mapped[fi][j]) {
          if (joint[fi][j] < lo || joint[fi][j] > hi) return done(ReportStatus::out_of_range);
        } else {
          joint[fi][j] = std::clamp(0.0, lo, hi);  // a joint the device does not sense: neutral
        }
      }
    }
  }
  out->t = t;
  out->hand = Eigen::Isometry3d::Identity();
  out->hand.translation() = hand_pos;
  out->hand.linear() = (Eigen::AngleAxisd(hand_rot.z(), Eigen::Vector3d::UnitZ()) *
                        Eigen::AngleAxisd(hand_rot.y(), Eigen::Vector3d::UnitY()) *
                        Eigen::AngleAxisd(hand_rot.x(), Eigen::Vector3d::UnitX()))
                           .toRotationMatrix();
  for (int fi = 0; fi < kFingers; ++fi) {
    Eigen::Vector3d p = tip[fi];
    const DeviceFingerChain& c = device_.kinematics[fi];
    if (!device_.tip_mapped[fi] && c.present) {
      // Planar chain from the base: metacarpal, proximal, distal segments,
      // each bent by the sum of the flexions so far about the hand's y axis
      // (positive flexion toward -z, the palm).
      p = c.base;
      double bend = 0;
      for (int j = kJoints - 1; j >= 0; --j) {  // metacarpal (2), proximal (1), distal (0)
        bend += joint[fi][j];
        p += c.segment[j] * Eigen::Vector3d(std::cos(bend), 0, -std::sin(bend));
      }
    }
    out->fingertip[fi] = out->hand * p;
  }
  out->joint = joint;
  return done(ReportStatus::ok);
}

void encode_forces(const DeviceDescription& device, const std::array<double, kFingers>& force_n,
                   std::span<std::uint8_t> report) {
  std::fill(report.begin(), report.end(), std::uint8_t{0});
  if (report.size() < static_cast<size_t>(device.out_size)) return;
  if (device.out_report_id >= 0) report[0] = static_cast<std::uint8_t>(device.out_report_id);
  for (const Actuator& a : device.actuators) {
    double f = force_n[a.finger];
    if (!std::isfinite(f)) f = 0;
    f = std::clamp(f, 0.0, a.saturation);
    const int bits = 8 * a.width - (a.is_signed ? 1 : 0);
    const double max_count = std::ldexp(1.0, bits) - 1;
    const double counts = std::clamp(std::round(f * a.counts_per_newton), 0.0, max_count);
    write_raw(report.data() + a.offset, a.width, a.big_endian, static_cast<std::int64_t>(counts));
  }
}

}  // namespace afford
