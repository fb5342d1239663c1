// Fuzzes the measured-trace reader (gap/trace_table.h): the first byte
// picks the layout (rig, separator, lines to skip before the header and
// after the table, the trace format's columns or the macadamia machine's
// of measurements/macadamia-plates.yaml), the rest is the file's text. A
// DataError is the expected answer; anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "errors.h"
#include "trace_table.h"

namespace {

afford::TableFormat format_of(std::uint8_t b) {
  const afford::Rig rig = (b & 1) != 0 ? afford::Rig::plates : afford::Rig::lever;
  afford::TableFormat f = afford::default_format(rig);
  static constexpr char kSeparators[] = {',', '\t', ' ', ','};
  f.separator = kSeparators[(b >> 1) & 3];
  f.skip = (b >> 3) & 3;
  f.footer = (b >> 5) & 1;
  if ((b & 0x80) != 0 && rig == afford::Rig::plates) {  // the machine's own layout
    f.skip = 9;
    f.footer = 37;
    f.separator = '\t';
    f.column[static_cast<size_t>(afford::Signal::t)] = "Time(s)";
    f.column[static_cast<size_t>(afford::Signal::displacement)] = "Defor(mm)";
    f.scale[static_cast<size_t>(afford::Signal::displacement)] = 1e-3;
    f.column[static_cast<size_t>(afford::Signal::force)] = "Load(kN)";
    f.scale[static_cast<size_t>(afford::Signal::force)] = 1e3;
  }
  f.loc = afford::SourceLoc{"fuzz.yaml", 1, 1};
  return f;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const afford::TableFormat format = format_of(data[0]);
  const afford::Rig rig = (data[0] & 1) != 0 ? afford::Rig::plates : afford::Rig::lever;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    afford::parse_trace(text, "fuzz.txt", format, rig, 2);
  } catch (const afford::DataError&) {
  }
  return 0;
}
