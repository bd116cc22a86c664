// A measured curve drawn for people by PLplot: axes, ticks, the curve, the missing points and the
// marks.

#include "marsokhod/imaging/pictures/line_chart.hpp"

#include "pictures/plot_canvas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <plplot/plplot.h>
#include <stdexcept>

namespace marsokhod::imaging {
namespace {

using namespace detail; // the canvas

constexpr PlotColour kCurveColour{31, 119, 180};
constexpr PlotColour kMissingColour{214, 39, 40};
constexpr PlotColour kMarkColour{120, 120, 120};

// The ranges the plot shows: log10 of x, and y from 0.
struct Frame {
  double log_x0 = 0.0;
  double log_x1 = 1.0;
  double y1 = 1.0;
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

// A tick at every x given, labelled, its labels on end when they would run into each other.
void draw_axes(const PlotCanvas& canvas, const LineChart& chart, const Frame& f,
               const std::vector<double>& xs, bool crowded) {
  canvas.colour(kPlotGrid);
  for (const double x : xs)
    pljoin(std::log10(x), 0.0, std::log10(x), f.y1);
  plbox("", 0.0, 0, "g", 0.0, 0);
  canvas.colour(kPlotInk);
  plbox("bc", 0.0, 0, "bcnstv", 0.0, 0);
  for (const double x : xs) {
    const double at = (std::log10(x) - f.log_x0) / (f.log_x1 - f.log_x0);
    const std::string label = compact(x);
    if (crowded)
      plmtex("bv", 0.7, at, 1.0, label.c_str());
    else
      plmtex("b", 1.6, at, 0.5, label.c_str());
  }
  plmtex("b", crowded ? 4.6 : 3.2, 0.5, 0.5, chart.x_label.c_str());
  plmtex("l", 4.2, 0.5, 0.5, chart.y_label.c_str());
  plschr(0.0, 1.15);
  plmtex("t", 2.0, 0.0, 0.0, chart.title.c_str());
  plschr(0.0, 0.85);
}

} // namespace

Image<std::uint8_t> draw_line_chart(const LineChart& chart) {
  check(chart);
  PlotCanvas canvas(chart.width, chart.height);
  std::vector<double> xs;
  const Frame f = frame_of(chart, xs);
  std::size_t longest = 0;
  for (const double x : xs)
    longest = std::max(longest, compact(x).size());
  const double plot_px = 0.86 * chart.width;
  const bool crowded =
      !xs.empty() && static_cast<double>(xs.size() * longest) * kPlotCharPx > 0.8 * plot_px;
  plvpor(0.10, 0.96, crowded ? 0.22 : 0.16, 0.86);
  plwind(f.log_x0, f.log_x1, 0.0, f.y1);
  draw_axes(canvas, chart, f, xs, crowded);
  for (const LineChart::Mark& m : chart.marks) {
    const double at = std::log10(m.x);
    canvas.colour(kMarkColour);
    pllsty(2);
    pljoin(at, 0.0, at, f.y1);
    pllsty(1);
    // A mark near the right edge takes its label on its left, inside the plot.
    const bool near_right = (at - f.log_x0) / (f.log_x1 - f.log_x0) > 0.7;
    plptex(at, 0.95 * f.y1, 1.0, 0.0, near_right ? 1.05 : -0.05, m.label.c_str());
  }
  std::vector<LineChart::Point> points = chart.points;
  std::sort(points.begin(), points.end(),
            [](const LineChart::Point& a, const LineChart::Point& b) { return a.x < b.x; });
  std::vector<PLFLT> px;
  std::vector<PLFLT> py;
  for (const LineChart::Point& p : points) {
    px.push_back(std::log10(p.x));
    py.push_back(p.y);
  }
  canvas.colour(kCurveColour);
  plwidth(3.0);
  if (px.size() > 1)
    plline(static_cast<PLINT>(px.size()), px.data(), py.data());
  const double dx = 0.008 * (f.log_x1 - f.log_x0);
  const double dy = 0.015 * f.y1;
  for (std::size_t i = 0; i < px.size(); ++i)
    plot_box(px[i] - dx, py[i] - dy, px[i] + dx, py[i] + dy);
  canvas.colour(kMissingColour);
  for (const double x : chart.missing) {
    const double at = std::log10(x);
    pljoin(at - 1.5 * dx, 1.0 * dy, at + 1.5 * dx, 4.0 * dy);
    pljoin(at - 1.5 * dx, 4.0 * dy, at + 1.5 * dx, 1.0 * dy);
  }
  plwidth(1.0);
  return canvas.take();
}

} // namespace marsokhod::imaging
