// The 3x3 census transform of one image row (private to the features and the matcher).
#pragma once

// The 3x3 census transform of one image row (private): shared by brightness_features() and
// the matcher's byte features, so both compute the same bits.

#include <cstdint>

namespace marsokhod::nav::detail {

/// out[x] for x in 0 .. width - 1: bit 7 - i is set when neighbour i of pixel x (raster order
/// over the 3x3 window, centre skipped) is darker than the pixel. The three rows are padded:
/// entries -1 and width exist (repeating the border).
void census3x3_row(const std::uint8_t* above, const std::uint8_t* here, const std::uint8_t* below,
                   int width, std::uint8_t* out);

} // namespace marsokhod::nav::detail
