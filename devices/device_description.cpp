#include "device_description.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "did_you_mean.h"
#include "validate.h"

namespace afford {
namespace {

constexpr long kMaxReport = 512;  // usb_device.h kMaxReportBytes
const char* const kAxes[3] = {"x", "y", "z"};
const char* const kRotAxes[3] = {"rx", "ry", "rz"};

// A whole number written in decimal or hex (0x..), within [lo, hi].
long read_integer(const Node& node, long lo, long hi, const std::string& what) {
  if (!node.is_scalar()) node.fail(what);
  const std::string& s = node.yaml().Scalar();
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 0);
  if (s.empty() || end == nullptr || *end != '\0') node.fail(what);
  if (v < lo || v > hi) node.fail(what);
  return v;
}

struct Encoding {
  int offset = 0, width = 1;
  bool big_endian = false, is_signed = false;
};

Encoding read_encoding(MapReader& m, int report_size) {
  Encoding e;
  const Node off = m.required("offset");
  e.offset = static_cast<int>(read_integer(off, 0, 1 << 16, "a byte offset (a whole number >= 0)"));
  const Node w = m.required("width");
  e.width = static_cast<int>(read_integer(w, 1, 4, "a width of 1, 2 or 4 bytes"));
  if (e.width == 3) w.fail("a width of 1, 2 or 4 bytes");
  if (std::optional<Node> en = m.optional("endian")) e.big_endian = read_choice(*en, {"little", "big"}) == "big";
  if (std::optional<Node> sg = m.optional("signed")) e.is_signed = read_bool(*sg);
  if (e.offset + e.width > report_size) {
    off.fail("bytes " + std::to_string(e.offset) + ".." + std::to_string(e.offset + e.width - 1) +
                 " within the report's " + std::to_string(report_size) + " bytes",
             "a field ending at byte " + std::to_string(e.offset + e.width - 1));
  }
  return e;
}

// Bytes [offset, offset+width) must not overlap the report id or another
// field; `owner` holds, per byte, the index+1 of the field using it.
void claim_bytes(std::vector<int>& owner, const std::vector<std::string>& names, const Encoding& e,
                 const Node& at, int index) {
  for (int b = e.offset; b < e.offset + e.width; ++b) {
    if (owner[b] != 0) {
      at.fail("bytes not used by another field",
              "byte " + std::to_string(b) + ", already used by " + names[owner[b] - 1]);
    }
    owner[b] = index + 1;
  }
}

Target read_target(const Node& node, const Dimension& dimension) {
  const std::string s = read_string(node);
  Target t;
  bool found = false;
  for (int f = 0; f < kFingers && !found; ++f) {
    for (int j = 0; j < kJoints && !found; ++j) {
      if (s == std::string(kFingerNames[f]) + "." + kJointNames[j]) t = {TargetKind::joint, f, j}, found = true;
    }
    for (int a = 0; a < 3 && !found; ++a) {
      if (s == std::string(kFingerNames[f]) + ".tip." + kAxes[a]) t = {TargetKind::tip_pos, f, a}, found = true;
    }
  }
  for (int a = 0; a < 3 && !found; ++a) {
    if (s == std::string("hand.") + kAxes[a]) t = {TargetKind::hand_pos, 0, a}, found = true;
    if (s == std::string("hand.") + kRotAxes[a]) t = {TargetKind::hand_rot, 0, a}, found = true;
  }
  if (s == "none") found = true;
  if (!found) {
    node.fail("a joint (thumb.distal, ...), a fingertip component (index.tip.x, ...), hand.x/y/z, hand.rx/ry/rz "
              "or none",
              "'" + s + "'" + did_you_mean(s, device_target_names()));
  }
  const bool wants_angle = t.kind == TargetKind::joint || t.kind == TargetKind::hand_rot;
  const bool wants_length = t.kind == TargetKind::hand_pos || t.kind == TargetKind::tip_pos;
  if ((wants_angle && !(dimension == dim::angle)) || (wants_length && !(dimension == dim::length))) {
    node.fail("a channel whose unit is " + describe_dimension(wants_angle ? dim::angle : dim::length) + " for '" +
                  s + "'",
              "a unit of dimension " + (dimension == dim::none ? std::string("none") : dimension.str()));
  }
  return t;
}

int read_finger(const Node& node) {
  const std::string s = read_string(node);
  for (int f = 0; f < kFingers; ++f) {
    if (s == kFingerNames[f]) return f;
  }
  node.fail("a finger (thumb, index, middle, ring, little)",
            "'" + s + "'" + did_you_mean(s, {kFingerNames.begin(), kFingerNames.end()}));
}

// The keys that say where a value sits in a report, shared by fields and
// actuators (read_encoding).
std::vector<KeySchema> encoding_keys() {
  using namespace schema;
  return {required_key("offset", integer(), "its first byte in the report"),
          required_key("width", integer(), "its width: 1, 2 or 4 bytes"),
          optional_key("endian", choice({"little", "big"}), "its byte order (default little)"),
          optional_key("signed", boolean(), "true for a two's complement value (default false)")};
}

const MapSchema& field_schema() {
  using namespace schema;
  static const MapSchema kField = [] {
    MapSchema m{"a field of the IN report: where it is and what it fills",
                {required_key("name", name(), "the field's name, unique in the report")}};
    for (KeySchema& k : encoding_keys()) m.keys.push_back(std::move(k));
    m.keys.push_back(optional_key("scale", number(), "the unit value of one count, not zero (default 1)"));
    m.keys.push_back(optional_key("value_offset", number(), "the value added after scaling (default 0)"));
    m.keys.push_back(optional_key("unit", text(), "the unit of the scaled value (deg, mm, ...)"));
    m.keys.push_back(optional_key("to", text(), "what it fills: thumb.distal, index.tip.x, hand.rx, ... or none"));
    return m;
  }();
  return kField;
}

const MapSchema& in_report_schema() {
  using namespace schema;
  static const MapSchema kIn{"the report the device sends",
                             {required_key("size", integer(), "its size in bytes, 1 to 512"),
                              optional_key("report_id", integer(), "its first byte, 0 to 255, if it has one"),
                              required_key("fields", sequence(mapping(field_schema()), 1), "its fields")}};
  return kIn;
}

const MapSchema& segments_schema() {
  using namespace schema;
  static const MapSchema kSegments = [] {
    MapSchema m{"the length of each segment of a finger"};
    for (const char* joint : kJointNames) {
      m.keys.push_back(required_key(joint, quantity(dim::length), std::string("the segment after the ") + joint +
                                                                       " joint"));
    }
    return m;
  }();
  return kSegments;
}

const MapSchema& chain_schema() {
  using namespace schema;
  static const MapSchema kChain{"a finger's kinematic chain",
                                {required_key("base", vector(dim::length), "the finger's base, in the hand frame"),
                                 required_key("segments", mapping(segments_schema()), "its segment lengths")}};
  return kChain;
}

const MapSchema& kinematics_schema() {
  using namespace schema;
  static const MapSchema kKinematics = [] {
    MapSchema m{"the fingers whose tips are computed from joint angles"};
    for (const char* finger : kFingerNames) {
      m.keys.push_back(optional_key(finger, mapping(chain_schema()), std::string("the chain of the ") + finger));
    }
    return m;
  }();
  return kKinematics;
}

const MapSchema& actuator_schema() {
  using namespace schema;
  static const MapSchema kActuator = [] {
    MapSchema m{"a force-feedback actuator of the OUT report",
                {required_key("finger", choice({kFingerNames.begin(), kFingerNames.end()}), "the finger it pushes")}};
    for (KeySchema& k : encoding_keys()) m.keys.push_back(std::move(k));
    m.keys.push_back(required_key("counts_per_newton", number(), "counts per newton, above 0"));
    m.keys.push_back(required_key("saturation", quantity(dim::force), "the largest force it exerts"));
    return m;
  }();
  return kActuator;
}

const MapSchema& out_report_schema() {
  using namespace schema;
  static const MapSchema kOut{"the report the device receives",
                              {required_key("size", integer(), "its size in bytes, 1 to 512"),
                               optional_key("report_id", integer(), "its first byte, 0 to 255, if it has one"),
                               required_key("actuators", sequence(mapping(actuator_schema()), 1), "its actuators")}};
  return kOut;
}

const MapSchema& usb_schema() {
  using namespace schema;
  static const MapSchema kUsb{
      "how the device is found and read",
      {required_key("vendor", integer(), "the USB vendor id, 0x0000 to 0xffff"),
       required_key("product", integer(), "the USB product id, 0x0000 to 0xffff"),
       optional_key("interface", integer(), "the interface number, 0 to 255 (default 0)"),
       required_key("in_endpoint", integer(), "the IN endpoint, 0x81 to 0x8f"),
       optional_key("out_endpoint", integer(), "the OUT endpoint, 0x01 to 0x0f, for force feedback"),
       optional_key("transfer", choice({"interrupt", "bulk"}), "the transfer type (default interrupt)")}};
  return kUsb;
}

void read_in_report(const Node& node, DeviceDescription& d) {
  MapReader m(node, "the IN report", in_report_schema());
  d.in_size = static_cast<int>(read_integer(m.required("size"), 1, kMaxReport, "a report size in bytes (1..512)"));
  std::vector<int> owner(static_cast<size_t>(d.in_size), 0);
  std::vector<std::string> names;
  if (std::optional<Node> id = m.optional("report_id")) {
    d.in_report_id = static_cast<int>(read_integer(*id, 0, 255, "a report id (0..255)"));
    names.push_back("the report id");
    owner[0] = 1;
  }
  const Node fields = m.required("fields");
  if (!fields.is_sequence() || fields.size() == 0) fields.fail("a sequence of fields");
  for (size_t i = 0; i < fields.size(); ++i) {
    const Node fn = fields[i];
    MapReader fm(fn, "a field", field_schema());
    Field f;
    f.loc = fn.loc();
    const Node name_node = fm.required("name");
    f.name = read_name(name_node);
    for (const Field& other : d.fields) {
      if (other.name == f.name) name_node.fail("a name not used by another field", "'" + f.name + "' again");
    }
    const Encoding e = read_encoding(fm, d.in_size);
    f.offset = e.offset, f.width = e.width, f.big_endian = e.big_endian, f.is_signed = e.is_signed;
    names.push_back("field '" + f.name + "'");
    claim_bytes(owner, names, e, fm.required("offset"), static_cast<int>(names.size()) - 1);
    if (std::optional<Node> s = fm.optional("scale")) {
      f.scale = read_number(*s);
      if (f.scale == 0) s->fail("a scale other than zero");
    }
    if (std::optional<Node> o = fm.optional("value_offset")) f.value_offset = read_number(*o);
    if (std::optional<Node> u = fm.optional("unit")) {
      std::string error;
      const std::optional<Quantity> q = parse_unit(read_string(*u), &error);
      if (!q) u->fail("a unit (deg, rad, mm, m, ...)", "'" + u->yaml().Scalar() + "' (" + error + ")");
      f.unit_si = q->si;
      f.dimension = q->dimension;
    }
    if (std::optional<Node> to = fm.optional("to")) {
      f.target = read_target(*to, f.dimension);
      for (const Field& other : d.fields) {
        const Target& o = other.target;
        if (o.kind != TargetKind::none && o.kind == f.target.kind && o.finger == f.target.finger &&
            o.index == f.target.index) {
          to->fail("a target no other field fills", "'" + to->yaml().Scalar() + "', filled by '" + other.name + "'");
        }
      }
    }
    d.fields.push_back(f);
  }
}

void read_kinematics(const Node& node, DeviceDescription& d) {
  MapReader m(node, "the kinematics", kinematics_schema());
  for (int f = 0; f < kFingers; ++f) {
    std::optional<Node> fn = m.optional(kFingerNames[f]);
    if (!fn) continue;
    MapReader fm(*fn, std::string("the chain of the ") + kFingerNames[f], chain_schema());
    DeviceFingerChain& c = d.kinematics[f];
    c.present = true;
    c.base = read_vector(fm.required("base"), dim::length);
    const Node segs = fm.required("segments");
    MapReader sm(segs, "the segments", segments_schema());
    for (int j = 0; j < kJoints; ++j) c.segment[j] = read_positive(sm.required(kJointNames[j]), dim::length);
  }
}

void read_out_report(const Node& node, DeviceDescription& d) {
  MapReader m(node, "the OUT report", out_report_schema());
  d.has_out = true;
  d.out_size = static_cast<int>(read_integer(m.required("size"), 1, kMaxReport, "a report size in bytes (1..512)"));
  std::vector<int> owner(static_cast<size_t>(d.out_size), 0);
  std::vector<std::string> names;
  if (std::optional<Node> id = m.optional("report_id")) {
    d.out_report_id = static_cast<int>(read_integer(*id, 0, 255, "a report id (0..255)"));
    names.push_back("the report id");
    owner[0] = 1;
  }
  const Node acts = m.required("actuators");
  if (!acts.is_sequence() || acts.size() == 0) acts.fail("a sequence of actuators");
  std::array<bool, kFingers> seen{};
  for (size_t i = 0; i < acts.size(); ++i) {
    MapReader am(acts[i], "an actuator", actuator_schema());
    Actuator a;
    const Node fnode = am.required("finger");
    a.finger = read_finger(fnode);
    if (seen[a.finger]) fnode.fail("one actuator per finger", "a second one for the " + std::string(kFingerNames[a.finger]));
    seen[a.finger] = true;
    const Encoding e = read_encoding(am, d.out_size);
    a.offset = e.offset, a.width = e.width, a.big_endian = e.big_endian, a.is_signed = e.is_signed;
    names.push_back(std::string("the ") + kFingerNames[a.finger] + "'s actuator");
    claim_bytes(owner, names, e, am.required("offset"), static_cast<int>(names.size()) - 1);
    a.counts_per_newton = read_number(am.required("counts_per_newton"));
    require_positive(am.required("counts_per_newton"), a.counts_per_newton);
    a.saturation = read_positive(am.required("saturation"), dim::force);
    d.actuators.push_back(a);
  }
}

}  // namespace

