// PNG writer and reader. The writer: 8-bit RGB, no interlace, filter 0 on
// every row, deflated by libdeflate at level 1 (fast, and about 7 times
// smaller than stored blocks for our frames). The reader reads ordinary
// PNGs through zlib: bit depth 8, grey, RGB, palette, grey+alpha or RGBA
// (alpha is dropped), any of the five row filters; interlaced or 16-bit
// files are errors. CRC-32 is zlib's, Adler-32 zlib's and libdeflate's.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "image.h"

namespace afford::render {

struct PngError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<std::uint8_t> encode_png(const Image& img);
Image decode_png(const std::vector<std::uint8_t>& bytes);  // throws PngError

// Files: write_png throws WriteError (engine/base/files.h: the path and the
// reason) when the file cannot be written to the last byte; read_png throws
// PngError (with the path) when it cannot be read.
void write_png(const std::string& path, const Image& img);
Image read_png(const std::string& path);

}  // namespace afford::render
