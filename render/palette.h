// The colours and the number text that the charts, the plots and the
// frame's bars share, so that every picture afford draws reads alike.
#pragma once

#include <cstdio>
#include <string>

#include "image.h"

namespace afford::render {

inline constexpr Rgb kInk{40, 44, 52};         // text and lines
inline constexpr Rgb kGrid{225, 228, 234};     // a chart's grid
inline constexpr Rgb kAxisInk{120, 126, 138};  // axes and ticks
inline constexpr Rgb kPanel{252, 252, 253};    // behind a chart
inline constexpr Rgb kWhite{255, 255, 255};

// printf's text of one number: `format` holds exactly one double's conversion.
inline std::string printf_number(const char* format, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

}  // namespace afford::render
