// False colour: a scalar field as an RGB picture with a legend, for people to read.
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace marsokhod::imaging {

/// How a scalar field (disparity, range, elevation) becomes a false-colour picture for people.
struct ColormapOptions {
  /// Value range mapped onto the colour scale; when absent, the finite values' 1st..99th
  /// percentile is used so that a few outliers do not flatten the picture.
  std::optional<float> min_value;
  std::optional<float> max_value;
  /// Unit shown on the legend, e.g. "px", "m".
  std::string unit;
  /// Title shown above the legend, e.g. "disparity".
  std::string title;
  /// Draws a colour bar with tick labels beside the picture.
  bool legend = true;
};

/// Renders a one-channel float field as an RGB image with a perceptually ordered scale
/// (dark blue = low, yellow = high) and a legend; non-finite values are drawn black.
Image<std::uint8_t> false_colour(ImageView<const float> field, const ColormapOptions& options);

} // namespace marsokhod::imaging
