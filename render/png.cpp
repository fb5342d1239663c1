#include "png.h"

#include <array>
#include <cstdio>
#include <cstring>

namespace afford::render {
namespace {

constexpr std::uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
constexpr size_t kMaxStored = 65535;  // bytes in one stored deflate block

const std::array<std::uint32_t, 256>& crc_table() {
  static const std::array<std::uint32_t, 256> kTable = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  return kTable;
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<std::uint8_t>(v >> s));
}

std::uint32_t get32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

void chunk(std::vector<std::uint8_t>& out, const char type[4], const std::vector<std::uint8_t>& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  put32(out, crc32(out.data() + start, out.size() - start));
}

}  // namespace

std::uint32_t crc32(const std::uint8_t* data, size_t n, std::uint32_t crc) {
  const auto& t = crc_table();
  std::uint32_t c = crc ^ 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) c = t[(c ^ data[i]) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::uint32_t adler32(const std::uint8_t* data, size_t n, std::uint32_t adler) {
  std::uint32_t a = adler & 0xFFFF, b = adler >> 16;
  for (size_t i = 0; i < n; ++i) {
    a = (a + data[i]) % 65521;
    b = (b + a) % 65521;
  }
  return (b << 16) | a;
}

std::vector<std::uint8_t> encode_png(const Image& img) {
  if (img.width <= 0 || img.height <= 0) throw PngError("cannot encode an empty image");
  // The raw scanlines, each led by its filter byte (0: none).
  const size_t row = static_cast<size_t>(img.width) * 3;
  std::vector<std::uint8_t> raw;
  raw.reserve((row + 1) * static_cast<size_t>(img.height));
  for (int y = 0; y < img.height; ++y) {
    raw.push_back(0);
    const auto* p = img.rgb.data() + row * static_cast<size_t>(y);
    raw.insert(raw.end(), p, p + row);
  }
  // zlib: header (deflate, 32K window, no dictionary, check bits), stored blocks, Adler-32.
  std::vector<std::uint8_t> z;
  z.reserve(raw.size() + raw.size() / kMaxStored * 5 + 16);
  z.push_back(0x78);
  z.push_back(0x01);
  size_t at = 0;
  do {
    const size_t n = std::min(kMaxStored, raw.size() - at);
    const bool last = at + n == raw.size();
    z.push_back(last ? 1 : 0);  // BFINAL, BTYPE 00
    z.push_back(static_cast<std::uint8_t>(n & 0xFF));
    z.push_back(static_cast<std::uint8_t>(n >> 8));
    z.push_back(static_cast<std::uint8_t>(~n & 0xFF));
    z.push_back(static_cast<std::uint8_t>((~n >> 8) & 0xFF));
    z.insert(z.end(), raw.begin() + static_cast<std::ptrdiff_t>(at), raw.begin() + static_cast<std::ptrdiff_t>(at + n));
    at += n;
  } while (at < raw.size());
  put32(z, adler32(raw.data(), raw.size()));

  std::vector<std::uint8_t> out(kSignature, kSignature + 8);
  std::vector<std::uint8_t> ihdr;
  put32(ihdr, static_cast<std::uint32_t>(img.width));
  put32(ihdr, static_cast<std::uint32_t>(img.height));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8 bits, truecolour, deflate, filter 0, no interlace
  chunk(out, "IHDR", ihdr);
  chunk(out, "IDAT", z);
  chunk(out, "IEND", {});
  return out;
}

Image decode_png(const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0) throw PngError("not a PNG file");
  size_t at = 8;
  int w = 0, h = 0;
  std::vector<std::uint8_t> z;
  bool end = false;
  while (!end) {
    if (at + 12 > bytes.size()) throw PngError("truncated PNG chunk");
    const std::uint32_t len = get32(&bytes[at]);
    if (at + 12 + len > bytes.size()) throw PngError("truncated PNG chunk");
    const std::uint8_t* type = &bytes[at + 4];
    const std::uint8_t* data = &bytes[at + 8];
    if (crc32(type, len + 4) != get32(data + len)) throw PngError("PNG chunk CRC mismatch");
    const std::string name(reinterpret_cast<const char*>(type), 4);
    if (name == "IHDR") {
      if (len != 13) throw PngError("bad IHDR");
      w = static_cast<int>(get32(data));
      h = static_cast<int>(get32(data + 4));
      if (data[8] != 8 || data[9] != 2 || data[10] != 0 || data[11] != 0 || data[12] != 0) {
        throw PngError("only 8-bit RGB, non-interlaced PNGs are read");
      }
    } else if (name == "IDAT") {
      z.insert(z.end(), data, data + len);
    } else if (name == "IEND") {
      end = true;
    }
    at += 12 + len;
  }
  if (w <= 0 || h <= 0 || w > 1 << 15 || h > 1 << 15) throw PngError("bad PNG size");
  // zlib with stored blocks only.
  if (z.size() < 6 || (z[0] & 0x0F) != 8 || ((z[0] << 8) | z[1]) % 31 != 0) throw PngError("bad zlib header");
  std::vector<std::uint8_t> raw;
  size_t p = 2;
  bool last = false;
  while (!last) {
    if (p + 5 > z.size()) throw PngError("truncated deflate data");
    if ((z[p] & 0x06) != 0) throw PngError("compressed deflate blocks are not read (stored blocks only)");
    last = z[p] & 1;
    const size_t n = z[p + 1] | (z[p + 2] << 8);
    const size_t nn = z[p + 3] | (z[p + 4] << 8);
    if ((n ^ nn) != 0xFFFF) throw PngError("bad stored block length");
    p += 5;
    if (p + n > z.size()) throw PngError("truncated deflate data");
    raw.insert(raw.end(), z.begin() + static_cast<std::ptrdiff_t>(p), z.begin() + static_cast<std::ptrdiff_t>(p + n));
    p += n;
  }
  if (p + 4 > z.size() || get32(&z[p]) != adler32(raw.data(), raw.size())) throw PngError("Adler-32 mismatch");
  const size_t row = static_cast<size_t>(w) * 3;
  if (raw.size() != (row + 1) * static_cast<size_t>(h)) throw PngError("wrong amount of image data");
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* src = &raw[(row + 1) * static_cast<size_t>(y)];
    if (src[0] != 0) throw PngError("only filter type 0 is read");
    std::memcpy(&img.rgb[row * static_cast<size_t>(y)], src + 1, row);
  }
  return img;
}

void write_png(const std::string& path, const Image& img) {
  const std::vector<std::uint8_t> bytes = encode_png(img);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw PngError("cannot write " + path);
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  if (std::fclose(f) != 0 || !ok) throw PngError("cannot write " + path);
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
