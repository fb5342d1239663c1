#include "backdrop.h"

#include <algorithm>
#include <cmath>

namespace afford::render {
namespace {

using Eigen::Vector3d;

struct Colour {
  double r, g, b;
};
constexpr Colour kSkyLow{0.80, 0.84, 0.89}, kSkyHigh{0.97, 0.98, 0.99};  // bottom and top of the picture
constexpr Colour kGround{0.90, 0.91, 0.93}, kGridLine{0.76, 0.79, 0.84};

Rgb to_rgb(const Colour& c) {
  auto u8 = [](double v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0, 1.0) * 255 + 0.5); };
  return {u8(c.r), u8(c.g), u8(c.b)};
}

// Narrows [*lo, *hi] to the pixels x of a row where a + b x >= 0 (> 0
// when strict).
void narrow(double a, double b, bool strict, int* lo, int* hi) {
  if (b == 0) {
    if (a < 0 || (strict && a == 0)) *hi = *lo - 1;
    return;
  }
  const double root = -a / b;  // where the function is zero
  if (b > 0) {
    const double first = strict ? std::floor(root) + 1 : std::ceil(root);
    if (first > *lo) *lo = static_cast<int>(std::min(first, static_cast<double>(*hi) + 1));
  } else {
    const double last = strict ? std::ceil(root) - 1 : std::floor(root);
    if (last < *hi) *hi = static_cast<int>(std::max(last, static_cast<double>(*lo) - 1));
  }
}

}  // namespace

Backdrop::Backdrop(const Camera& camera, int width, int height, const Ground* ground)
    : width_(width), height_(height), has_ground_(ground != nullptr) {
  if (ground == nullptr) return;
  // The ray through pixel (x, y) as the scene's view and projection have it
  // (glm::lookAt, glm::perspective): d = d0 + x dx + y dy.
  const Vector3d forward = (camera.target - camera.position).normalized();
  const Vector3d right = forward.cross(usable_up(camera)).normalized();
  const Vector3d up = right.cross(forward);
  const double ty = std::tan(camera.fov / 2), tx = ty * width / height;
  const Vector3d dx = right * (2 * tx / width), dy = -up * (2 * ty / height);
  const Vector3d d0 = forward + right * (tx * (1.0 / width - 1)) + up * (ty * (1 - 1.0 / height));
  // The ray meets the plane at t = rise / d_z, ahead when t > 0. There its
  // world x minus a line's x0 is (alpha d_z + rise d_x) / d_z with alpha
  // the eye's x minus x0: the sign of the numerator (times the sign of
  // rise) says which side of the line x = x0 the pixel sees.
  const double rise = ground->z - camera.position.z();
  const double side = rise >= 0 ? 1 : -1;
  auto along = [&](int axis, double alpha) {  // the linear function of the line {x, y}[axis] = eye - alpha
    auto coefficient = [&](const Vector3d& v) { return side * (alpha * v.z() + rise * v[axis]); };
    return Linear{coefficient(dx), coefficient(dy), coefficient(d0)};
  };
  ahead_ = Linear{side * dx.z(), side * dy.z(), side * d0.z()};
  const double span = ground->step * ground->cells;
  const double ax = camera.position.x() - ground->x0, ay = camera.position.y() - ground->y0;
  auto unit = [](const Linear& f) {  // scaled to a distance in pixels
    const double norm = std::hypot(f.a, f.b);
    return norm > 0 ? Linear{f.a / norm, f.b / norm, f.c / norm} : f;
  };
  const Linear far_x = along(0, ax - span), far_y = along(1, ay - span);
  inside_[0] = unit(along(0, ax));
  inside_[1] = unit(along(1, ay));
  inside_[2] = unit(Linear{-far_x.a, -far_x.b, -far_x.c});
  inside_[3] = unit(Linear{-far_y.a, -far_y.b, -far_y.c});
  for (int axis = 0; axis < 2; ++axis) {
    for (int k = 0; k <= ground->cells; ++k) {
      const Linear f = unit(along(axis, (axis == 0 ? ax : ay) - k * ground->step));
      if (f.a != 0 || f.b != 0) lines_.push_back(f);
    }
  }
}

Image Backdrop::draw() const {
  Image img(width_, height_);
  const Rgb ground = to_rgb(kGround), grid = to_rgb(kGridLine);
  for (int y = 0; y < height_; ++y) {
    std::uint8_t* row = &img.rgb[static_cast<size_t>(y) * static_cast<size_t>(width_) * 3];
    const double high = 1 - (y + 0.5) / height_;
    const Rgb sky = to_rgb({kSkyLow.r + (kSkyHigh.r - kSkyLow.r) * high, kSkyLow.g + (kSkyHigh.g - kSkyLow.g) * high,
                            kSkyLow.b + (kSkyHigh.b - kSkyLow.b) * high});
    auto fill = [row](int from, int to, Rgb c) {
      for (int x = from; x <= to; ++x) {
        row[3 * x] = c.r;
        row[3 * x + 1] = c.g;
        row[3 * x + 2] = c.b;
      }
    };
    int glo = 0, ghi = -1, xlo = 0, xhi = -1;  // the square's pixels, and within a pixel of it
    if (has_ground_) {
      int lo = 0, hi = width_ - 1;  // below the horizon
      narrow(ahead_.b * y + ahead_.c, ahead_.a, true, &lo, &hi);
      glo = xlo = lo, ghi = xhi = hi;
      for (const Linear& f : inside_) {
        narrow(f.b * y + f.c, f.a, false, &glo, &ghi);
        narrow(f.b * y + f.c + 1, f.a, true, &xlo, &xhi);
      }
    }
    if (glo > ghi) {
      fill(0, width_ - 1, sky);
    } else {
      fill(0, glo - 1, sky);
      fill(glo, ghi, ground);
      fill(ghi + 1, width_ - 1, sky);
    }
    if (xlo > xhi) continue;
    // The lines, one pixel wide, where they pass within a pixel; the border
    // lines reach half a pixel out of the square.
    for (const Linear& f : lines_) {
      const double a = f.b * y + f.c;  // the distance in pixels is |a + f.a x|
      int from = xlo, to = xhi;
      if (std::abs(f.a) < 1e-12) {  // along the row: all of it or none
        if (std::abs(a) >= 1) continue;
      } else {  // the pixels where the distance is under one
        const double u = (-1 - a) / f.a, v = (1 - a) / f.a;
        const double first = std::max(std::min(u, v), xlo - 1.0), last = std::min(std::max(u, v), xhi + 1.0);
        if (first > last) continue;
        from = std::max(from, static_cast<int>(std::floor(first)) + 1);
        to = std::min(to, static_cast<int>(std::ceil(last)) - 1);
      }
      for (int x = from; x <= to; ++x) {
        const double cover = 1 - std::abs(a + f.a * x);
        std::uint8_t* p = row + 3 * x;
        p[0] = static_cast<std::uint8_t>(p[0] + (grid.r - p[0]) * cover + 0.5);
        p[1] = static_cast<std::uint8_t>(p[1] + (grid.g - p[1]) * cover + 0.5);
        p[2] = static_cast<std::uint8_t>(p[2] + (grid.b - p[2]) * cover + 0.5);
      }
    }
  }
  return img;
}

}  // namespace afford::render
