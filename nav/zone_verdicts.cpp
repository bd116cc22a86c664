#include "zone_rules.hpp"

namespace marsokhod::nav::detail {
namespace {

// A cell some of whose points are steps and some perhaps not: each pixel takes its own test.
constexpr std::uint8_t kMixed = 0xFF;

// The verdict of a cell's pixels where the cell decides it: no point of the cell is a step when
// neither its lowest nor its highest point is one (the tests only grow away from the window),
// and then its pixels are all slopes, margins or traversable alike.
ScratchBuffer<std::uint8_t> cell_verdicts(const GroundGrid& grid, const CellRules& rules,
                                          float step_limit, std::pmr::memory_resource* memory) {
  const std::size_t cells = rules.steep.size();
  ScratchBuffer<std::uint8_t> verdicts(cells, memory);
  for (std::size_t i = 0; i < cells; ++i) {
    const float high = rules.window.highest[i];
    const float low = rules.window.lowest[i];
    if (is_step(high, low, grid.lowest()[i], step_limit) ||
        is_step(high, low, grid.highest()[i], step_limit)) {
      verdicts[i] = kMixed;
      continue;
    }
    const Zone otherwise = rules.steep[i] != 0  ? Zone::slope
                           : rules.near[i] != 0 ? Zone::margin
                                                : Zone::traversable;
    verdicts[i] = static_cast<std::uint8_t>(otherwise);
  }
  return verdicts;
}

} // namespace

std::uint64_t judge_pixels(const GroundGrid& grid, const TerrainPoints& terrain,
                           const CellRules& rules, float step_limit, Image<std::uint8_t>& zone,
                           std::pmr::memory_resource* memory) {
  const ScratchBuffer<std::uint8_t> verdicts = cell_verdicts(grid, rules, step_limit, memory);
  const auto step = static_cast<std::uint8_t>(Zone::step);
  const auto slope = static_cast<std::uint8_t>(Zone::slope);
  const auto margin = static_cast<std::uint8_t>(Zone::margin);
  const auto traversable = static_cast<std::uint8_t>(Zone::traversable);
  const int width = zone.width();
  std::uint64_t judged = 0;
  for (int y = 0; y < zone.height(); ++y) {
    const std::int32_t* cells = grid.cells_of_row(y);
    const float* elevation = terrain.elevation.row(y);
    std::uint8_t* row = zone.row(y);
    const auto judge = [&](int x) {
      if (cells[x] < 0)
        return;
      ++judged;
      const auto i = static_cast<std::size_t>(cells[x]);
      if (verdicts[i] != kMixed) {
        row[x] = verdicts[i];
        return;
      }
      row[x] = is_step(rules.window.highest[i], rules.window.lowest[i], elevation[x], step_limit)
                   ? step
               : rules.steep[i] != 0 ? slope
               : rules.near[i] != 0  ? margin
                                     : traversable;
    };
    int x = 0;
    // Pixels that were not binned come in runs (the sky, the strip only the left camera sees):
    // four of them at once have all their sign bits set.
    for (; x + 4 <= width; x += 4) {
      if ((cells[x] & cells[x + 1] & cells[x + 2] & cells[x + 3]) < 0)
        continue;
      for (int k = x; k < x + 4; ++k)
        judge(k);
    }
    for (; x < width; ++x)
      judge(x);
  }
  return 2 * judged;
}

} // namespace marsokhod::nav::detail
