// A pyramid layer's brightness features in the matcher's storage (private).

#include "marsokhod/nav/features/layer_features.hpp"

#include "features/census_rows.hpp"
#include "work/work_report.hpp"

#include <algorithm>
#include <array>

namespace marsokhod::nav {
namespace {

// The census bytes of every pixel; three padded rows take turns so that each image row is
// copied once.
template <class Meter>
imaging::Image<std::uint8_t> census3x3_bytes(imaging::ImageView<const std::uint8_t> image,
                                             Meter& meter, std::pmr::memory_resource* memory) {
  const int width = image.width();
  const int height = image.height();
  imaging::Image<std::uint8_t> bytes(width, height, 1, 0, memory);
  const auto padded = static_cast<std::size_t>(width + 2);
  std::pmr::vector<std::uint8_t> buffer(3 * padded, 0, memory);
  // Row y (clamped to the image) is held in slot y mod 3, for y from -1 on.
  const auto slot = [&](int y) {
    return buffer.data() + static_cast<std::size_t>((y + 3) % 3) * padded;
  };
  const auto load = [&](int y) {
    const std::uint8_t* source = image.row(std::clamp(y, 0, height - 1));
    std::uint8_t* target = slot(y);
    std::copy(source, source + width, target + 1);
    target[0] = source[0];
    target[width + 1] = source[width - 1];
  };
  load(-1);
  load(0);
  for (int y = 0; y < height; ++y) {
    load(y + 1);
    detail::census3x3_row(slot(y - 1) + 1, slot(y) + 1, slot(y + 1) + 1, width, bytes.row(y));
    detail::report(meter, Work::feature_pixel, static_cast<std::uint64_t>(width));
  }
  return bytes;
}

} // namespace

template <class Meter>
LayerFeatures layer_features(imaging::ImageView<const std::uint8_t> image, FeatureKind kind,
                             Meter& meter, std::pmr::memory_resource* memory) {
  LayerFeatures features{kind, imaging::Image<std::uint8_t>(memory),
                         imaging::Image<std::uint32_t>(memory)};
  if (kind != FeatureKind::census3x3) {
    features.words = brightness_features(image, kind, meter, memory);
    return features;
  }
  if (image.empty())
    return features;
  features.bytes = census3x3_bytes(image, meter, memory);
  return features;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template LayerFeatures layer_features<M>(imaging::ImageView<const std::uint8_t>, FeatureKind,    \
                                           M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
