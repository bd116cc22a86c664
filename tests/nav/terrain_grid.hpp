// Test support for the zone and planner tests: hand-made, map-like terrain.
#pragma once

// Hand-made terrain for the zone and planner tests: a map-like view in which pixel (x, y)
// sees the ground point `cell` metres per pixel from its neighbours, row 0 farthest, so that
// distances in pixels are distances in metres divided by the cell.

#include "marsokhod/nav/terrain/elevation.hpp"

#include <functional>

namespace marsokhod::nav::testing {

struct GridSpec {
  int width = 64;
  int height = 64;
  double cell_m = 0.05;
  double nearest_m = 2.0; ///< forward distance of the bottom row
};

/// The planner tests' view: 41 columns (column 20 straight ahead) by 208 rows on a 5 cm grid,
/// row 207 2.0 m ahead up to row 0 12.35 m ahead, reaching the 10-12 m target band.
inline GridSpec long_grid() {
  return GridSpec{41, 208, 0.05, 2.0};
}

/// Forward distance of row y and lateral offset of column x (left positive, centre column 0).
inline double grid_forward(const GridSpec& g, int y) {
  return g.nearest_m + g.cell_m * (g.height - 1 - y);
}
inline double grid_left(const GridSpec& g, int x) {
  return g.cell_m * ((g.width - 1) / 2 - x);
}

/// Elevation given by `height(forward, left)`; ranges set to match.
inline TerrainPoints grid_terrain(const GridSpec& g,
                                  const std::function<double(double, double)>& height) {
  TerrainPoints t{
      imaging::Image<float>(g.width, g.height), imaging::Image<float>(g.width, g.height),
      imaging::Image<float>(g.width, g.height), imaging::Image<float>(g.width, g.height), 0};
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) {
      const double forward = grid_forward(g, y);
      const double left = grid_left(g, x);
      t.forward(x, y) = static_cast<float>(forward);
      t.left(x, y) = static_cast<float>(left);
      t.elevation(x, y) = static_cast<float>(height(forward, left));
      t.range(x, y) = static_cast<float>(std::hypot(forward, left));
    }
  }
  t.known_pixels = static_cast<std::uint64_t>(g.width) * g.height;
  return t;
}

} // namespace marsokhod::nav::testing
