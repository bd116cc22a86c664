// Brightness features stable under gain and offset: census and rank transforms.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <cstdint>
#include <memory_resource>
#include <optional>
#include <string_view>

namespace marsokhod::nav {

/// Brightness features that stay stable when one camera sees the scene with a different gain
/// and offset than the other: each describes a pixel only by the order of the grey levels around
/// it, so any strictly increasing grey-level mapping (a * I + b with a > 0) leaves it unchanged.
enum class FeatureKind : std::uint8_t {
  census3x3, ///< 8 bits: which of the 8 neighbours are darker than the centre
  census5x5, ///< 24 bits: which of the 24 pixels of the 5x5 window are darker than the centre
  rank5x5,   ///< 0..24: how many of the 24 pixels of the 5x5 window are darker than the centre
};

std::string_view to_string(FeatureKind kind);
/// "census3x3", "census5x5" or "rank5x5"; nothing for any other text.
std::optional<FeatureKind> parse_feature_kind(std::string_view text);

/// The feature of every pixel (census bits or rank); pixels outside the image repeat the
/// nearest border pixel, so they never count as darker.
template <class Meter = NullMeter>
imaging::Image<std::uint32_t>
brightness_features(imaging::ImageView<const std::uint8_t> image, FeatureKind kind,
                    Meter& meter = null_meter,
                    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// Distance between two features of the given kind: Hamming distance for census bits, absolute
/// difference for ranks.
int feature_distance(FeatureKind kind, std::uint32_t a, std::uint32_t b);

} // namespace marsokhod::nav
