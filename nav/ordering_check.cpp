#include "zone_rules.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace marsokhod::nav::detail {
namespace {

constexpr auto kUnknown = static_cast<std::uint8_t>(Zone::unknown);

// One column's judged pixels from the bottom row up, the longest run of them whose ground
// distance never decreases, and the buffers for finding it; reused column after column.
class ColumnOrder {
public:
  explicit ColumnOrder(std::pmr::memory_resource* memory)
      : rows_(memory), ranges_(memory), tails_(memory), parent_(memory), kept_(memory) {}

  void load(const TerrainPoints& terrain, const Image<std::uint8_t>& zone, int x) {
    rows_.clear();
    ranges_.clear();
    for (int y = terrain.height() - 1; y >= 0; --y) {
      if (zone(x, y) == kUnknown)
        continue;
      rows_.push_back(y);
      ranges_.push_back(terrain.range(x, y));
    }
  }

  // Patience sorting: tails_[k] is the pixel ending the best chain of k + 1 pixels found so
  // far (the one with the smallest distance); equal distances may follow each other.
  std::uint64_t find_longest_chain() {
    const std::size_t n = ranges_.size();
    tails_.clear();
    parent_.assign(n, -1);
    kept_.assign(n, 0);
    std::uint64_t tests = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const float r = ranges_[i];
      const auto place = std::upper_bound(tails_.begin(), tails_.end(), r, [&](float v, int t) {
        ++tests;
        return v < ranges_[static_cast<std::size_t>(t)];
      });
      parent_[i] = place == tails_.begin() ? -1 : *(place - 1);
      if (place == tails_.end())
        tails_.push_back(static_cast<int>(i));
      else
        *place = static_cast<int>(i);
    }
    for (int i = tails_.empty() ? -1 : tails_.back(); i >= 0;
         i = parent_[static_cast<std::size_t>(i)])
      kept_[static_cast<std::size_t>(i)] = 1;
    return tests + n;
  }

  // Pixels off the chain that lie beyond the next chain pixel above them, or short of the
  // last one below them, by more than the tolerance become unknown.
  void mark_contradictions(double tolerance, int x, Image<std::uint8_t>& zone) const {
    const std::size_t n = ranges_.size();
    float below = -1.0F;
    std::size_t next = 0; // first chain pixel at or above i
    for (std::size_t i = 0; i < n; ++i) {
      if (kept_[i] != 0) {
        below = ranges_[i];
        continue;
      }
      next = std::max(next, i);
      while (next < n && kept_[next] == 0)
        ++next;
      const double r = ranges_[i];
      const bool too_far = next < n && r > ranges_[next] * (1.0 + tolerance) + kOrderSlack_m;
      const bool too_near = below >= 0.0F && r < below * (1.0 - tolerance) - kOrderSlack_m;
      if (too_far || too_near)
        zone(x, rows_[i]) = kUnknown;
    }
  }

private:
  std::pmr::vector<int> rows_;
  std::pmr::vector<float> ranges_;
  std::pmr::vector<int> tails_;
  std::pmr::vector<int> parent_;
  std::pmr::vector<std::uint8_t> kept_;
};

} // namespace

std::uint64_t mark_out_of_order(const TerrainPoints& terrain, const ZoneOptions& options,
                                Image<std::uint8_t>& zone, std::pmr::memory_resource* memory) {
  if (options.order_tolerance <= 0.0)
    return 0;
  ColumnOrder column(memory);
  std::uint64_t tests = 0;
  for (int x = 0; x < zone.width(); ++x) {
    column.load(terrain, zone, x);
    tests += column.find_longest_chain();
    column.mark_contradictions(options.order_tolerance, x, zone);
  }
  return tests;
}

} // namespace marsokhod::nav::detail
