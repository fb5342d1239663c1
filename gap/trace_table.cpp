#include "trace_table.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string_view>

#include "counted_step.h"
#include "files.h"
#include "units.h"

namespace afford {
namespace {

// The signals each rig needs.
bool needed(Signal s, Rig rig) {
  if (s == Signal::t) return true;
  if (rig == Rig::lever) return s == Signal::angle || s == Signal::effort_force;
  return s == Signal::displacement || s == Signal::force;
}

// The fields of one line, with the 1-based column where each starts.
struct Field {
  std::string_view text;
  int column;
};

std::vector<Field> split(std::string_view line, char separator) {
  std::vector<Field> fields;
  auto trimmed = [](std::string_view s, int column) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) {
      s.remove_prefix(1);
      ++column;
    }
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return Field{s, column};
  };
  if (separator == ' ') {
    size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      if (i == line.size()) break;
      const size_t start = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
      fields.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return fields;
  }
  size_t start = 0;
  for (;;) {
    const size_t end = line.find(separator, start);
    fields.push_back(trimmed(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start),
                             static_cast<int>(start) + 1));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return fields;
}

std::string shown(std::string_view s) {
  constexpr size_t kShown = 40;
  if (s.size() <= kShown) return "'" + std::string(s) + "'";
  return "'" + std::string(s.substr(0, kShown)) + "...' (" + std::to_string(s.size()) + " characters)";
}

// How a column's numbers were printed: for each pair (the exponent of a
// cell's last printed digit, of its leading digit), how many cells. Zero
// cells count for nothing: a zero is most likely exact.
using PrintedDigits = std::map<std::pair<int, int>, size_t>;

void note_printed(std::string_view text, double value, PrintedDigits* digits) {
  if (value == 0 || !std::isfinite(value)) return;
  const size_t e = text.find_first_of("eE");
  const std::string_view mantissa = text.substr(0, e);
  const size_t dot = mantissa.find('.');
  const long decimals = dot == std::string_view::npos ? 0 : static_cast<long>(mantissa.size() - dot - 1);
  long exponent = 0;  // clamped: "1e999999999999" is read elsewhere as too large
  if (e != std::string_view::npos) {
    exponent = std::clamp(std::strtol(std::string(text.substr(e + 1)).c_str(), nullptr, 10), -400L, 400L);
  }
  const auto last = static_cast<int>(std::clamp(exponent - decimals, -800L, 800L));
  const int leading = static_cast<int>(std::floor(std::log10(std::abs(value))));
  ++(*digits)[{last, leading}];  // a handful of keys: a column's cells share their digits
}

// The deviation of the rounding the printed digits make: each cell's last
// digit's step over sqrt(12), RMS. Where a writer dropped trailing zeros
// ("%g" prints 0.0008 for 0.000800000), a cell's step is that of the most
// significant digits any cell of the column shows.
double printed_resolution(const PrintedDigits& digits) {
  int significant = 0;
  for (const auto& [key, count] : digits) significant = std::max(significant, key.second - key.first + 1);
  double squares = 0;
  size_t cells = 0;
  for (const auto& [key, count] : digits) {
    const double step = std::pow(10.0, std::min(key.first, key.second - significant + 1));
    squares += step * step * static_cast<double>(count);
    cells += count;
  }
  return cells > 0 ? std::sqrt(squares / static_cast<double>(cells) / 12) : 0.0;
}

}  // namespace

const char* signal_name(Signal s) {
  static const char* const kNames[] = {"t", "angle", "effort_force", "actee_force", "broken", "displacement", "force"};
  return kNames[static_cast<int>(s)];
}

TableFormat default_format(Rig rig) {
  TableFormat f;
  for (int i = 0; i < kSignals; ++i) {
    const auto s = static_cast<Signal>(i);
    const bool lever_signal = s == Signal::angle || s == Signal::effort_force || s == Signal::actee_force;
    const bool plates_signal = s == Signal::displacement || s == Signal::force;
    if (s == Signal::t || s == Signal::broken || (rig == Rig::lever ? lever_signal : plates_signal)) {
      f.column[static_cast<size_t>(i)] = signal_name(s);
      f.scale[static_cast<size_t>(i)] = 1.0;
    }
  }
  return f;
}

Trace read_trace(const std::string& path, const TableFormat& format, Rig rig, size_t min_rows) {
  // A missing trace is the measurement's mistake, named where it names the file.
  if (!std::filesystem::exists(path)) fail(format.loc, "a readable trace file '" + path + "'", "none");
  return parse_trace(read_regular_file(path, static_cast<size_t>(kMaxTraceBytes)), path, format, rig, min_rows);
}

