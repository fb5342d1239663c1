#include "canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace afford::render {
namespace {

std::string hex(Rgb c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

std::string xml(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

}  // namespace

SvgCanvas::SvgCanvas(int w, int h) {
  out_ = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(w) + "\" height=\"" +
         std::to_string(h) + "\" viewBox=\"0 0 " + std::to_string(w) + " " + std::to_string(h) +
         "\" font-family=\"DejaVu Sans Mono, monospace\" font-size=\"13\">\n";
}

std::string SvgCanvas::finish() { return out_ + "</svg>\n"; }

void SvgCanvas::rect(double x, double y, double w, double h, Rgb fill) {
  out_ += "<rect x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"" + num(w) + "\" height=\"" + num(h) +
          "\" fill=\"" + hex(fill) + "\"/>\n";
}

void SvgCanvas::line(double x0, double y0, double x1, double y1, Rgb c, double width, double dash) {
  out_ += "<line x1=\"" + num(x0) + "\" y1=\"" + num(y0) + "\" x2=\"" + num(x1) + "\" y2=\"" + num(y1) +
          "\" stroke=\"" + hex(c) + "\" stroke-width=\"" + num(width) + "\"" +
          (dash > 0 ? " stroke-dasharray=\"" + num(dash) + "\"" : std::string()) + "/>\n";
}

void SvgCanvas::polyline(const std::vector<Pt>& p, Rgb c, double width) {
  out_ += "<polyline fill=\"none\" stroke=\"" + hex(c) + "\" stroke-width=\"" + num(width) +
          "\" stroke-linejoin=\"round\" points=\"";
  for (const Pt& q : p) out_ += num(q.x) + "," + num(q.y) + " ";
  out_ += "\"/>\n";
}

void SvgCanvas::polygon(const std::vector<Pt>& p, Rgb fill) {
  out_ += "<polygon fill=\"" + hex(fill) + "\" points=\"";
  for (const Pt& q : p) out_ += num(q.x) + "," + num(q.y) + " ";
  out_ += "\"/>\n";
}

void SvgCanvas::text(double x, double y, const std::string& s, Rgb c, Anchor a) {
  static const char* const kAnchor[] = {"start", "middle", "end"};
  out_ += "<text x=\"" + num(x) + "\" y=\"" + num(y + 4.5) + "\" fill=\"" + hex(c) + "\" text-anchor=\"" +
          kAnchor[static_cast<int>(a)] + "\">" + xml(s) + "</text>\n";
}

double SvgCanvas::text_width(const std::string& s) const { return 7.8 * static_cast<double>(s.size()); }

void RasterCanvas::rect(double x, double y, double w, double h, Rgb fill) {
  fill_rect(*img_, static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)),
            static_cast<int>(std::lround(w)), static_cast<int>(std::lround(h)), fill);
}

void RasterCanvas::line(double x0, double y0, double x1, double y1, Rgb c, double width, double dash) {
  draw_line(*img_, x0, y0, x1, y1, c, width, dash);
}

void RasterCanvas::polyline(const std::vector<Pt>& p, Rgb c, double width) {
  for (size_t i = 1; i < p.size(); ++i) draw_line(*img_, p[i - 1].x, p[i - 1].y, p[i].x, p[i].y, c, width);
}

void RasterCanvas::polygon(const std::vector<Pt>& p, Rgb fill) {
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const Pt& q : p) {
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  }
  for (int y = static_cast<int>(std::floor(y0)); y <= static_cast<int>(std::ceil(y1)); ++y) {
    for (int x = static_cast<int>(std::floor(x0)); x <= static_cast<int>(std::ceil(x1)); ++x) {
      const double px = x + 0.5, py = y + 0.5;
      bool in = false;
      for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
        if ((p[i].y > py) != (p[j].y > py) &&
            px < (p[j].x - p[i].x) * (py - p[i].y) / (p[j].y - p[i].y) + p[i].x) {
          in = !in;
        }
      }
      if (in) img_->set(x, y, fill);
    }
  }
}

void RasterCanvas::text(double x, double y, const std::string& s, Rgb c, Anchor a) {
  const double w = text_width(s);
  const double left = a == Anchor::start ? x : a == Anchor::middle ? x - w / 2 : x - w;
  draw_text(*img_, static_cast<int>(std::lround(left)), static_cast<int>(std::lround(y - kGlyphHeight)), s, c, 2);
}

double RasterCanvas::text_width(const std::string& s) const { return static_cast<double>(render::text_width(s, 2)); }

std::string fit_to(const Canvas& c, const std::string& s, double width) {
  if (c.text_width(s) <= width) return s;
  for (size_t n = s.size(); n-- > 0;) {
    const std::string t = s.substr(0, n) + "..";
    if (c.text_width(t) <= width) return t;
  }
  return "";
}

double tick_step(double span, int n) {
  if (span <= 0) return 1;
  const double raw = span / n;
  const double p = std::pow(10, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (raw <= m * p) return m * p;
  }
  return 10 * p;
}

std::string tick_label(double v, double step) {
  char buf[32];
  const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < step * 1e-6 ? 0.0 : v);
  return buf;
}

}  // namespace afford::render
