// A few figures drawn side by side: axes, grid, the bars with their values, the legend.

#include "marsokhod/imaging/pictures/bar_chart.hpp"

#include "pictures/bitmap_font.hpp"
#include "pictures/chart_drawing.hpp"
#include "pictures/colour_scale.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace marsokhod::imaging {
namespace {

using namespace detail; // the strokes

// The categorical palette of matplotlib's tab10, grey first; the fifth is red, so that a chart of
// outcome classes in their order shows "unsafe" in red.
constexpr std::array<Rgb, 8> kSeries{{{127, 127, 127},
                                      {31, 119, 180},
                                      {255, 127, 14},
                                      {44, 160, 44},
                                      {214, 39, 40},
                                      {148, 103, 189},
                                      {140, 86, 75},
                                      {227, 119, 194}}};

void check(const BarChart& chart) {
  if (chart.series.size() > kSeries.size())
    throw std::invalid_argument(
        fmt::format("bar chart: {} series, at most {}", chart.series.size(), kSeries.size()));
  for (const BarChart::Group& g : chart.groups) {
    if (g.values.size() != chart.series.size())
      throw std::invalid_argument(fmt::format("bar chart: group '{}' has {} values for {} series",
                                              g.label, g.values.size(), chart.series.size()));
    for (const std::optional<double>& v : g.values)
      if (v && (!std::isfinite(*v) || *v < 0.0))
        throw std::invalid_argument(fmt::format(
            "bar chart: group '{}' has the value {}, not finite and >= 0", g.label, *v));
  }
}

double top_value(const BarChart& chart) {
  double top = 1.0;
  for (const BarChart::Group& g : chart.groups)
    for (const std::optional<double>& v : g.values)
      top = std::max(top, v.value_or(0.0) * 1.15);
  return top;
}

void draw_legend(ImageView<std::uint8_t> rgb, const BarChart& chart, int right, int y) {
  int x = right;
  for (std::size_t s = chart.series.size(); s-- > 0;) {
    x -= text_width(chart.series[s], 1) + 24;
    box(rgb, x, y, x + 10, y + 8, kSeries[s]);
    text(rgb, x + 14, y, chart.series[s], kInk);
  }
}

} // namespace

Image<std::uint8_t> draw_bar_chart(const BarChart& chart) {
  check(chart);
  Image<std::uint8_t> picture(chart.width, chart.height, 3, 255);
  ImageView<std::uint8_t> rgb = picture.view();
  const int left = 60;
  const int top = 56;
  const int right = chart.width - 20;
  const int bottom = chart.height - 44;
  const double y1 = top_value(chart);
  const auto py = [&](double y) {
    return bottom - static_cast<int>(std::lround(y / y1 * (bottom - top)));
  };
  const Ticks ticks = legend_ticks(0.0, y1);
  for (std::size_t i = 0; i < ticks.values.size(); ++i) {
    const int y = py(ticks.values[i]);
    line(rgb, left, y, right, y, kGrid, 1);
    text(rgb, left - 8 - text_width(ticks.labels[i], 1), y - 4, ticks.labels[i], kInk);
  }
  const int groups = std::max<int>(1, static_cast<int>(chart.groups.size()));
  const int slot = (right - left) / groups;
  const int bars = std::max<int>(1, static_cast<int>(chart.series.size()));
  const int bar = std::max(4, (slot * 2 / 3) / bars);
  for (int g = 0; g < static_cast<int>(chart.groups.size()); ++g) {
    const BarChart::Group& group = chart.groups[static_cast<std::size_t>(g)];
    const int centre = left + slot * g + slot / 2;
    const int first = centre - bar * bars / 2;
    for (int s = 0; s < static_cast<int>(group.values.size()); ++s) {
      const std::optional<double>& v = group.values[static_cast<std::size_t>(s)];
      if (!v)
        continue;
      const int x0 = first + s * bar;
      box(rgb, x0 + 1, py(*v), x0 + bar - 2, bottom, kSeries[static_cast<std::size_t>(s)]);
      const std::string label = fmt::format(fmt::runtime(chart.value_format), *v);
      text(rgb, x0 + bar / 2 - text_width(label, 1) / 2, py(*v) - 12, label, kInk);
    }
    text(rgb, centre - text_width(group.label, 1) / 2, bottom + 10, group.label, kInk);
  }
  line(rgb, left, bottom, right, bottom, kInk, 2);
  line(rgb, left, top, left, bottom, kInk, 2);
  text(rgb, left, 10, chart.title, kInk, kTitleScale);
  text(rgb, 8, top - 16, chart.y_label, kInk);
  draw_legend(rgb, chart, right, top - 16);
  return picture;
}

} // namespace marsokhod::imaging
