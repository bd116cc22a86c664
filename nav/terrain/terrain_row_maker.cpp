// The level points of one row: every operation the scalar expression does, two lanes at a time.

#include "terrain/terrain_row_maker.hpp"

#include "lanes/path_lanes.hpp"
#include "terrain/terrain_rounding.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace marsokhod::nav::detail {
namespace {

constexpr float kUnmeasured = std::numeric_limits<float>::infinity();

// std::hypot rounded to float, without its cost on nearly every pixel: sqrt(x^2 + y^2) lies
// within a few double ulps of the exact value, as does hypot, so where every value within
// 1e-15 (relative) of it rounds to the same float, hypot's does too. Near a float rounding
// boundary, or where the squares might lose precision, hypot decides.
float ground_distance(double x, double y) {
  const double squared = x * x + y * y;
  if (!(squared > 1e-200 && squared < 1e200))
    return static_cast<float>(std::hypot(x, y));
  const double estimate = std::sqrt(squared);
  const auto rounded = static_cast<float>(estimate);
  if (static_cast<float>(estimate * (1.0 - 1e-15)) == rounded &&
      static_cast<float>(estimate * (1.0 + 1e-15)) == rounded)
    return rounded;
  return static_cast<float>(std::hypot(x, y));
}

// The level point seen at column u through a row's direction, as the scalar expression
//   origin + (B / d) * (row_direction + u * column_step)
// evaluates it, and its ground distance; false where the disparity gives no point.
bool level_point(const PixelGeometry& geometry, const Eigen::Vector3d& row_direction,
                 double baseline, int u, float d, float* point, float* range) {
  if (!(d > 0.0F) || !std::isfinite(d)) // NaN fails the first test
    return false;
  const Eigen::Vector3d level =
      geometry.origin + (baseline / d) * (row_direction + u * geometry.column_step);
  for (int axis = 0; axis < 3; ++axis)
    point[axis] = static_cast<float>(level[axis]);
  *range = ground_distance(level.x(), level.y());
  return true;
}

// ground_distance() of two lanes, hypot only where a known lane needs it (bit i of `known` set
// for a known lane i; the others may be nonsense).
detail::Floats2 ground_distances(Doubles2 x, Doubles2 y, int known) {
  const Doubles2 estimate = detail::lanes_sqrt(x * x + y * y);
  detail::Floats2 range = detail::narrowed(estimate);
  const int settled = detail::settled_roundings(estimate) | (~known & 3);
  if (settled == 3)
    return range;
  for (int lane = 0; lane < 2; ++lane)
    if ((settled & (1 << lane)) == 0)
      range[lane] = ground_distance(x[lane], y[lane]);
  return range;
}

// One row of the terrain, two columns at a time: every operation the one the scalar
// expression does, in the same order, so each lane rounds as level_point() would.
class RowConverter {
public:
  RowConverter(const PixelGeometry& geometry, const Eigen::Vector3d& row_direction, double baseline,
               float* const (&rows)[4])
      : geometry_(geometry), row_direction_(row_direction), baseline_(baseline), rows_(rows) {
    for (int axis = 0; axis < 3; ++axis) {
      origin_[axis] = detail::broadcast(geometry.origin[axis]);
      direction_[axis] = detail::broadcast(row_direction[axis]);
      step_[axis] = detail::broadcast(geometry.column_step[axis]);
    }
  }

  std::uint64_t convert(const float* disparity, int width) const {
    std::uint64_t converted = 0;
    int u = 0;
    // Columns as doubles, counted up exactly rather than converted at every pair.
    Doubles2 columns{0.0, 1.0};
    for (; u + 1 < width; u += 2, columns += detail::broadcast(2.0))
      converted += convert_pair(disparity, u, columns);
    if (u < width)
      converted += convert_one(disparity[u], u);
    return converted;
  }

private:
  std::uint64_t convert_one(float d, int u) const {
    float point[3];
    float range = 0.0F;
    if (!level_point(geometry_, row_direction_, baseline_, u, d, point, &range))
      return 0;
    for (int axis = 0; axis < 3; ++axis)
      rows_[axis][u] = point[axis];
    rows_[3][u] = range;
    return 1;
  }

  // Both lanes are computed and stored; an unknown one computes nonsense, which is then
  // overwritten with +inf (rarer than a select on every value).
  std::uint64_t convert_pair(const float* disparity, int u, Doubles2 columns) const {
    const Doubles2 d = detail::load_widened(disparity + u);
    const int known =
        detail::lane_bits(detail::both(d > Doubles2{}, d <= detail::broadcast(kLargest)));
    if (known == 0)
      return 0;
    const Doubles2 scale = detail::broadcast(baseline_) / d;
    Doubles2 level[3];
    for (int axis = 0; axis < 3; ++axis) {
      level[axis] = origin_[axis] + scale * (direction_[axis] + columns * step_[axis]);
      detail::store_floats(rows_[axis] + u, detail::narrowed(level[axis]));
    }
    detail::store_floats(rows_[3] + u, ground_distances(level[0], level[1], known));
    if (known == 3)
      return 2;
    const int unknown = known == 1 ? u + 1 : u;
    for (float* row : rows_)
      row[unknown] = kUnmeasured;
    return 1;
  }

  static constexpr double kLargest = std::numeric_limits<float>::max();
  const PixelGeometry& geometry_;
  const Eigen::Vector3d& row_direction_;
  double baseline_;
  float* const (&rows_)[4];
  Doubles2 origin_[3];
  Doubles2 direction_[3];
  Doubles2 step_[3];
};

} // namespace

std::uint64_t TerrainRowMaker::make(int v, const float* disparity, int width,
                                    float* const (&rows)[4]) const {
  const Eigen::Vector3d row_direction = geometry_.row_direction(v);
  return RowConverter(geometry_, row_direction, baseline_, rows).convert(disparity, width);
}

void check_disparity_fits(imaging::ImageView<const float> disparity, const imaging::StereoRig& rig,
                          const char* who) {
  if (disparity.width() != rig.width() || disparity.height() != rig.height() ||
      disparity.channels() != 1)
    throw std::invalid_argument(fmt::format(
        "{}: a {}x{} disparity map (channels {}) does not fit the {}x{} rig", who,
        disparity.width(), disparity.height(), disparity.channels(), rig.width(), rig.height()));
}

} // namespace marsokhod::nav::detail
