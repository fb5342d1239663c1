// Reading a measured trace: a table of numbers with a header row, in the
// trace format of the docs (CSV, SI units, columns by name) or in another
// layout that a measurement's `format:` block describes (lines to skip, the
// separator, which column is which signal and in what unit).
#pragma once

#include <array>
#include <string>

#include "errors.h"
#include "measurement.h"

namespace afford {

struct TableFormat {
  int skip = 0;                                // lines before the header row
  int footer = 0;                              // lines after the table (a machine's settings)
  char separator = ',';                        // ',', '\t', or ' ' for runs of blanks
  std::array<std::string, kSignals> column{};  // header name of each signal's column; empty: absent
  std::array<double, kSignals> scale{};        // SI per unit of the column
  SourceLoc loc;                               // the format block, or the measurement's trace key
};

// The trace format: `t, angle, effort_force, actee_force` (lever) or
// `t, displacement, force` (plates), SI, and `broken` where present.
TableFormat default_format(Rig rig);

// Reads `path` by `format`; unknown columns are ignored. A cell that is not
// a finite number is an error naming the file, its line and column; so are
// a time that does not increase, a missing column the rig needs (named at
// format.loc), and fewer than `min_rows` rows.
// Only a regular file of at most kMaxTraceBytes is read.
Trace read_trace(const std::string& path, const TableFormat& format, Rig rig, size_t min_rows);
// The same from the file's text, `path` naming it in errors.
Trace parse_trace(const std::string& text, const std::string& path, const TableFormat& format, Rig rig,
                  size_t min_rows);

// The largest trace file read, bytes, and the most rows.
inline constexpr long kMaxTraceBytes = 256L << 20;
inline constexpr size_t kMaxTraceRows = 20'000'000;

}  // namespace afford
