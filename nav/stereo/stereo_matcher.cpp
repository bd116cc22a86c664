// The stereo matcher: a pyramid of layers matched coarse to fine, then filled.

#include "stereo/stereo_checks.hpp"
#include "work/work_report.hpp"

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/features/layer_features.hpp"
#include "marsokhod/nav/features/pair_pyramid.hpp"
#include "marsokhod/nav/stereo/layered_matching.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"

#include <utility>

namespace marsokhod::nav {

template <class Meter>
StereoResult match_stereo(imaging::ImageView<const std::uint8_t> left,
                          imaging::ImageView<const std::uint8_t> right,
                          const StereoOptions& options, Meter& meter,
                          std::pmr::memory_resource* memory) {
  detail::check_pair(left, right, options);
  if (auto reason = uniform_pair_reason(left, right))
    return unmatched_stereo(left.width(), left.height(), std::move(*reason), memory);
  LayeredMatching matching(left.width(), left.height(), options, memory);
  const PairPyramid pyramid(left, right, matching.levels(), meter, memory);
  while (!matching.finished()) {
    const int level = matching.next_level();
    const imaging::ImageView<const std::uint8_t> left_layer =
        pyramid.layer(level, imaging::Eye::left);
    const LayerFeatures left_features = layer_features(left_layer, options.feature, meter, memory);
    const LayerFeatures right_features =
        layer_features(pyramid.layer(level, imaging::Eye::right), options.feature, meter, memory);
    matching.match_layer(left_layer, left_features, right_features, meter);
  }
  return matching.take_result();
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template StereoResult match_stereo<M>(imaging::ImageView<const std::uint8_t>,                    \
                                        imaging::ImageView<const std::uint8_t>,                    \
                                        const StereoOptions&, M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
