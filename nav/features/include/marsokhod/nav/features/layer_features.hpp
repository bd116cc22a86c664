// LayerFeatures: a pyramid layer's brightness features in the compact form the matcher reads.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/features/brightness_features.hpp"

#include <cstdint>
#include <memory_resource>

namespace marsokhod::nav {

/// A pyramid layer's brightness features as the stereo matcher reads them: what a features
/// process hands to a matching process. census3x3 keeps its 8 bits in one byte a pixel, a quarter
/// of the memory the 32-bit features of brightness_features() take; the wider kinds keep those.
struct LayerFeatures {
  FeatureKind kind = FeatureKind::census3x3;
  imaging::Image<std::uint8_t> bytes;  ///< census3x3
  imaging::Image<std::uint32_t> words; ///< census5x5, rank5x5
};

/// The same features as brightness_features(), reported to the meter the same way.
/// Instantiated for NullMeter, CountingMeter and DynamicMeter.
template <class Meter>
LayerFeatures layer_features(imaging::ImageView<const std::uint8_t> image, FeatureKind kind,
                             Meter& meter, std::pmr::memory_resource* memory);

} // namespace marsokhod::nav
