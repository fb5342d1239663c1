// The drawing operations of the plots (the session timeline, the gap
// diagnosis's charts), with an SVG backend (text) and a raster backend
// (an Image, no OpenGL), so that both files come from one layout.
#pragma once

#include <string>
#include <vector>

#include "image.h"

namespace afford::render {

enum class Anchor { start, middle, end };

struct Pt {
  double x, y;
};

class Canvas {
 public:
  virtual ~Canvas() = default;
  virtual void rect(double x, double y, double w, double h, Rgb fill) = 0;
  virtual void line(double x0, double y0, double x1, double y1, Rgb c, double width, double dash = 0) = 0;
  virtual void polyline(const std::vector<Pt>& p, Rgb c, double width) = 0;
  virtual void polygon(const std::vector<Pt>& p, Rgb fill) = 0;
  // y is the middle of the text's height.
  virtual void text(double x, double y, const std::string& s, Rgb c, Anchor a = Anchor::start) = 0;
  virtual double text_width(const std::string& s) const = 0;
};

class SvgCanvas : public Canvas {
 public:
  SvgCanvas(int w, int h);
  std::string finish();  // the whole document
  void rect(double x, double y, double w, double h, Rgb fill) override;
  void line(double x0, double y0, double x1, double y1, Rgb c, double width, double dash) override;
  void polyline(const std::vector<Pt>& p, Rgb c, double width) override;
  void polygon(const std::vector<Pt>& p, Rgb fill) override;
  void text(double x, double y, const std::string& s, Rgb c, Anchor a) override;
  double text_width(const std::string& s) const override;

 private:
  std::string out_;
};

class RasterCanvas : public Canvas {
 public:
  explicit RasterCanvas(Image* img) : img_(img) {}
  void rect(double x, double y, double w, double h, Rgb fill) override;
  void line(double x0, double y0, double x1, double y1, Rgb c, double width, double dash) override;
  void polyline(const std::vector<Pt>& p, Rgb c, double width) override;
  void polygon(const std::vector<Pt>& p, Rgb fill) override;
  void text(double x, double y, const std::string& s, Rgb c, Anchor a) override;
  double text_width(const std::string& s) const override;

 private:
  Image* img_;
};

// The text if it is at most `width` wide on the canvas, else its longest
// start that is, with ".." after it.
std::string fit_to(const Canvas& c, const std::string& s, double width);

// "Nice" tick step: 1, 2 or 5 times a power of ten, about n ticks over span.
double tick_step(double span, int n);
// A tick's label with as many decimals as the step needs.
std::string tick_label(double v, double step);

// A vertical axis: data range [lo, hi] drawn between pixel rows top and bottom.
struct Axis {
  double lo, hi;       // data
  double top, bottom;  // pixels
  double y(double v) const { return bottom - (v - lo) / (hi - lo) * (bottom - top); }
};

}  // namespace afford::render
