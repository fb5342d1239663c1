// An 8-bit RGB raster and the few 2-D drawing operations the frames' text,
// the contact sheet and the timeline plot need. Row 0 is the top row.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace afford::render {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3, row-major from the top

  Image() = default;
  Image(int w, int h, Rgb fill = {255, 255, 255});
  Rgb at(int x, int y) const;
  void set(int x, int y, Rgb c);                // ignores points outside
  void blend(int x, int y, Rgb c, double a);    // a in [0, 1]; ignores points outside
};

void fill_rect(Image& img, int x0, int y0, int w, int h, Rgb c);
void stroke_rect(Image& img, int x0, int y0, int w, int h, Rgb c);
// A line `width` pixels wide (round caps); dashed when dash > 0 (dash and
// gap of that many pixels).
void draw_line(Image& img, double x0, double y0, double x1, double y1, Rgb c, double width = 1, double dash = 0);
// Copies src into dst with its top-left corner at (x, y), clipped.
void blit(Image& dst, const Image& src, int x, int y);
// An RGBA picture as OpenGL leaves it (width * height * 4 bytes, bottom row
// first), turned top-down and averaged over factor x factor blocks
// (supersampled anti-aliasing) in one pass: the picture comes out
// width / factor by height / factor. With `under` (of that size), the
// colour is taken as premultiplied by its alpha and put over `under`;
// without, the alpha is ignored.
Image from_gl_rgba(const std::uint8_t* rgba, int width, int height, int factor, const Image* under = nullptr);

// ---- the built-in 5x7 bitmap font: printable ASCII, one pixel of spacing;
// g, p, q and y hang two pixels below the line (leave room under it)
inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6;
// Pixel width of text at a scale (each font pixel becomes scale x scale).
int text_width(std::string_view text, int scale);
// Draws text with its top-left corner at (x, y); characters the font lacks
// are drawn as '?'.
void draw_text(Image& img, int x, int y, std::string_view text, Rgb c, int scale = 1);
// The same on a filled box with `pad` pixels around (labels on pictures).
void draw_label(Image& img, int x, int y, std::string_view text, Rgb fg, Rgb bg, int scale = 1, int pad = 2);

}  // namespace afford::render
