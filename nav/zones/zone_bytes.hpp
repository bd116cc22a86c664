// The zone map's bytes and the bound of an empty cell, as the zone stages compare them (private
// to the zones room).
#pragma once

#include "marsokhod/nav/zones/zones.hpp"

#include <cstdint>
#include <limits>

namespace marsokhod::nav::detail {

inline constexpr auto kUnknownZone = static_cast<std::uint8_t>(Zone::unknown);
inline constexpr auto kTraversableZone = static_cast<std::uint8_t>(Zone::traversable);
/// The height bounds of a cell nothing was binned into start from +-infinity.
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

} // namespace marsokhod::nav::detail
