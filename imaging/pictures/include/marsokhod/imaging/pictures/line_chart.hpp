// LineChart: a measured curve as a picture, with the points where there is no value marked.
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <string>
#include <vector>

namespace marsokhod::imaging {

/// A curve of (x, y) points for people to look at: the points joined in x order, x on a log
/// scale (every x must be positive) with a tick at every x given, y from 0; `missing` x values
/// (no y: the measurement could not be made) are marked at the bottom in red, and `marks` draw
/// labelled vertical lines.
struct LineChart {
  struct Point {
    double x = 0.0;
    double y = 0.0;
  };
  struct Mark {
    double x = 0.0;
    std::string label;
  };
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<Point> points;
  std::vector<double> missing;
  std::vector<Mark> marks;
  int width = 720;
  int height = 420;
};

/// Draws the chart as an RGB image. Throws std::invalid_argument for an x that is not finite
/// and positive or a y that is not finite.
Image<std::uint8_t> draw_line_chart(const LineChart& chart);

} // namespace marsokhod::imaging
