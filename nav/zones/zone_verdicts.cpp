// Zone rule: every pixel's verdict from its ground-grid cell, in one pass.

#include "zones/zone_rules.hpp"

namespace marsokhod::nav::detail {
namespace {

// A cell some of whose points are steps and some perhaps not: each pixel takes its own test.
constexpr std::uint8_t kMixed = 0xFF;

// The verdict of a cell's pixels where the cell decides it: no point of the cell is a step when
// neither its lowest nor its highest point is one (the tests only grow away from the window),
// and then its pixels are all slopes, margins or traversable alike.
ScratchBuffer<std::uint8_t> cell_verdicts(const CellRules& rules,
                                          std::pmr::memory_resource* memory) {
  const std::size_t cells = rules.steep.size();
  ScratchBuffer<std::uint8_t> verdicts(cells, memory);
  for (std::size_t i = 0; i < cells; ++i) {
    if (rules.step[i] != 0) {
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

std::uint64_t judge_pixels(const GroundGrid& grid, const TerrainRows& terrain,
                           const CellRules& rules, float step_limit,
                           imaging::Image<std::uint8_t>& zone, std::pmr::memory_resource* memory) {
  const ScratchBuffer<std::uint8_t> verdicts = cell_verdicts(rules, memory);
  const auto step = static_cast<std::uint8_t>(Zone::step);
  const auto slope = static_cast<std::uint8_t>(Zone::slope);
  const auto margin = static_cast<std::uint8_t>(Zone::margin);
  const auto traversable = static_cast<std::uint8_t>(Zone::traversable);
  // In locals: a byte store may alias anything, and would make every member be read again.
  const std::uint8_t* verdict = verdicts.data();
  const float* highest = rules.window.highest.data();
  const float* lowest = rules.window.lowest.data();
  const std::uint8_t* steep = rules.steep.data();
  const std::uint8_t* near = rules.near.data();
  const int width = zone.width();
  const int nx = grid.nx();
  const bool whole = grid.own_begin() == 0 && grid.own_end() == nx;
  ScratchBuffer<std::int32_t> scratch(static_cast<std::size_t>(width), memory);
  std::uint64_t judged = 0;
  for (int y = 0; y < zone.height(); ++y) {
    const TerrainRows::Row points = terrain.row(y);
    std::uint8_t* row = zone.row(y);
    const std::int32_t* cells = grid.row_cells(y, points, row, scratch.data());
    const float* elevation = points.elevation;
    const auto judge = [&](int x) {
      if (cells[x] < 0 || (!whole && !grid.owns(cells[x] % nx)))
        return;
      ++judged;
      const auto i = static_cast<std::size_t>(cells[x]);
      if (verdict[i] != kMixed) {
        row[x] = verdict[i];
        return;
      }
      row[x] = is_step(highest[i], lowest[i], elevation[x], step_limit) ? step
               : steep[i] != 0                                          ? slope
               : near[i] != 0                                           ? margin
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
