// check_pair: the stereo matcher's refusal of pairs it cannot match (private to stereo).
#pragma once

// Input checks of the stereo matcher (private).

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"

#include <cstdint>

namespace marsokhod::nav::detail {

/// Throws std::invalid_argument when the pair cannot be matched with these options: bad
/// options, empty or multi-channel images, sizes that differ, a search range wider than the
/// image, an image too small for the pyramid.
void check_pair(imaging::ImageView<const std::uint8_t> left,
                imaging::ImageView<const std::uint8_t> right, const StereoOptions& options);

/// The checks of check_pair that need only the pair's size: options, search range, pyramid.
void check_pair_size(int width, int height, const StereoOptions& options);

} // namespace marsokhod::nav::detail
