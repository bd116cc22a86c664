#pragma once

// Input checks of the stereo matcher (private).

#include "marsokhod/nav/image.hpp"
#include "marsokhod/nav/stereo.hpp"

#include <cstdint>

namespace marsokhod::nav::detail {

/// Throws std::invalid_argument when the pair cannot be matched with these options: bad
/// options, empty or multi-channel images, sizes that differ, a search range wider than the
/// image, an image too small for the pyramid.
void check_pair(ImageView<const std::uint8_t> left, ImageView<const std::uint8_t> right,
                const StereoOptions& options);

} // namespace marsokhod::nav::detail
