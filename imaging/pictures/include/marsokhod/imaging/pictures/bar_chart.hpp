// BarChart: a few figures side by side, one bar per series in each group (paper beside model).
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <optional>
#include <string>
#include <vector>

namespace marsokhod::imaging {

/// Groups of bars for people to compare: each group has one value per series (a missing
/// value leaves a gap), each bar is labelled with its value, the y axis starts at 0, and a
/// legend names the series by colour.
struct BarChart {
  struct Group {
    std::string label;
    std::vector<std::optional<double>> values; ///< one per series
  };
  std::string title;
  std::string y_label;
  std::vector<std::string> series;
  std::vector<Group> groups;
  std::string value_format = "{:.1f}"; ///< fmt format of the bars' labels
  int width = 720;
  int height = 420;
};

/// Draws the chart as an RGB image. Throws std::invalid_argument for a group whose values do
/// not match the series, a negative or non-finite value, or more series than it has colours.
Image<std::uint8_t> draw_bar_chart(const BarChart& chart);

} // namespace marsokhod::imaging
