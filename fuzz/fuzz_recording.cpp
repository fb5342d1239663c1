// Fuzzes the recording reader (devices/recording_source.h): the bytes are
// a recording file. Every record carries a CRC-32, which random mutation
// almost never keeps right; so when the first byte is odd the rest is
// taken as records whose checksums the fuzzer makes good first, to reach
// the parsing behind them. A std::runtime_error (DataError included) is
// the expected answer to a file that is not a recording; anything else is
// a bug.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "recording.h"
#include "recording_source.h"

namespace {

// Rewrites the crc of every whole record after the magic and version.
void fix_checksums(std::string& bytes) {
  auto* p = reinterpret_cast<unsigned char*>(bytes.data());
  size_t at = afford::kRecordingMagic.size() + 4;
  while (at + afford::kRecordOverhead <= bytes.size()) {
    const size_t payload = afford::get_u32(p + at);
    if (payload > bytes.size() - at - afford::kRecordOverhead) return;
    const size_t crc_at = at + 4 + 1 + payload;
    afford::put_u32(p + crc_at, afford::crc32(p + at, crc_at - at));
    at = crc_at + 4;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  if ((data[0] & 1) != 0) fix_checksums(bytes);
  try {
    const afford::Recording rec = afford::parse_recording(bytes, "fuzz.afrec");
    (void)rec.summary();
    afford::RecordingSource source(rec);
    afford::Sample s;
    for (double t = 0; source.sample_at(t, &s) && t < 1.0; t += rec.timestep) {
    }
  } catch (const std::runtime_error&) {
  }
  return 0;
}
