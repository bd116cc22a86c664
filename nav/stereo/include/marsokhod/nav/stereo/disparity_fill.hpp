// What becomes of unreliable disparities: fill policies and the 3x3 median filter.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <cstdint>
#include <memory_resource>
#include <optional>
#include <string_view>

namespace marsokhod::nav {

/// What becomes of the pixels the left-right check found unreliable.
enum class FillPolicy : std::uint8_t {
  /// Left as +inf (unknown, the Middlebury convention).
  none,
  /// Each run of unreliable pixels in a row takes the smaller disparity of the reliable pixels
  /// that bound it (the background: occlusions lie beside foreground objects, on the far
  /// surface); a run at an image edge takes its one bounding value. A row without any reliable
  /// pixel copies the nearest row that has one (the lower one on a tie).
  background_along_row,
};

std::string_view to_string(FillPolicy policy);
/// "none" or "background"; nothing for any other text.
std::optional<FillPolicy> parse_fill_policy(std::string_view text);

/// Applies `policy` to the pixels where `valid` is 0; returns how many pixels it wrote. When
/// no pixel at all is valid nothing is written.
template <class Meter = NullMeter>
std::uint64_t fill_disparity(imaging::ImageView<float> disparity,
                             imaging::ImageView<const std::uint8_t> valid, FillPolicy policy,
                             Meter& meter = null_meter,
                             std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// 3x3 median of `input` into `output` (same size, borders repeated); it removes the isolated
/// wrong pixels and the one-row streaks that a row-by-row optimisation leaves.
template <class Meter = NullMeter>
void median3x3(imaging::ImageView<const float> input, imaging::ImageView<float> output,
               Meter& meter = null_meter,
               std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
