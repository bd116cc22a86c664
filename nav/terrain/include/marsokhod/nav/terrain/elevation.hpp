// Range and elevation: the visible terrain's level-frame points from a disparity map.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <cmath>
#include <cstdint>
#include <memory_resource>

namespace marsokhod::nav {

/// The visible terrain in front of the rover: the level-frame point seen at every pixel of the
/// left image (docs/navigation.md, "Range and elevation"). Unknown pixels (no disparity, or a
/// disparity of zero or less) hold +inf in every field, as Middlebury PFM files do.
struct TerrainPoints {
  imaging::Image<float> forward; ///< level x, metres ahead of the rover centre along its heading
  imaging::Image<float> left;    ///< level y, metres to the left
  imaging::Image<float>
      elevation;               ///< level z: height above the horizontal plane under the rover, m
  imaging::Image<float> range; ///< ground (horizontal) distance from the rover centre, m
  std::uint64_t known_pixels = 0;

  int width() const { return elevation.width(); }
  int height() const { return elevation.height(); }
  bool known(int x, int y) const { return std::isfinite(elevation(x, y)); }
};

/// Turns a disparity map of the left image (x_right = x_left - d, +inf or d <= 0 unknown) into
/// level-frame points through the rig and the rover's measured attitude: the camera pitch is in
/// the rig, the rover's pitch and roll in `attitude`. The disparity must have the rig's size
/// (std::invalid_argument otherwise); NaN counts as unknown. Buffers come from `memory`; work
/// is reported per converted pixel (Work::range_pixel and Work::elevation_pixel).
/// Instantiated for NullMeter, CountingMeter and DynamicMeter.
template <class Meter = NullMeter>
TerrainPoints
reconstruct_terrain(imaging::ImageView<const float> disparity, const imaging::StereoRig& rig,
                    const imaging::Attitude& attitude, Meter& meter = null_meter,
                    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
