// Terrain rows worked out again from the disparity, and the known points counted without
// keeping them.

#include "marsokhod/nav/terrain/terrain_rows.hpp"

#include "terrain/terrain_row_maker.hpp"
#include "work/work_report.hpp"

#include <algorithm>
#include <limits>
#include <memory>

namespace marsokhod::nav {
namespace {

constexpr float kNoPoint = std::numeric_limits<float>::infinity();

// The four planes of one row in `points`, each +inf (unknown) until converted.
void clear_planes(std::pmr::vector<float>& points, int width, float* (&rows)[4]) {
  std::fill(points.begin(), points.end(), kNoPoint);
  for (int plane = 0; plane < 4; ++plane)
    rows[plane] = points.data() + static_cast<std::ptrdiff_t>(plane) * width;
}

} // namespace

struct RecomputedTerrain::Maker {
  detail::TerrainRowMaker rows;
};

RecomputedTerrain::RecomputedTerrain(imaging::ImageView<const float> disparity,
                                     const imaging::StereoRig& rig,
                                     const imaging::Attitude& attitude, std::uint64_t known_pixels,
                                     DynamicMeter& meter, std::pmr::memory_resource* memory)
    : TerrainRows(disparity.width(), disparity.height(), known_pixels), disparity_(disparity),
      meter_(&meter),
      maker_((detail::check_disparity_fits(disparity, rig, "RecomputedTerrain"),
              std::make_unique<Maker>(Maker{detail::TerrainRowMaker(rig, attitude)}))),
      points_(static_cast<std::size_t>(disparity.width()) * 4, kNoPoint, memory) {}

RecomputedTerrain::~RecomputedTerrain() = default;

TerrainRows::Row RecomputedTerrain::row(int y) const {
  if (y != cached_) {
    float* rows[4];
    clear_planes(points_, width(), rows);
    const std::uint64_t converted = maker_->rows.make(y, disparity_.row(y), width(), rows);
    (*meter_)(Work::range_pixel, converted);
    (*meter_)(Work::elevation_pixel, converted);
    cached_ = y;
  }
  const float* at = points_.data();
  const auto stride = static_cast<std::ptrdiff_t>(width());
  return {at, at + stride, at + 2 * stride, at + 3 * stride};
}

template <class Meter>
std::uint64_t count_terrain_points(imaging::ImageView<const float> disparity,
                                   const imaging::StereoRig& rig, const imaging::Attitude& attitude,
                                   Meter& meter, std::pmr::memory_resource* memory) {
  detail::check_disparity_fits(disparity, rig, "count_terrain_points");
  const detail::TerrainRowMaker maker(rig, attitude);
  std::pmr::vector<float> points(static_cast<std::size_t>(disparity.width()) * 4, kNoPoint, memory);
  std::uint64_t known = 0;
  for (int v = 0; v < disparity.height(); ++v) {
    float* rows[4];
    clear_planes(points, disparity.width(), rows);
    const std::uint64_t converted = maker.make(v, disparity.row(v), disparity.width(), rows);
    detail::report(meter, Work::range_pixel, converted);
    detail::report(meter, Work::elevation_pixel, converted);
    known += converted;
  }
  return known;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template std::uint64_t count_terrain_points<M>(                                                  \
      imaging::ImageView<const float>, const imaging::StereoRig&, const imaging::Attitude&, M&,    \
      std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
