// The PNG reader on files other programs write: every row filter, grey,
// palette and alpha colour types, ancillary chunks; and the writer's size.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdlib>

#include "png.h"

namespace afford {
namespace {

using render::Image;

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<std::uint8_t>(v >> s));
}

void chunk(std::vector<std::uint8_t>& out, const std::string& type, const std::vector<std::uint8_t>& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  std::vector<std::uint8_t> body(type.begin(), type.end());
  body.insert(body.end(), data.begin(), data.end());
  out.insert(out.end(), body.begin(), body.end());
  put32(out, static_cast<std::uint32_t>(::crc32(0, body.data(), static_cast<uInt>(body.size()))));
}

int paeth(int a, int b, int c) {
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

// A PNG as another encoder would write it: row y uses filter y % 5, written
// from the PNG specification's forward definitions, not from our reader.
std::vector<std::uint8_t> foreign_png(int w, int h, int colour, int bpp, const std::vector<std::uint8_t>& pixels,
                                      const std::vector<std::uint8_t>& palette = {}) {
  const size_t row = static_cast<size_t>(w * bpp);
  std::vector<std::uint8_t> raw;
  for (int y = 0; y < h; ++y) {
    const int f = y % 5;
    raw.push_back(static_cast<std::uint8_t>(f));
    for (size_t i = 0; i < row; ++i) {
      const auto at = [&](int yy, size_t ii) { return pixels[static_cast<size_t>(yy) * row + ii]; };
      const int x = at(y, i), a = i >= size_t(bpp) ? at(y, i - bpp) : 0, b = y > 0 ? at(y - 1, i) : 0,
                c = y > 0 && i >= size_t(bpp) ? at(y - 1, i - bpp) : 0;
      const int pred = f == 0 ? 0 : f == 1 ? a : f == 2 ? b : f == 3 ? (a + b) / 2 : paeth(a, b, c);
      raw.push_back(static_cast<std::uint8_t>(x - pred));
    }
  }
  std::vector<std::uint8_t> z(::compressBound(static_cast<uLong>(raw.size())));
  uLongf zn = z.size();
  EXPECT_EQ(::compress2(z.data(), &zn, raw.data(), raw.size(), 9), Z_OK);
  z.resize(zn);
  std::vector<std::uint8_t> out = {137, 80, 78, 71, 13, 10, 26, 10};
  std::vector<std::uint8_t> ihdr;
  put32(ihdr, static_cast<std::uint32_t>(w));
  put32(ihdr, static_cast<std::uint32_t>(h));
  ihdr.insert(ihdr.end(), {8, static_cast<std::uint8_t>(colour), 0, 0, 0});
  chunk(out, "IHDR", ihdr);
  chunk(out, "tEXt", {'C', 'o', 'm', 'm', 'e', 'n', 't', 0, 'x'});  // ancillary: skipped
  if (!palette.empty()) chunk(out, "PLTE", palette);
  // Two IDAT chunks, as encoders that stream write them.
  const auto half = static_cast<std::ptrdiff_t>(z.size() / 2);
  chunk(out, "IDAT", {z.begin(), z.begin() + half});
  chunk(out, "IDAT", {z.begin() + half, z.end()});
  chunk(out, "IEND", {});
  return out;
}

std::uint8_t value(int x, int y, int k) { return static_cast<std::uint8_t>(x * 37 + y * 91 + k * 53 + x * y); }

TEST(PngRead, RgbaWithEveryFilterDropsAlpha) {
  const int w = 7, h = 10;
  std::vector<std::uint8_t> px;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 4; ++k) px.push_back(value(x, y, k));
  const Image img = render::decode_png(foreign_png(w, h, 6, 4, px));
  ASSERT_EQ(img.width, w);
  ASSERT_EQ(img.height, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k) EXPECT_EQ(img.rgb[static_cast<size_t>((y * w + x) * 3 + k)], value(x, y, k));
}

TEST(PngRead, RgbGreyGreyAlphaAndPalette) {
  const int w = 5, h = 6;
  std::vector<std::uint8_t> rgb, grey, grey_alpha, index;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int k = 0; k < 3; ++k) rgb.push_back(value(x, y, k));
      grey.push_back(value(x, y, 0));
      grey_alpha.insert(grey_alpha.end(), {value(x, y, 0), 200});
      index.push_back(static_cast<std::uint8_t>((x + y) % 3));
    }
  }
  const std::vector<std::uint8_t> palette = {255, 0, 0, 0, 255, 0, 0, 0, 255};
  EXPECT_EQ(render::decode_png(foreign_png(w, h, 2, 3, rgb)).rgb, rgb);
  const Image g = render::decode_png(foreign_png(w, h, 0, 1, grey));
  const Image ga = render::decode_png(foreign_png(w, h, 4, 2, grey_alpha));
  const Image p = render::decode_png(foreign_png(w, h, 3, 1, index, palette));
  for (size_t i = 0; i < grey.size(); ++i) {
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(g.rgb[i * 3 + k], grey[i]);
      EXPECT_EQ(ga.rgb[i * 3 + k], grey[i]);
      EXPECT_EQ(p.rgb[i * 3 + k], palette[index[i] * 3 + k]);
    }
  }
}

TEST(PngRead, RejectsWhatItCannotRead) {
  std::vector<std::uint8_t> px(4 * 4 * 3, 9);
  std::vector<std::uint8_t> bytes = foreign_png(4, 4, 2, 3, px);
  bytes[8 + 8 + 12] = 1;  // IHDR interlace byte (the CRC is checked first, so fix it)
  const std::vector<std::uint8_t> body(bytes.begin() + 12, bytes.begin() + 12 + 17);
  const auto crc = static_cast<std::uint32_t>(::crc32(0, body.data(), static_cast<uInt>(body.size())));
  for (int s = 0; s < 4; ++s) bytes[29 + s] = static_cast<std::uint8_t>(crc >> (24 - 8 * s));
  try {
    render::decode_png(bytes);
    ADD_FAILURE() << "an interlaced PNG was read";
  } catch (const render::PngError& e) {
    EXPECT_STREQ(e.what(), "interlaced PNGs are not read");
  }
  // A palette image without its palette.
  EXPECT_THROW(render::decode_png(foreign_png(4, 4, 3, 1, std::vector<std::uint8_t>(16, 0))), render::PngError);
}

TEST(PngWrite, CompressesAFlatFrame) {
  // Stored blocks took 922,218 bytes for any 640x480 frame.
  const Image img(640, 480, {40, 80, 120});
  const std::vector<std::uint8_t> bytes = render::encode_png(img);
  EXPECT_LT(bytes.size(), 10000u);
  EXPECT_EQ(render::decode_png(bytes).rgb, img.rgb);
}

}  // namespace
}  // namespace afford
