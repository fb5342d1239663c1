// Device descriptions: what the bytes of a USB device's reports mean, as
// data (devices/*.yaml, devices/README.md). Read and validated once
// (file:line:col on every mistake), then used by the report decoder and
// encoder (report_decoder.h) and the libusb backend (usb_device.h).
//
//   device: cyberglove-22            name (first key: the kind of file)
//   description: ...                 one line
//   usb: {vendor: 0x1234, product: 0x5678, interface: 0,
//         in_endpoint: 0x81, out_endpoint: 0x02, transfer: interrupt}
//   rate: 100                        the device's sample rate, Hz
//   resample: hold | interpolate     how a frame between two samples is filled
//   in_report:
//     size: 64                       bytes
//     report_id: 1                   optional: byte 0 must be this
//     fields:
//       - {name: thumb_ip, offset: 1, width: 2, endian: little, signed: true,
//          scale: 0.01, value_offset: 0, unit: deg, to: thumb.distal}
//   kinematics: {...}                optional: fingertips from joint angles
//   out_report:                      optional: force feedback
//     size: 16
//     report_id: 2
//     actuators:
//       - {finger: thumb, offset: 1, width: 2, endian: little, signed: false,
//          counts_per_newton: 100, saturation: 20 N}
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "errors.h"
#include "spec.h"
#include "units.h"
#include "yaml_reader.h"

namespace afford {

enum class Transfer { interrupt, bulk };
enum class Resample { hold, interpolate };

// Where a channel's value goes in the agent's Sample.
enum class TargetKind {
  none,       // read (and range-checked by nothing), not used: e.g. abduction sensors
  joint,      // sample.joint[finger][index], rad
  hand_pos,   // sample.hand translation component `index` (x, y, z), m, world
  hand_rot,   // hand rotation angle about x, y or z (`index`), rad: R = Rz*Ry*Rx
  tip_pos,    // fingertip `finger` component `index`, m, in the hand frame
};

struct Target {
  TargetKind kind = TargetKind::none;
  int finger = 0;  // 0..4 for joint and tip_pos
  int index = 0;   // joint (distal, proximal, metacarpal) or axis (x, y, z)
};

// One integer in a report. value (SI) = (raw * scale + value_offset) * unit.
struct Field {
  std::string name;
  int offset = 0;            // bytes from the report's start
  int width = 1;             // bytes: 1, 2 or 4
  bool big_endian = false;
  bool is_signed = false;
  double scale = 1;          // unit per count
  double value_offset = 0;   // unit, added after scaling
  double unit_si = 1;        // SI value of one `unit`
  Dimension dimension;       // of `unit`
  Target target;
  SourceLoc loc;             // of the field's entry
};

// One force actuator of the OUT report: counts = clamp(F, 0, saturation) *
// counts_per_newton, clamped again to the width's range.
struct Actuator {
  int finger = 0;
  int offset = 0;
  int width = 1;
  bool big_endian = false;
  bool is_signed = false;
  double counts_per_newton = 1;  // 1/N
  double saturation = 0;         // N, the largest force sent
};

// Planar finger chains: a finger starts at `base` (hand frame) pointing
// along +x; its metacarpal, proximal and distal segments (in that order)
// bend about the hand's y axis toward -z (the palm) by the joint angles.
struct DeviceFingerChain {
  bool present = false;
  Eigen::Vector3d base = Eigen::Vector3d::Zero();  // m, hand frame
  std::array<double, kJoints> segment{};           // m, indexed like joints: distal, proximal, metacarpal
};

struct DeviceDescription {
  std::string file;
  std::string name;
  std::string description;

  // usb
  std::uint16_t vendor = 0, product = 0;
  int interface = 0;
  std::uint8_t in_endpoint = 0x81;
  int out_endpoint = -1;  // -1: none (force via the IN endpoint's device is not possible)
  Transfer transfer = Transfer::interrupt;

  double rate = 100;  // Hz
  Resample resample = Resample::hold;

  int in_size = 0;       // bytes
  int in_report_id = -1; // -1: none; else byte 0
  std::vector<Field> fields;

  std::array<DeviceFingerChain, kFingers> kinematics{};

  bool has_out = false;
  int out_size = 0;
  int out_report_id = -1;
  std::vector<Actuator> actuators;

  // Which Sample parts the fields fill (computed).
  std::array<std::array<bool, kJoints>, kFingers> joint_mapped{};
  bool hand_pos_mapped = false, hand_rot_mapped = false;
  std::array<bool, kFingers> tip_mapped{};
};

// Reads a device description; every mistake is a DataError at file:line:col.
DeviceDescription load_device_description(const std::string& path);
DeviceDescription read_device_description(const Node& root);
const MapSchema& device_schema();  // the keys of a device description

// Lets validate_file (afford check, afford.check) read device descriptions.
void add_device_file_kind();

// Every target name a field's `to:` may give ("thumb.distal", "hand.x", ...).
std::vector<std::string> device_target_names();

}  // namespace afford
