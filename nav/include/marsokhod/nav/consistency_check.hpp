#pragma once

#include "marsokhod/nav/work.hpp"

#include <cstdint>
#include <span>

namespace marsokhod::nav {

/// The right image's view of one scan line's matches, derived from the left view's winners
/// instead of a second matching pass: each left pixel x with disparity d and aggregated cost c
/// claims right pixel x - d, and the cheapest claim on each right pixel stands (the smaller
/// disparity on a tie). `right` gets the standing claim's disparity, -1 where none arrived;
/// `right_cost` is workspace. Where two surfaces compete for one right pixel (an occlusion, a
/// fattened edge) only the better match keeps it.
void claim_right_pixels(std::span<const int> left, std::span<const std::uint16_t> left_cost,
                        std::span<int> right, std::span<std::uint16_t> right_cost);

/// The left-right check of one scan line: a left pixel x with disparity d is reliable (255)
/// when x - d lies inside the image and the right pixel's disparity is within `tolerance` of
/// d; otherwise (occluded, mismatched, outside the right image) it is 0. Returns the number of
/// reliable pixels. `right` holds -1 where no match reached a right pixel.
template <class Meter = NullMeter>
int check_left_right(std::span<const int> left, std::span<const int> right, int tolerance,
                     std::span<std::uint8_t> valid, Meter& meter = null_meter);

} // namespace marsokhod::nav
