// Range and elevation: the level-frame point of every pixel from its disparity and the rig.

#include "marsokhod/nav/terrain/elevation.hpp"

#include "terrain/terrain_row_maker.hpp"
#include "work/work_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace marsokhod::nav {
namespace {

constexpr float kUnknownPoint = std::numeric_limits<float>::infinity();

TerrainPoints unknown_terrain(int width, int height, std::pmr::memory_resource* memory) {
  TerrainPoints terrain{imaging::Image<float>(width, height, 1, kUnknownPoint, memory),
                        imaging::Image<float>(width, height, 1, kUnknownPoint, memory),
                        imaging::Image<float>(width, height, 1, kUnknownPoint, memory),
                        imaging::Image<float>(width, height, 1, kUnknownPoint, memory), 0};
  return terrain;
}

} // namespace

template <class Meter>
TerrainPoints reconstruct_terrain(imaging::ImageView<const float> disparity,
                                  const imaging::StereoRig& rig, const imaging::Attitude& attitude,
                                  Meter& meter, std::pmr::memory_resource* memory) {
  detail::check_disparity_fits(disparity, rig, "reconstruct_terrain");
  const int width = disparity.width();
  const int height = disparity.height();
  TerrainPoints terrain = unknown_terrain(width, height, memory);
  const detail::TerrainRowMaker maker(rig, attitude);
  for (int v = 0; v < height; ++v) {
    float* const rows[4] = {terrain.forward.row(v), terrain.left.row(v), terrain.elevation.row(v),
                            terrain.range.row(v)};
    const std::uint64_t converted = maker.make(v, disparity.row(v), width, rows);
    detail::report(meter, Work::range_pixel, converted);
    detail::report(meter, Work::elevation_pixel, converted);
    terrain.known_pixels += converted;
  }
  return terrain;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template TerrainPoints reconstruct_terrain<M>(                                                   \
      imaging::ImageView<const float>, const imaging::StereoRig&, const imaging::Attitude&, M&,    \
      std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
