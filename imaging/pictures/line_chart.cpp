// A measured curve drawn for people: axes, ticks, the curve, the missing points and the marks.

#include "marsokhod/imaging/pictures/line_chart.hpp"

#include "pictures/bitmap_font.hpp"
#include "pictures/chart_drawing.hpp"
#include "pictures/colour_scale.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace marsokhod::imaging {
namespace {

using namespace detail; // the strokes

// The plot area inside the margins, and the value ranges it shows.
struct Frame {
  int left = 0;
  int top = 0;
  int right = 0;
  int bottom = 0;
  double log_x0 = 0.0;
  double log_x1 = 1.0;
  double y1 = 1.0;

  int px(double x) const {
    const double t = (std::log10(x) - log_x0) / (log_x1 - log_x0);
    return left + static_cast<int>(std::lround(t * (right - left)));
  }
  int py(double y) const { return bottom - static_cast<int>(std::lround(y / y1 * (bottom - top))); }
};

void check(const LineChart& chart) {
  const auto bad_x = [](double x) { return !std::isfinite(x) || x <= 0.0; };
  for (const LineChart::Point& p : chart.points)
    if (bad_x(p.x) || !std::isfinite(p.y))
      throw std::invalid_argument(fmt::format(
          "line chart: point ({}, {}) is not a finite positive x and finite y", p.x, p.y));
  for (const double x : chart.missing)
    if (bad_x(x))
      throw std::invalid_argument(fmt::format("line chart: missing x {} is not positive", x));
  for (const LineChart::Mark& m : chart.marks)
    if (bad_x(m.x))
      throw std::invalid_argument(fmt::format("line chart: mark x {} is not positive", m.x));
}

Frame frame_of(const LineChart& chart, std::vector<double>& xs) {
  for (const LineChart::Point& p : chart.points)
    xs.push_back(p.x);
  xs.insert(xs.end(), chart.missing.begin(), chart.missing.end());
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  Frame f;
  f.left = 60;
  f.top = 56;
  f.right = chart.width - 30;
  f.bottom = chart.height - 50;
  const double lo = xs.empty() ? 1.0 : xs.front();
  const double hi = xs.empty() ? 10.0 : xs.back();
  f.log_x0 = std::log10(lo) - 0.05;
  f.log_x1 = std::log10(std::max(hi, lo * 10.0)) + 0.05;
  for (const LineChart::Point& p : chart.points)
    f.y1 = std::max(f.y1, p.y * 1.1);
  return f;
}

std::string compact(double value) {
  return std::abs(value - std::round(value)) < 1e-9 ? fmt::format("{:.0f}", value)
                                                    : fmt::format("{:g}", value);
}

void draw_axes(ImageView<std::uint8_t> rgb, const LineChart& chart, const Frame& f,
               const std::vector<double>& xs) {
  const detail::Ticks ticks = detail::legend_ticks(0.0, f.y1);
  for (std::size_t i = 0; i < ticks.values.size(); ++i) {
    const int y = f.py(ticks.values[i]);
    line(rgb, f.left, y, f.right, y, kGrid, 1);
    text(rgb, f.left - 8 - detail::text_width(ticks.labels[i], 1), y - 4, ticks.labels[i], kInk);
  }
  int free_from = 0; // a tick label that would overlap the one before is left out
  for (const double x : xs) {
    const int at = f.px(x);
    line(rgb, at, f.top, at, f.bottom, kGrid, 1);
    const std::string label = compact(x);
    const int start = at - detail::text_width(label, 1) / 2;
    if (start < free_from)
      continue;
    text(rgb, start, f.bottom + 8, label, kInk);
    free_from = start + detail::text_width(label, 1) + 6;
  }
  line(rgb, f.left, f.bottom, f.right, f.bottom, kInk, 2);
  line(rgb, f.left, f.top, f.left, f.bottom, kInk, 2);
  text(rgb, f.left, 10, chart.title, kInk, kTitleScale);
  text(rgb, (f.left + f.right - detail::text_width(chart.x_label, 1)) / 2, chart.height - 24,
       chart.x_label, kInk);
  text(rgb, 8, f.top - 16, chart.y_label, kInk);
}

} // namespace

Image<std::uint8_t> draw_line_chart(const LineChart& chart) {
  check(chart);
  Image<std::uint8_t> picture(chart.width, chart.height, 3, 255);
  ImageView<std::uint8_t> rgb = picture.view();
  std::vector<double> xs;
  const Frame f = frame_of(chart, xs);
  draw_axes(rgb, chart, f, xs);
  for (const LineChart::Mark& m : chart.marks) {
    const int at = f.px(m.x);
    line(rgb, at, f.top, at, f.bottom, kMark, 2, 6);
    text(rgb, at + 6, f.top + 4, m.label, kMark);
  }
  std::vector<LineChart::Point> points = chart.points;
  std::sort(points.begin(), points.end(),
            [](const LineChart::Point& a, const LineChart::Point& b) { return a.x < b.x; });
  for (std::size_t i = 1; i < points.size(); ++i)
    line(rgb, f.px(points[i - 1].x), f.py(points[i - 1].y), f.px(points[i].x), f.py(points[i].y),
         kCurve, 3);
  for (const LineChart::Point& p : points)
    square(rgb, f.px(p.x), f.py(p.y), 4, kCurve);
  for (const double x : chart.missing) {
    const int at = f.px(x);
    line(rgb, at - 6, f.bottom - 18, at + 6, f.bottom - 6, kMissing, 3);
    line(rgb, at - 6, f.bottom - 6, at + 6, f.bottom - 18, kMissing, 3);
  }
  return picture;
}

} // namespace marsokhod::imaging
