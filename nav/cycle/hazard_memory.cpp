// Keeping the hazards of the last cycles and giving them back in the current rover frame.
#include "marsokhod/nav/cycle/hazard_memory.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace marsokhod::nav {

HazardMemory::HazardMemory(int cycles, double cell_m) : kept_(cycles), cell_m_(cell_m) {
  if (cycles < 1)
    throw std::invalid_argument(
        fmt::format("hazard memory: cycles = {} must be at least 1", cycles));
  if (!(cell_m > 0.0) || !std::isfinite(cell_m))
    throw std::invalid_argument(
        fmt::format("hazard memory: cell_m = {} must be finite and positive", cell_m));
}

void HazardMemory::remember(const TerrainPoints& terrain, const ZoneMap& zones,
                            const imaging::PlanarPose& pose) {
  const double c = std::cos(pose.heading_rad);
  const double s = std::sin(pose.heading_rad);
  std::set<Cell> cells;
  for (int y = 0; y < terrain.height(); ++y)
    for (int x = 0; x < terrain.width(); ++x) {
      const Zone zone = zones.at(x, y);
      if ((zone != Zone::step && zone != Zone::slope) || !terrain.known(x, y))
        continue;
      const double ahead = terrain.forward(x, y);
      const double left = terrain.left(x, y);
      const double wx = pose.x + ahead * c - left * s;
      const double wy = pose.y + ahead * s + left * c;
      cells.emplace(std::llround(wx / cell_m_), std::llround(wy / cell_m_));
    }
  cycles_.push_back(std::move(cells));
  while (static_cast<int>(cycles_.size()) > kept_)
    cycles_.pop_front();
}

std::vector<GroundPoint> HazardMemory::recall(const imaging::PlanarPose& pose,
                                              double radius_m) const {
  std::set<Cell> cells;
  for (const std::set<Cell>& cycle : cycles_)
    cells.insert(cycle.begin(), cycle.end());
  const double c = std::cos(pose.heading_rad);
  const double s = std::sin(pose.heading_rad);
  std::vector<GroundPoint> points;
  for (const Cell& cell : cells) {
    const double dx = static_cast<double>(cell.first) * cell_m_ - pose.x;
    const double dy = static_cast<double>(cell.second) * cell_m_ - pose.y;
    if (dx * dx + dy * dy > radius_m * radius_m)
      continue;
    points.push_back({dx * c + dy * s, -dx * s + dy * c});
  }
  return points;
}

} // namespace marsokhod::nav