const MapSchema& device_schema() {
  using namespace schema;
  static const MapSchema kDevice{
      "a device description: a USB hand-tracking or force-feedback device (devices/README.md)",
      {required_key("device", name(), "the device's name"),
       optional_key("description", text(), "what the device is, in a sentence"),
       required_key("usb", mapping(usb_schema()), "how the device is found and read"),
       required_key("rate", number(), "its sample rate in Hz, above 0 and at most 100000"),
       optional_key("resample", choice({"hold", "interpolate"}), "how samples fill the frames (default hold)"),
       required_key("in_report", mapping(in_report_schema()), "the report the device sends"),
       optional_key("kinematics", mapping(kinematics_schema()), "fingertips from joint angles"),
       optional_key("out_report", mapping(out_report_schema()), "the report it receives, with out_endpoint")}};
  return kDevice;
}

std::vector<std::string> device_target_names() {
  std::vector<std::string> out{"none"};
  for (int f = 0; f < kFingers; ++f) {
    for (int j = 0; j < kJoints; ++j) out.push_back(std::string(kFingerNames[f]) + "." + kJointNames[j]);
    for (const char* a : kAxes) out.push_back(std::string(kFingerNames[f]) + ".tip." + a);
  }
  for (const char* a : kAxes) out.push_back(std::string("hand.") + a);
  for (const char* a : kRotAxes) out.push_back(std::string("hand.") + a);
  return out;
}

