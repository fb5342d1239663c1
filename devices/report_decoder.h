// Report bytes to agent samples, and haptic forces to report bytes, as a
// device description (device_description.h) says. Allocation-free per
// report: every buffer is sized when the decoder is built.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "device_description.h"
#include "model.h"
#include "sample.h"

namespace afford {

// Why a report was skipped. Each is counted; none is an error.
enum class ReportStatus {
  ok,
  short_report,     // fewer bytes than the IN report's size
  wrong_report_id,  // byte 0 is not the description's report id
  out_of_range,     // a joint angle outside the agent's range, or a value not finite
};
inline constexpr int kReportStatuses = 4;
const char* report_status_name(ReportStatus s);  // "short", "wrong report id", ...

class ReportDecoder {
 public:
  // Keeps references: both must outlive the decoder. `model` gives the
  // agent's joint ranges (model.has_agent); without an agent no range is
  // checked.
  ReportDecoder(const DeviceDescription& device, const Model& model);

  // Decodes one report received at time t (s) into *out (its t is set to
  // t). Returns ok, or why it was skipped (then *out is untouched); counts
  // either way. Never allocates; any bytes are safe.
  ReportStatus decode(std::span<const std::uint8_t> report, double t, Sample* out);

  // The channel values of the last decoded report, SI, one per field in
  // the description's order.
  std::span<const double> channels() const { return channels_; }

  std::int64_t count(ReportStatus s) const { return counts_[static_cast<int>(s)]; }
  std::int64_t skipped() const;  // every status but ok

 private:
  const DeviceDescription& device_;
  const Model& model_;
  std::vector<double> channels_;
  std::array<std::int64_t, kReportStatuses> counts_{};
};

// Raw integer at `offset` (width 1, 2 or 4 bytes, endianness, sign).
std::int64_t read_raw(const std::uint8_t* bytes, int width, bool big_endian, bool is_signed);
void write_raw(std::uint8_t* bytes, int width, bool big_endian, std::int64_t value);

// Fills `report` (device.out_size bytes) with the forces (N, per finger,
// thumb first): the report id, then each actuator's counts, the force
// clamped to [0, saturation] and the counts to the width's range. Bytes no
// actuator uses are zero. No allocation.
void encode_forces(const DeviceDescription& device, const std::array<double, kFingers>& force_n,
                   std::span<std::uint8_t> report);

}  // namespace afford
