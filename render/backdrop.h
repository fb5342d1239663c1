// The scene's backdrop: the sky, a vertical gradient, and the ground, a pale
// square with a grid under the scene. from_gl_rgba puts the OpenGL picture
// over it. Drawn by llvmpipe at the supersampled size, the same backdrop was
// three full-screen layers, a third of a frame's time; here it is a fill of
// each row and a few pixels per grid line.
//
// The ground is a plane, so every edge and grid line of it is a straight
// line in the picture, where a linear function of the pixel's position
// (x, y) is zero: a pixel's distance to it, in pixels, is that function
// over the norm of its gradient, and lines one pixel wide are drawn with
// that distance as their cover (anti-aliased).
#pragma once

#include <vector>

#include "image.h"
#include "scene.h"

namespace afford::render {

struct Ground {
  double z = 0;               // m, world height of the plane
  double x0 = 0, y0 = 0;      // m, world: the square's corner of least x and y
  double step = 0.01;         // m between grid lines
  int cells = 1;              // grid cells along each side of the square
  bool operator==(const Ground&) const = default;
};

class Backdrop {
 public:
  // The backdrop of a width x height picture seen by camera (as the scene
  // projects it); the sky alone when ground is nullptr.
  Backdrop(const Camera& camera, int width, int height, const Ground* ground);
  Image draw() const;

  // a x + b y + c at the centre of pixel (x, y), counted from the top left.
  struct Linear {
    double a = 0, b = 0, c = 0;
  };

 private:
  int width_, height_;
  bool has_ground_ = false;
  Linear ahead_;                // > 0 where the ray meets the plane in front of the eye
  Linear inside_[4];            // >= 0 inside the square, one per edge, in pixels
  std::vector<Linear> lines_;   // the grid lines, each scaled to distance in pixels
};

}  // namespace afford::render
