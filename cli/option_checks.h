// Checks of option values, attached to the declarations (CLI11 validators):
// a bad value is a usage error (exit 2) "--opt: expected ..., found '...'".
#pragma once

#include <CLI/CLI.hpp>

namespace afford::cli {

// Type names the bash completion reads: a value of kind kFile completes to
// file names, kDir to directories; any other kind completes to nothing.
inline constexpr const char* kFile = "FILE";
inline constexpr const char* kDir = "DIR";

// A whole number from 1 up.
CLI::Validator count_above_zero();

// A number of seconds above 0 (and below 1e9).
CLI::Validator seconds_above_zero();

// A number of frames per second in (0, 1000].
CLI::Validator frames_per_second();

// WxH between 64x48 and 3840x2160.
CLI::Validator picture_size();

// Reads "WxH" (already checked by picture_size) into width and height.
void read_size(const std::string& text, int* width, int* height);

}  // namespace afford::cli
