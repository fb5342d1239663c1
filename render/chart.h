// A plain x-y chart: curves over shaded bands of x, with a title, axis
// labels and a legend; as SVG and as PNG from one layout. The gap
// diagnosis draws its residual over time and its force-angle loops with it.
#pragma once

#include <string>
#include <vector>

#include "image.h"

namespace afford::render {

struct ChartCurve {
  std::string label;  // in the legend; curves with the same label share one entry
  Rgb colour;
  double width = 1.5;        // px
  std::vector<double> x, y;  // same length, data units; a NaN breaks the line
};

// A stretch of x shaded in a colour (a phase of a trace); the colour's
// legend entry is in ChartLegendBand.
struct ChartBand {
  double x0 = 0, x1 = 0;
  Rgb colour;
};

struct ChartLegendBand {
  std::string label;
  Rgb colour;
};

// A labelled vertical line (where one trace ends and the next begins).
struct ChartMarker {
  double x = 0;
  std::string label;
};

struct Chart {
  std::string title, x_label, y_label;  // labels with their units: "time [s]"
  std::vector<ChartBand> bands;
  std::vector<ChartLegendBand> band_legend;
  std::vector<ChartMarker> markers;
  std::vector<ChartCurve> curves;
  bool zero_line = false;  // a line at y = 0 (residuals)
};

inline constexpr int kChartWidth = 1100, kChartHeight = 560;

std::string chart_svg(const Chart& chart, int width = kChartWidth, int height = kChartHeight);
Image chart_png(const Chart& chart, int width = kChartWidth, int height = kChartHeight);

}  // namespace afford::render
