#include "image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace afford::render {

Image::Image(int w, int h, Rgb fill) : width(w), height(h), rgb(static_cast<size_t>(w) * static_cast<size_t>(h) * 3) {
  for (size_t i = 0; i < rgb.size(); i += 3) {
    rgb[i] = fill.r;
    rgb[i + 1] = fill.g;
    rgb[i + 2] = fill.b;
  }
}

Rgb Image::at(int x, int y) const {
  const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void Image::set(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= width || y >= height) return;
  const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
  rgb[i] = c.r;
  rgb[i + 1] = c.g;
  rgb[i + 2] = c.b;
}

void Image::blend(int x, int y, Rgb c, double a) {
  if (x < 0 || y < 0 || x >= width || y >= height || a <= 0) return;
  a = std::min(a, 1.0);
  const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
  auto mix = [a](std::uint8_t old, std::uint8_t v) {
    return static_cast<std::uint8_t>(old + (v - old) * a + 0.5);  // in [0, 255.5): rounds as lround
  };
  rgb[i] = mix(rgb[i], c.r);
  rgb[i + 1] = mix(rgb[i + 1], c.g);
  rgb[i + 2] = mix(rgb[i + 2], c.b);
}

void fill_rect(Image& img, int x0, int y0, int w, int h, Rgb c) {
  const int xa = std::max(x0, 0), ya = std::max(y0, 0);
  const int xb = std::min(x0 + w, img.width), yb = std::min(y0 + h, img.height);
  for (int y = ya; y < yb; ++y) {
    for (int x = xa; x < xb; ++x) img.set(x, y, c);
  }
}

void stroke_rect(Image& img, int x0, int y0, int w, int h, Rgb c) {
  fill_rect(img, x0, y0, w, 1, c);
  fill_rect(img, x0, y0 + h - 1, w, 1, c);
  fill_rect(img, x0, y0, 1, h, c);
  fill_rect(img, x0 + w - 1, y0, 1, h, c);
}

// Coverage of each pixel by a capsule around the segment (distance test at
// the pixel centre with a one-pixel ramp): cheap anti-aliasing.
void draw_line(Image& img, double x0, double y0, double x1, double y1, Rgb c, double width, double dash) {
  const double dx = x1 - x0, dy = y1 - y0;
  const double len2 = dx * dx + dy * dy;
  const double len = std::sqrt(len2);
  const double r = width / 2;
  const int xa = static_cast<int>(std::floor(std::min(x0, x1) - r - 1));
  const int xb = static_cast<int>(std::ceil(std::max(x0, x1) + r + 1));
  const int ya = static_cast<int>(std::floor(std::min(y0, y1) - r - 1));
  const int yb = static_cast<int>(std::ceil(std::max(y0, y1) + r + 1));
  for (int y = std::max(ya, 0); y <= std::min(yb, img.height - 1); ++y) {
    for (int x = std::max(xa, 0); x <= std::min(xb, img.width - 1); ++x) {
      const double px = x + 0.5, py = y + 0.5;
      double u = len2 > 0 ? ((px - x0) * dx + (py - y0) * dy) / len2 : 0;
      u = std::clamp(u, 0.0, 1.0);
      if (dash > 0 && std::fmod(u * len, 2 * dash) > dash) continue;
      const double ex = x0 + u * dx - px, ey = y0 + u * dy - py;
      const double d = std::sqrt(ex * ex + ey * ey);
      const double cover = std::clamp(r + 0.5 - d, 0.0, 1.0);
      if (cover > 0) img.blend(x, y, c, cover);
    }
  }
}

void blit(Image& dst, const Image& src, int x, int y) {
  for (int j = 0; j < src.height; ++j) {
    const int ty = y + j;
    if (ty < 0 || ty >= dst.height) continue;
    for (int i = 0; i < src.width; ++i) {
      const int tx = x + i;
      if (tx < 0 || tx >= dst.width) continue;
      dst.set(tx, ty, src.at(i, j));
    }
  }
}

namespace {

// The factor is a template argument so that the loops unroll and the
// divisions by constants become multiplies. The block's rows are summed
// first, in a plain loop the compiler vectorises; a block that is wholly
// drawn or wholly backdrop (most of them) skips the blending.
template <int F>
Image from_gl_rgba_by(const std::uint8_t* rgba, int width, int height, const Image* under) {
  constexpr int n = F * F;
  constexpr int full = 255 * n;  // a block's alpha sum where nothing of `under` shows
  Image out(width / F, height / F);
  const size_t stride = static_cast<size_t>(width) * 4, used = static_cast<size_t>(out.width) * F * 4;
  std::vector<std::uint16_t> column(used);  // each column's sum over the block's rows
  for (int y = 0; y < out.height; ++y) {
    // Output row y (from the top) is made of GL rows counted from the bottom.
    const std::uint8_t* first = rgba + static_cast<size_t>(height - 1 - y * F) * stride;
    for (size_t k = 0; k < used; ++k) column[k] = first[k];
    for (int j = 1; j < F; ++j) {
      const std::uint8_t* src = rgba + static_cast<size_t>(height - 1 - (y * F + j)) * stride;
      for (size_t k = 0; k < used; ++k) column[k] = static_cast<std::uint16_t>(column[k] + src[k]);
    }
    const size_t at = static_cast<size_t>(y) * static_cast<size_t>(out.width) * 3;
    std::uint8_t* dst = &out.rgb[at];
    const std::uint8_t* bg = under != nullptr ? &under->rgb[at] : nullptr;
    const std::uint16_t* col = column.data();
    for (int x = 0; x < out.width; ++x, dst += 3, col += 4 * F) {
      int sum[4] = {0, 0, 0, 0};
      for (int i = 0; i < 4 * F; ++i) sum[i % 4] += col[i];
      const int rest = full - sum[3];
      if (bg == nullptr || rest == 0) {
        for (int c = 0; c < 3; ++c) dst[c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
      } else if (rest == full) {  // nothing drawn: the colour sums are 0 too
        for (int c = 0; c < 3; ++c) dst[c] = bg[3 * x + c];
      } else {  // premultiplied colour over the backdrop: C + (1 - A) B
        for (int c = 0; c < 3; ++c) {
          dst[c] = static_cast<std::uint8_t>((sum[c] * 255 + rest * bg[3 * x + c] + full / 2) / full);
        }
      }
    }
  }
  return out;
}

}  // namespace

Image from_gl_rgba(const std::uint8_t* rgba, int width, int height, int factor, const Image* under) {
  if (under != nullptr && (under->width * factor != width || under->height * factor != height)) {
    throw std::invalid_argument("from_gl_rgba: the picture under is not the size of the result");
  }
  switch (factor) {
    case 1: return from_gl_rgba_by<1>(rgba, width, height, under);
    case 2: return from_gl_rgba_by<2>(rgba, width, height, under);
    case 3: return from_gl_rgba_by<3>(rgba, width, height, under);
    case 4: return from_gl_rgba_by<4>(rgba, width, height, under);
    default: throw std::invalid_argument("from_gl_rgba: supersampling factor " + std::to_string(factor) + " is not 1 to 4");
  }
}

}  // namespace afford::render
