// Placing a cycle's zones on the ground, one point per map cell.
#include "marsokhod/eval/traverse/cycle_zones.hpp"

#include <cmath>
#include <cstdint>
#include <set>
#include <utility>

namespace marsokhod::eval {
namespace {

using Cell = std::pair<std::int64_t, std::int64_t>;

std::vector<Eigen::Vector2d> centres(const std::set<Cell>& cells, double cell_m) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(cells.size());
  for (const Cell& c : cells)
    points.emplace_back(static_cast<double>(c.first) * cell_m,
                        static_cast<double>(c.second) * cell_m);
  return points;
}

} // namespace

void book_zones(const world::RoverPlacement& placement, const nav::NavigationResult& navigation,
                double cell_m, TraverseCycle& cycle) {
  const nav::TerrainPoints& terrain = navigation.terrain;
  const nav::ZoneMap& zones = navigation.zones;
  if (zones.width() != terrain.width() || zones.height() != terrain.height())
    return; // a cycle that stopped before its zones
  std::set<Cell> seen;
  std::set<Cell> prohibited;
  for (int y = 0; y < terrain.height(); ++y)
    for (int x = 0; x < terrain.width(); ++x) {
      if (!std::isfinite(terrain.forward(x, y)) || !std::isfinite(terrain.left(x, y)))
        continue;
      const nav::Zone zone = zones.at(x, y);
      const bool hazard = zone == nav::Zone::step || zone == nav::Zone::slope;
      if (!hazard && zone != nav::Zone::traversable && zone != nav::Zone::margin)
        continue;
      const Eigen::Vector3d world = placement.level_to_world *
                                    Eigen::Vector3d(terrain.forward(x, y), terrain.left(x, y), 0.0);
      const Cell cell{std::llround(world.x() / cell_m), std::llround(world.y() / cell_m)};
      (hazard ? prohibited : seen).insert(cell);
    }
  for (const Cell& c : prohibited)
    seen.erase(c);
  cycle.seen = centres(seen, cell_m);
  cycle.prohibited = centres(prohibited, cell_m);
}

} // namespace marsokhod::eval