DeviceDescription read_device_description(const Node& root) {
  if (!root.is_map()) root.fail("a device description (a mapping whose first key is 'device')");
  const std::string first = root.yaml().begin()->first.as<std::string>();
  if (first != "device") {
    root.child(root.yaml().begin()->first)
        .fail("a device description (its first key 'device')", "'" + first + "'");
  }
  MapReader m(root, "a device description", device_schema());
  DeviceDescription d;
  d.file = root.loc().file;
  d.name = read_name(m.required("device"));
  if (std::optional<Node> desc = m.optional("description")) d.description = read_string(*desc);

  {
    MapReader u(m.required("usb"), "the usb section", usb_schema());
    d.vendor = static_cast<std::uint16_t>(read_integer(u.required("vendor"), 0, 0xffff, "a vendor id (0x0000..0xffff)"));
    d.product =
        static_cast<std::uint16_t>(read_integer(u.required("product"), 0, 0xffff, "a product id (0x0000..0xffff)"));
    if (std::optional<Node> i = u.optional("interface")) {
      d.interface = static_cast<int>(read_integer(*i, 0, 255, "an interface number (0..255)"));
    }
    d.in_endpoint =
        static_cast<std::uint8_t>(read_integer(u.required("in_endpoint"), 0x81, 0x8f, "an IN endpoint (0x81..0x8f)"));
    if (std::optional<Node> o = u.optional("out_endpoint")) {
      d.out_endpoint = static_cast<int>(read_integer(*o, 0x01, 0x0f, "an OUT endpoint (0x01..0x0f)"));
    }
    if (std::optional<Node> t = u.optional("transfer")) {
      d.transfer = read_choice(*t, {"interrupt", "bulk"}) == "bulk" ? Transfer::bulk : Transfer::interrupt;
    }
  }
  {
    const Node r = m.required("rate");
    d.rate = read_number(r);
    if (!(d.rate > 0 && d.rate <= 100000)) r.fail("a sample rate in Hz, above 0 and at most 100000");
  }
  if (std::optional<Node> r = m.optional("resample")) {
    d.resample = read_choice(*r, {"hold", "interpolate"}) == "interpolate" ? Resample::interpolate : Resample::hold;
  }
  read_in_report(m.required("in_report"), d);
  if (std::optional<Node> k = m.optional("kinematics")) read_kinematics(*k, d);
  if (std::optional<Node> o = m.optional("out_report")) {
    if (d.out_endpoint < 0) o->fail("an out_report only with usb: out_endpoint", "no out_endpoint");
    read_out_report(*o, d);
  }
  for (const Field& f : d.fields) {
    switch (f.target.kind) {
      case TargetKind::joint: d.joint_mapped[f.target.finger][f.target.index] = true; break;
      case TargetKind::hand_pos: d.hand_pos_mapped = true; break;
      case TargetKind::hand_rot: d.hand_rot_mapped = true; break;
      case TargetKind::tip_pos: d.tip_mapped[f.target.finger] = true; break;
      case TargetKind::none: break;
    }
  }
  return d;
}

DeviceDescription load_device_description(const std::string& path) {
  return read_device_description(load_yaml_file(path));
}

void add_device_file_kind() {
  add_file_kind("device", [](const Node& root) { return "device " + read_device_description(root).name; });
}

}  // namespace afford
