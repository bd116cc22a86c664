#include "zone_rules.hpp"

namespace marsokhod::nav::detail {
namespace {

// What a cell's pixels need besides their own height, side by side so that a pixel reads one
// place: the step window and the verdict of a pixel that is no step.
struct CellVerdict {
  float highest;
  float lowest;
  std::uint8_t otherwise;
};

ScratchBuffer<CellVerdict> cell_verdicts(const CellRules& rules,
                                         std::pmr::memory_resource* memory) {
  const std::size_t cells = rules.steep.size();
  ScratchBuffer<CellVerdict> verdicts(cells, memory);
  for (std::size_t i = 0; i < cells; ++i) {
    const Zone otherwise = rules.steep[i] != 0  ? Zone::slope
                           : rules.near[i] != 0 ? Zone::margin
                                                : Zone::traversable;
    verdicts[i] = {rules.window.highest[i], rules.window.lowest[i],
                   static_cast<std::uint8_t>(otherwise)};
  }
  return verdicts;
}

} // namespace

std::uint64_t judge_pixels(const GroundGrid& grid, const TerrainPoints& terrain,
                           const CellRules& rules, float step_limit, Image<std::uint8_t>& zone,
                           std::pmr::memory_resource* memory) {
  const ScratchBuffer<CellVerdict> verdicts = cell_verdicts(rules, memory);
  const auto step = static_cast<std::uint8_t>(Zone::step);
  std::uint64_t judged = 0;
  for (int y = 0; y < zone.height(); ++y) {
    const std::int32_t* cells = grid.cells_of_row(y);
    const float* elevation = terrain.elevation.row(y);
    std::uint8_t* row = zone.row(y);
    for (int x = 0; x < zone.width(); ++x) {
      if (cells[x] < 0)
        continue;
      const CellVerdict& v = verdicts[static_cast<std::size_t>(cells[x])];
      row[x] = is_step(v.highest, v.lowest, elevation[x], step_limit) ? step : v.otherwise;
      ++judged;
    }
  }
  return 2 * judged;
}

} // namespace marsokhod::nav::detail
