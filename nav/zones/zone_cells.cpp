// Zone rule: a verdict written onto the traversable pixels of flagged ground-grid cells.

#include "zones/zone_rules.hpp"

namespace marsokhod::nav::detail {

void mark_flagged_cells(const GroundGrid& grid, const CellFlags& flagged, Zone verdict,
                        imaging::Image<std::uint8_t>& zone) {
  const auto traversable = static_cast<std::uint8_t>(Zone::traversable);
  const std::ptrdiff_t channels = zone.channels();
  for (int y = 0; y < zone.height(); ++y) {
    const std::int32_t* cells = grid.cells_of_row(y);
    std::uint8_t* row = zone.row(y);
    for (int x = 0; x < zone.width(); ++x) {
      const std::int32_t cell = cells[x];
      std::uint8_t& pixel = row[x * channels];
      if (cell >= 0 && flagged[static_cast<std::size_t>(cell)] != 0 && pixel == traversable)
        pixel = static_cast<std::uint8_t>(verdict);
    }
  }
}

} // namespace marsokhod::nav::detail