Trace parse_trace(const std::string& text, const std::string& path, const TableFormat& format, Rig rig,
                  size_t min_rows) {
  std::istringstream in(text);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) {
    if (lines.size() > kMaxTraceRows) fail(SourceLoc{path, static_cast<int>(lines.size()), 1}, "at most " + std::to_string(kMaxTraceRows) + " rows", "more");
    lines.push_back(std::move(l));
  }
  auto skip = static_cast<size_t>(format.skip);
  const auto footer = static_cast<size_t>(format.footer);
  // Comment lines before the header ('#', as afford's own trace.csv starts
  // with its units) are skipped too.
  while (skip < lines.size() && lines[skip].starts_with('#')) ++skip;
  if (skip + footer >= lines.size()) {
    fail(SourceLoc{path, static_cast<int>(lines.size()), 1},
         std::to_string(skip) + " lines, a header row and " + std::to_string(footer) + " lines after the table",
         std::to_string(lines.size()) + " lines");
  }
  const size_t table_end = lines.size() - footer;

  // The header row: which column holds each signal.
  const int header_row = static_cast<int>(skip) + 1;
  const std::vector<Field> header = split(lines[skip], format.separator);
  std::array<int, kSignals> index;
  index.fill(-1);
  for (int s = 0; s < kSignals; ++s) {
    const std::string& name = format.column[static_cast<size_t>(s)];
    if (name.empty()) continue;
    for (size_t c = 0; c < header.size(); ++c) {
      if (header[c].text == name) index[static_cast<size_t>(s)] = static_cast<int>(c);
    }
    if (index[static_cast<size_t>(s)] < 0 && needed(static_cast<Signal>(s), rig)) {
      std::string found;
      for (size_t c = 0; c < header.size(); ++c) found += (c ? ", " : "") + std::string(header[c].text);
      fail(SourceLoc{path, header_row, 1}, "a column '" + name + "' (" + signal_name(static_cast<Signal>(s)) + ")",
           "the columns " + shown(found));
    }
  }

  Trace trace;
  trace.file = path;
  std::array<PrintedDigits, kSignals> digits;
  int last_row = header_row;
  for (size_t l = skip + 1; l < table_end; ++l) {
    const std::string& line = lines[l];
    const int row = static_cast<int>(l) + 1;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank lines end nothing
    last_row = row;
    const std::vector<Field> fields = split(line, format.separator);
    for (int s = 0; s < kSignals; ++s) {
      const int c = index[static_cast<size_t>(s)];
      if (c < 0) continue;
      if (static_cast<size_t>(c) >= fields.size()) {
        fail(SourceLoc{path, row, static_cast<int>(line.size()) + 1},
             std::to_string(header.size()) + " columns, '" + format.column[static_cast<size_t>(s)] + "' among them",
             std::to_string(fields.size()));
      }
      const Field& f = fields[static_cast<size_t>(c)];
      const std::optional<double> v = parse_number(f.text);
      if (!v) fail(SourceLoc{path, row, f.column}, "a number", shown(f.text));
      trace[static_cast<Signal>(s)].push_back(*v * format.scale[static_cast<size_t>(s)]);
      note_printed(f.text, *v, &digits[static_cast<size_t>(s)]);
    }
    const std::vector<double>& t = trace[Signal::t];
    if (t.size() >= 2 && !(t.back() > t[t.size() - 2])) {
      const Field& f = fields[static_cast<size_t>(index[0])];
      fail(SourceLoc{path, row, f.column}, "a time after " + format_quantity(t[t.size() - 2], dim::time),
           format_quantity(t.back(), dim::time));
    }
  }
  for (size_t s = 0; s < kSignals; ++s) {
    trace.resolution[s] = printed_resolution(digits[s]) * format.scale[s];
    // A measured signal counted in steps coarser than its digits (an
    // encoder's counts, a converter's bits) rounds to those steps: a slow
    // motion read by an encoder is a staircase, its noise the rounding's.
    const auto signal = static_cast<Signal>(s);
    if (signal == Signal::t || signal == Signal::broken) continue;
    const double step = counted_step(trace.column[s], trace.resolution[s] * std::sqrt(12.0));
    trace.resolution[s] = std::max(trace.resolution[s], step / std::sqrt(12.0));
  }
  if (trace.size() < min_rows) {
    fail(SourceLoc{path, last_row, 1},
         "a trace of at least " + std::to_string(min_rows) + " rows (to fit on part and judge on the rest)",
         std::to_string(trace.size()));
  }
  return trace;
}

}  // namespace afford
