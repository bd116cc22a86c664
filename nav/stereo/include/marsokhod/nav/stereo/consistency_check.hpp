// The left-right consistency check of one scan line, and the right view it needs.
#pragma once

#include "marsokhod/nav/work/work.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace marsokhod::nav {

/// The right image's view of one scan line from the left view's aggregated costs (the S of the
/// scan-line programme, aggregated[x * candidates + d] for left pixel x and disparity d): right
/// pixel r takes the disparity d with the smallest S(r + d, d) over the left pixels r + d of the
/// line, the smaller disparity on a tie, or -1 where no left pixel reaches it (r + d >= width
/// for every d). This is the right view of semi-global matching (Hirschmueller 2008): a second
/// minimum over the same costs instead of a second matching pass. Left pixels x < `unseen`
/// take no part (their scene lies outside the right image: StereoOptions::unseen_columns).
/// Throws std::invalid_argument when aggregated does not hold width x candidates values.
std::vector<int> right_view_disparities(std::span<const std::uint16_t> aggregated, int width,
                                        int candidates, int unseen = 0);

/// The left-right check of one scan line: a left pixel x with disparity d is reliable (255)
/// when x - d lies inside the image and the right pixel's disparity is within `tolerance` of
/// d; otherwise (occluded, mismatched, outside the right image) it is 0. Returns the number of
/// reliable pixels. `right` holds -1 where no match reached a right pixel.
template <class Meter = NullMeter>
int check_left_right(std::span<const int> left, std::span<const int> right, int tolerance,
                     std::span<std::uint8_t> valid, Meter& meter = null_meter);

} // namespace marsokhod::nav
