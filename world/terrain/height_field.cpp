// The height field's grid, and the nodes around a point within a reach.

#include "marsokhod/world/terrain/height_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace marsokhod::world {

HeightField::HeightField(int nx, int ny, double cell_m, Eigen::Vector2d origin)
    : cell_m_(cell_m), origin_(origin) {
  if (nx < 2 || ny < 2)
    throw std::invalid_argument("HeightField: the grid needs at least 2 x 2 nodes");
  if (!(cell_m > 0.0) || !std::isfinite(cell_m))
    throw std::invalid_argument("HeightField: cell size must be positive and finite");
  if (!origin.allFinite())
    throw std::invalid_argument("HeightField: origin must be finite");
  heights_ = imaging::Image<float>(nx, ny, 1, 0.0f);
  inv_cell_ = 1.0 / cell_m;
}

NodeRange nodes_around(const HeightField& height, const Eigen::Vector2d& centre, double reach) {
  const Eigen::Vector2d low = (centre.array() - reach - height.origin().array()) / height.cell_m();
  const Eigen::Vector2d high = (centre.array() + reach - height.origin().array()) / height.cell_m();
  // Clamp in floating point first so that far-away squares cannot overflow an int.
  const auto index = [](double u, int last) {
    return static_cast<int>(std::clamp(u, -1.0, static_cast<double>(last) + 1.0));
  };
  NodeRange range;
  range.i0 = std::max(0, index(std::floor(low.x()), height.nx() - 1));
  range.i1 = std::min(height.nx() - 1, index(std::ceil(high.x()), height.nx() - 1));
  range.j0 = std::max(0, index(std::floor(low.y()), height.ny() - 1));
  range.j1 = std::min(height.ny() - 1, index(std::ceil(high.y()), height.ny() - 1));
  return range;
}

} // namespace marsokhod::world
