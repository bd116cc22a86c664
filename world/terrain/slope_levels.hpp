// Slope bounds of the terrain per quadtree block (private to the renderer's ray casting).
#pragma once

#include "marsokhod/world/terrain/height_field.hpp"

#include <vector>

namespace marsokhod::world {

/// Lipschitz bounds of the bilinear surface, for the whole grid and per quadtree block.
struct SlopeLevels {
  /// No two surface points differ in height by more than this times their ground distance.
  double steepest = 0.0;
  /// levels[k][by * width + bx]: a Lipschitz bound of the surface over block (bx, by) of level
  /// first_level + k (2^level cells a side) widened by one cell on every side, so that it also
  /// holds for a ground segment that starts over the block and is no longer than a cell. Rows
  /// are as wide as the maximum mipmap's levels.
  std::vector<std::vector<float>> levels;
};

/// The bounds from first_level up to the single block covering the grid.
SlopeLevels slope_levels(const HeightField& height, int first_level);

} // namespace marsokhod::world
