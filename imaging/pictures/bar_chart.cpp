// A few figures drawn side by side by PLplot: axes, grid, the bars with their values, the legend.

#include "marsokhod/imaging/pictures/bar_chart.hpp"

#include "pictures/plot_canvas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <plplot/plplot.h>
#include <stdexcept>

namespace marsokhod::imaging {
namespace {

using namespace detail; // the canvas

// The categorical palette of matplotlib's tab10, grey first; the fifth is red, so that a chart of
// outcome classes in their order shows "unsafe" in red.
constexpr std::array<PlotColour, 8> kSeries{{{127, 127, 127},
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

// The label cut to what `room_px` holds, its end marked by an ellipsis.
std::string fitted(const std::string& label, double room_px) {
  const auto room = static_cast<std::size_t>(std::max(4.0, room_px / kPlotCharPx));
  if (label.size() <= room)
    return label;
  return label.substr(0, room - 1) + "\u2026";
}

void draw_legend(const PlotCanvas& canvas, const BarChart& chart, double left) {
  plvpor(left, 0.99, 0.30, 0.86);
  plwind(0.0, 1.0, 0.0, 1.0);
  const double step = 1.0 / std::max<double>(6.0, static_cast<double>(chart.series.size()));
  for (std::size_t s = 0; s < chart.series.size(); ++s) {
    const double y = 1.0 - step * (static_cast<double>(s) + 0.5);
    canvas.colour(kSeries[s]);
    plot_box(0.0, y - 0.15 * step, 0.08, y + 0.15 * step);
    canvas.colour(kPlotInk);
    plptex(0.14, y, 1.0, 0.0, 0.0, chart.series[s].c_str());
  }
}

} // namespace

Image<std::uint8_t> draw_bar_chart(const BarChart& chart) {
  check(chart);
  PlotCanvas canvas(chart.width, chart.height);
  const double top = top_value(chart);
  const auto groups = static_cast<double>(std::max<std::size_t>(1, chart.groups.size()));
  const auto bars = static_cast<double>(std::max<std::size_t>(1, chart.series.size()));
  const double right = chart.series.size() > 1 ? 0.80 : 0.96;
  // Group labels that would run into each other stand on end below their slots.
  std::size_t longest = 0;
  for (const BarChart::Group& g : chart.groups)
    longest = std::max(longest, g.label.size());
  const double slot_px = (right - 0.10) * chart.width / groups;
  const bool crowded = static_cast<double>(longest) * kPlotCharPx > 0.95 * slot_px;
  const double bottom =
      crowded ? std::min(0.5, 0.06 + static_cast<double>(longest) * kPlotCharPx / chart.height)
              : 0.14;
  plvpor(0.10, right, bottom, 0.86);
  plwind(0.0, groups, 0.0, top);
  canvas.colour(kPlotGrid);
  plbox("", 0.0, 0, "g", 0.0, 0);
  canvas.colour(kPlotInk);
  plbox("bc", 0.0, 0, "bcnstv", 0.0, 0);
  const double width = 0.7 / bars;
  for (std::size_t g = 0; g < chart.groups.size(); ++g) {
    const BarChart::Group& group = chart.groups[g];
    const double first = static_cast<double>(g) + 0.5 - 0.35;
    for (std::size_t s = 0; s < group.values.size(); ++s) {
      const std::optional<double>& v = group.values[s];
      if (!v)
        continue;
      const double x0 = first + width * static_cast<double>(s);
      canvas.colour(kSeries[s]);
      plot_box(x0 + 0.05 * width, 0.0, x0 + 0.95 * width, *v);
      // An empty bar says nothing worth a label; a row of zeros would hide the others.
      if (*v == 0.0)
        continue;
      canvas.colour(kPlotInk);
      const std::string label = fmt::format(fmt::runtime(chart.value_format), *v);
      plschr(0.0, 0.7);
      plptex(x0 + 0.5 * width, *v + 0.025 * top, 1.0, 0.0, 0.5, label.c_str());
      plschr(0.0, 0.85);
    }
    canvas.colour(kPlotInk);
    const double at = (static_cast<double>(g) + 0.5) / groups;
    if (crowded)
      plmtex("bv", 0.7, at, 1.0, fitted(group.label, bottom * chart.height - 24.0).c_str());
    else
      plmtex("b", 1.6, at, 0.5, group.label.c_str());
  }
  plmtex("l", 4.2, 0.5, 0.5, chart.y_label.c_str());
  plschr(0.0, 1.15);
  plmtex("t", 2.0, 0.0, 0.0, chart.title.c_str());
  plschr(0.0, 0.85);
  if (chart.series.size() > 1)
    draw_legend(canvas, chart, right + 0.01);
  return canvas.take();
}

} // namespace marsokhod::imaging
