#include "png.h"

#include <libdeflate.h>
#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "files.h"

namespace afford::render {
namespace {

constexpr std::uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
// libdeflate's level 1: on a 640x480 frame 2.3 ms against zlib's 4.2 ms at
// its level 1, and 10 % smaller (README, Dependencies).
constexpr int kLevel = 1;

// One compressor a thread, kept: it holds some 100 KB of tables that each
// frame would otherwise allocate and fault in again.
libdeflate_compressor& compressor() {
  struct Free {
    void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
  };
  thread_local const std::unique_ptr<libdeflate_compressor, Free> c(libdeflate_alloc_compressor(kLevel));
  if (!c) throw PngError("libdeflate could not start compressing (out of memory)");
  return *c;
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<std::uint8_t>(v >> s));
}

std::uint32_t get32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

std::uint32_t crc(const std::uint8_t* data, size_t n) {
  return static_cast<std::uint32_t>(::crc32_z(::crc32_z(0, nullptr, 0), data, n));
}

void chunk(std::vector<std::uint8_t>& out, const char type[4], const std::uint8_t* data, size_t n) {
  put32(out, static_cast<std::uint32_t>(n));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + n);
  put32(out, crc(out.data() + start, out.size() - start));
}

// Inflates a whole zlib stream whose size is known (the scanlines).
std::vector<std::uint8_t> inflate_all(const std::vector<std::uint8_t>& z, size_t expected) {
  std::vector<std::uint8_t> raw(expected);
  uLongf n = static_cast<uLongf>(expected);
  const int rc = ::uncompress(raw.data(), &n, z.data(), static_cast<uLong>(z.size()));
  if (rc == Z_BUF_ERROR) throw PngError("more image data than the size says");
  if (rc != Z_OK) throw PngError("bad zlib data in IDAT");
  if (n != expected) throw PngError("wrong amount of image data");
  return raw;
}

