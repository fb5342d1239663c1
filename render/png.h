// A minimal PNG writer and reader, by hand (no libpng): 8-bit RGB, no
// interlace, filter 0, the image data in zlib "stored" (uncompressed)
// deflate blocks with their Adler-32, every chunk with its CRC-32. The
// reader reads what the writer writes (and any PNG of that form); anything
// else is an error.
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

// Files; throw PngError (with the path) when they cannot be written or read.
void write_png(const std::string& path, const Image& img);
Image read_png(const std::string& path);

std::uint32_t crc32(const std::uint8_t* data, size_t n, std::uint32_t crc = 0);
std::uint32_t adler32(const std::uint8_t* data, size_t n, std::uint32_t adler = 1);

}  // namespace afford::render
