// The right image's disparities from the left view's costs (private to the stereo matcher).
#pragma once

// The right image's disparities from the left view's aggregated costs (private to the stereo
// matcher), for the left-right check.

#include "matching/band_layout.hpp"

#include <cstdint>

namespace marsokhod::nav::detail {

/// For every right pixel r of each line of the band, the disparity d with the smallest
/// aggregated cost S(r + d, d) over the left pixels whose window holds d (the smaller d on a
/// tie), or -1 when no left pixel reaches r. `aggregated` holds S cell by cell as
/// BandDp::aggregated() leaves it; `disparity` and `best` have layout.width() x kBandRows
/// entries ([r * kBandRows + lane]); `best` is scratch. Returns the cells examined per line.
/// This is the right view of semi-global matching (Hirschmueller 2008, section 3.4): it sees
/// occlusions that a check of the left winners' claims alone cannot, since a mismatched left
/// pixel whose right pixel nobody else claims passes such a check. Left pixels x below
/// `unseen[lane]` (kBandRows entries; null for none) take no part: their scene lies outside the
/// right image (StereoOptions::unseen_columns), so no right pixel shows it.
std::uint64_t choose_right_view(const BandLayout& layout, const std::uint16_t* aggregated,
                                std::int16_t* disparity, std::int16_t* best,
                                const std::int16_t* unseen = nullptr);

} // namespace marsokhod::nav::detail