std::uint8_t paeth(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return static_cast<std::uint8_t>(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

// Undoes the row filters in place; bpp is bytes per pixel.
void unfilter(std::vector<std::uint8_t>& raw, size_t row, int h, size_t bpp) {
  for (int y = 0; y < h; ++y) {
    std::uint8_t* cur = &raw[(row + 1) * static_cast<size_t>(y)];
    const std::uint8_t* prev = y > 0 ? cur - (row + 1) + 1 : nullptr;
    const std::uint8_t f = cur[0];
    std::uint8_t* p = cur + 1;
    for (size_t i = 0; i < row; ++i) {
      const int a = i >= bpp ? p[i - bpp] : 0, b = prev ? prev[i] : 0, c = prev && i >= bpp ? prev[i - bpp] : 0;
      switch (f) {
        case 0: break;
        case 1: p[i] = static_cast<std::uint8_t>(p[i] + a); break;
        case 2: p[i] = static_cast<std::uint8_t>(p[i] + b); break;
        case 3: p[i] = static_cast<std::uint8_t>(p[i] + (a + b) / 2); break;
        case 4: p[i] = static_cast<std::uint8_t>(p[i] + paeth(a, b, c)); break;
        default: throw PngError("unknown row filter " + std::to_string(f));
      }
    }
  }
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& img) {
  if (img.width <= 0 || img.height <= 0) throw PngError("cannot encode an empty image");
  // The scanlines, each led by its filter byte (0: none), compressed whole
  // into a zlib stream.
  const size_t row = static_cast<size_t>(img.width) * 3;
  std::vector<std::uint8_t> raw((row + 1) * static_cast<size_t>(img.height));
  for (size_t y = 0; y < static_cast<size_t>(img.height); ++y) {
    raw[(row + 1) * y] = 0;
    std::memcpy(&raw[(row + 1) * y + 1], img.rgb.data() + row * y, row);
  }
  libdeflate_compressor& c = compressor();
  std::vector<std::uint8_t> z(libdeflate_zlib_compress_bound(&c, raw.size()));
  const size_t zn = libdeflate_zlib_compress(&c, raw.data(), raw.size(), z.data(), z.size());
  if (zn == 0) throw PngError("libdeflate could not compress the image");  // cannot happen within the bound

  std::vector<std::uint8_t> out(kSignature, kSignature + 8);
  out.reserve(zn + 64);
  std::vector<std::uint8_t> ihdr;
  put32(ihdr, static_cast<std::uint32_t>(img.width));
  put32(ihdr, static_cast<std::uint32_t>(img.height));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8 bits, truecolour, deflate, filter 0, no interlace
  chunk(out, "IHDR", ihdr.data(), ihdr.size());
  chunk(out, "IDAT", z.data(), zn);
  chunk(out, "IEND", nullptr, 0);
  return out;
}

Image decode_png(const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0) throw PngError("not a PNG file");
  size_t at = 8;
  int w = 0, h = 0, colour = -1;
  std::vector<std::uint8_t> z, palette;
  bool end = false;
  while (!end) {
    if (at + 12 > bytes.size()) throw PngError("truncated PNG chunk");
    const std::uint32_t len = get32(&bytes[at]);
    if (len > bytes.size() - at - 12) throw PngError("truncated PNG chunk");
    const std::uint8_t* type = &bytes[at + 4];
    const std::uint8_t* data = &bytes[at + 8];
    if (crc(type, len + 4) != get32(data + len)) throw PngError("PNG chunk CRC mismatch");
    const std::string name(reinterpret_cast<const char*>(type), 4);
    if (name == "IHDR") {
      if (len != 13) throw PngError("bad IHDR");
      w = static_cast<int>(get32(data));
      h = static_cast<int>(get32(data + 4));
      colour = data[9];
      if (data[8] != 8) throw PngError("only 8-bit PNGs are read (this one has " + std::to_string(data[8]) + " bits)");
      if (data[10] != 0 || data[11] != 0) throw PngError("unknown compression or filter method");
      if (data[12] != 0) throw PngError("interlaced PNGs are not read");
    } else if (name == "PLTE") {
      palette.assign(data, data + len);
    } else if (name == "IDAT") {
      z.insert(z.end(), data, data + len);
    } else if (name == "IEND") {
      end = true;
    } else if ((type[0] & 0x20) == 0) {
      throw PngError("unknown critical chunk " + name);
    }
    at += 12 + len;
  }
  if (w <= 0 || h <= 0 || w > 1 << 15 || h > 1 << 15) throw PngError("bad PNG size");
  size_t bpp = 0;  // bytes per pixel
  switch (colour) {
    case 0: case 3: bpp = 1; break;
    case 2: bpp = 3; break;
    case 4: bpp = 2; break;
    case 6: bpp = 4; break;
    default: throw PngError("unknown colour type " + std::to_string(colour));
  }
  if (colour == 3 && (palette.empty() || palette.size() % 3 != 0)) throw PngError("palette PNG without a PLTE chunk");
  const size_t row = static_cast<size_t>(w) * bpp;
  std::vector<std::uint8_t> raw = inflate_all(z, (row + 1) * static_cast<size_t>(h));
  unfilter(raw, row, h, bpp);
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* src = &raw[(row + 1) * static_cast<size_t>(y) + 1];
    std::uint8_t* dst = &img.rgb[static_cast<size_t>(w) * 3 * static_cast<size_t>(y)];
    for (int x = 0; x < w; ++x, src += bpp, dst += 3) {
      if (colour == 3) {
        if (size_t{src[0]} * 3 + 3 > palette.size()) throw PngError("palette index out of range");
        std::memcpy(dst, &palette[size_t{src[0]} * 3], 3);
      } else if (colour == 0 || colour == 4) {
        dst[0] = dst[1] = dst[2] = src[0];
      } else {
        std::memcpy(dst, src, 3);
      }
    }
  }
  return img;
}

void write_png(const std::string& path, const Image& img) {
  const std::vector<std::uint8_t> bytes = encode_png(img);
  write_file_checked(path, std::string(bytes.begin(), bytes.end()));
}

Image read_png(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) throw PngError("cannot read " + path);
  std::vector<std::uint8_t> bytes;
  std::uint8_t buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.insert(bytes.end(), buf, buf + n);
  std::fclose(f);
  try {
    return decode_png(bytes);
  } catch (const PngError& e) {
    throw PngError(path + ": " + e.what());
  }
}

}  // namespace afford::render
