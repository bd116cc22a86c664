// TerrainRows: the terrain as the zones and the path read it, one row at a time.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/terrain/elevation.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <memory_resource>
#include <vector>

namespace marsokhod::nav {

/// The level-frame points of the left image as the prohibited zones and the path read them:
/// row by row. ResidentTerrain holds every row (the native cycle, a node with room for the four
/// maps); RecomputedTerrain holds only the disparity and works a row out again each time one
/// is asked for (a node that cannot hold them), reporting that work as it goes.
class TerrainRows {
public:
  /// One row's points: forward, left, elevation and range of each column, +inf where unknown.
  struct Row {
    const float* forward = nullptr;
    const float* left = nullptr;
    const float* elevation = nullptr;
    const float* range = nullptr;

    bool known(int x) const { return std::isfinite(elevation[x]); }
  };

  TerrainRows(int width, int height, std::uint64_t known_pixels)
      : width_(width), height_(height), known_pixels_(known_pixels) {}
  TerrainRows(const TerrainRows&) = delete;
  TerrainRows& operator=(const TerrainRows&) = delete;
  virtual ~TerrainRows() = default;

  int width() const { return width_; }
  int height() const { return height_; }
  /// Pixels with a point (the same count reconstruct_terrain gives).
  std::uint64_t known_pixels() const { return known_pixels_; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  /// Row y, 0 <= y < height(); valid until the next call of row().
  virtual Row row(int y) const = 0;

private:
  int width_;
  int height_;
  std::uint64_t known_pixels_;
};

/// Every row of a TerrainPoints, read in place.
class ResidentTerrain final : public TerrainRows {
public:
  explicit ResidentTerrain(const TerrainPoints& terrain)
      : TerrainRows(terrain.width(), terrain.height(), terrain.known_pixels), terrain_(&terrain) {}
  Row row(int y) const override {
    return {terrain_->forward.row(y), terrain_->left.row(y), terrain_->elevation.row(y),
            terrain_->range.row(y)};
  }

private:
  const TerrainPoints* terrain_;
};

/// The terrain of a disparity map, one row at a time: each row asked for is converted again
/// from the disparity exactly as reconstruct_terrain converts it (so the same values), and the
/// conversion is reported to `meter` (Work::range_pixel and Work::elevation_pixel per point)
/// every time. Holds one row of points; the disparity, the rig and the meter must outlive it.
/// Throws std::invalid_argument for a disparity that does not fit the rig.
class RecomputedTerrain final : public TerrainRows {
public:
  RecomputedTerrain(imaging::ImageView<const float> disparity, const imaging::StereoRig& rig,
                    const imaging::Attitude& attitude, std::uint64_t known_pixels,
                    DynamicMeter& meter,
                    std::pmr::memory_resource* memory = std::pmr::get_default_resource());
  ~RecomputedTerrain() override;
  Row row(int y) const override;

private:
  struct Maker;
  imaging::ImageView<const float> disparity_;
  DynamicMeter* meter_;
  std::unique_ptr<Maker> maker_;
  mutable std::pmr::vector<float> points_; // forward, left, elevation, range of one row
  mutable int cached_ = -1;
};

/// The known points of a disparity map, as reconstruct_terrain counts them, without keeping
/// them; reported like reconstruct_terrain. Instantiated for NullMeter, CountingMeter and
/// DynamicMeter.
template <class Meter>
std::uint64_t count_terrain_points(imaging::ImageView<const float> disparity,
                                   const imaging::StereoRig& rig, const imaging::Attitude& attitude,
                                   Meter& meter, std::pmr::memory_resource* memory);

} // namespace marsokhod::nav
