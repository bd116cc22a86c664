// The image pyramid: halving an image into the next, coarser layer.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <cstdint>
#include <memory_resource>

namespace marsokhod::nav {

/// The next pyramid layer: each pixel is the rounded mean of a 2x2 block, so the layer is
/// floor(width / 2) x floor(height / 2) (an odd last column or row is dropped).
template <class Meter = NullMeter>
imaging::Image<std::uint8_t>
halve_image(imaging::ImageView<const std::uint8_t> image, Meter& meter = null_meter,
            std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
