// Zone rule: pixels whose ground distance breaks their column's order are marked unknown.

#include "zones/zone_buffer.hpp"
#include "zones/zone_bytes.hpp"
#include "zones/zone_rules.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

namespace marsokhod::nav::detail {
namespace {

// The judged pixels of columns first .. first + columns - 1, bottom row first, gathered row by
// row so that the image is read in memory order: column x holds count[x - first] entries from
// (x - first) * height on.
struct Columns {
  Columns(int first_column, int columns, int rows_per_column, std::pmr::memory_resource* memory)
      : first(first_column), height(rows_per_column),
        count(static_cast<std::size_t>(columns), 0, memory),
        rows(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows_per_column), memory),
        ranges(rows.size(), memory) {}

  void gather(const TerrainRows& terrain, const imaging::Image<std::uint8_t>& zone) {
    // Where the next entry of each column goes, in locals so that the stores to the columns
    // are not read as stores to them.
    const int end = first + static_cast<int>(count.size());
    std::pmr::vector<std::size_t> next(count.size(), count.get_allocator());
    for (int x = first; x < end; ++x)
      next[static_cast<std::size_t>(x - first)] = start(x);
    int* row_of = rows.data();
    float* range_of = ranges.data();
    for (int y = terrain.height() - 1; y >= 0; --y) {
      const std::uint8_t* judged = zone.row(y);
      const float* range = terrain.row(y).range;
      for (int x = first; x < end; ++x) {
        if (judged[x] == kUnknownZone)
          continue;
        const std::size_t at = next[static_cast<std::size_t>(x - first)]++;
        // Reading a row may let time pass, and an upset strike the column ends (occam's
        // range check on the subscript).
        if (at < start(x) || at >= start(x) + static_cast<std::size_t>(height))
          throw std::range_error("zones: a column's end in the ordering check was struck");
        row_of[at] = y;
        range_of[at] = range[x];
      }
    }
    for (int x = first; x < end; ++x)
      count[static_cast<std::size_t>(x - first)] =
          static_cast<int>(next[static_cast<std::size_t>(x - first)] - start(x));
  }
  std::size_t start(int x) const {
    return static_cast<std::size_t>(x - first) * static_cast<std::size_t>(height);
  }
  std::span<const float> ranges_of(int x) const {
    return {ranges.data() + start(x),
            static_cast<std::size_t>(count[static_cast<std::size_t>(x - first)])};
  }
  std::span<const int> rows_of(int x) const {
    return {rows.data() + start(x),
            static_cast<std::size_t>(count[static_cast<std::size_t>(x - first)])};
  }

  int first;
  int height;
  std::pmr::vector<int> count;
  ScratchBuffer<int> rows; // only the first count[x] of each column are written
  ScratchBuffer<float> ranges;
};

// The longest sequence of a column's pixels whose ground distance never decreases, by patience
// sorting: tails_[k] ends the best chain of k + 1 pixels found so far (the one with the smallest
// distance); equal distances may follow each other. Buffers are reused column after column.
class LongestChain {
public:
  explicit LongestChain(std::pmr::memory_resource* memory)
      : tails_(memory), tail_ranges_(memory), parent_(memory), kept_(memory) {}

  std::uint64_t find(std::span<const float> ranges) {
    const std::size_t n = ranges.size();
    tails_.resize(n);
    tail_ranges_.resize(n);
    parent_.resize(n);
    kept_.assign(n, 0);
    // One test for each pixel, and one against the end of the longest chain.
    std::uint64_t tests = 2 * static_cast<std::uint64_t>(n);
    std::size_t length = 0;
    int last = -1;            // the pixel ending the longest chain
    float longest_end = 0.0F; // and its distance
    for (std::size_t i = 0; i < n; ++i) {
      const float r = ranges[i];
      // Ground seen farther up the column usually extends the longest chain: test that first.
      if (length == 0 || longest_end <= r) {
        parent_[i] = last;
        tails_[length] = static_cast<int>(i);
        tail_ranges_[length++] = r;
        last = static_cast<int>(i);
        longest_end = r;
        continue;
      }
      const std::size_t at = first_end_beyond(r, length - 1, tests);
      parent_[i] = at == 0 ? -1 : tails_[at - 1];
      tails_[at] = static_cast<int>(i);
      tail_ranges_[at] = r;
      if (at + 1 < length)
        continue;
      last = static_cast<int>(i);
      longest_end = r;
    }
    for (int i = last; i >= 0; i = parent_[static_cast<std::size_t>(i)])
      kept_[static_cast<std::size_t>(i)] = 1;
    return tests;
  }

  bool kept(std::size_t i) const { return kept_[i] != 0; }

private:
  // The first of the chain ends 0 .. last farther than r (the last one is): r may follow every
  // end before it.
  std::size_t first_end_beyond(float r, std::size_t last, std::uint64_t& tests) const {
    std::size_t low = 0;
    std::size_t high = last;
    while (low < high) {
      const std::size_t mid = (low + high) / 2;
      ++tests;
      if (tail_ranges_[mid] <= r)
        low = mid + 1;
      else
        high = mid;
    }
    return low;
  }

  std::pmr::vector<int> tails_;
  std::pmr::vector<float> tail_ranges_; // the distance at each chain end, read without tails_
  std::pmr::vector<int> parent_;
  std::pmr::vector<std::uint8_t> kept_;
};

// Pixels off the chain that lie beyond the next chain pixel above them, or short of the last
// one below them, by more than the tolerance become unknown.
void mark_contradictions(const LongestChain& chain, std::span<const float> ranges,
                         std::span<const int> rows, double tolerance, int x,
                         imaging::Image<std::uint8_t>& zone) {
  const std::size_t n = ranges.size();
  double below = -1.0;
  std::size_t next = 0; // the first chain pixel at or above pixel i
  for (std::size_t i = 0; i < n; ++i) {
    if (chain.kept(i)) {
      below = ranges[i];
      continue;
    }
    next = std::max(next, i);
    while (next < n && !chain.kept(next))
      ++next;
    const double r = ranges[i];
    const bool too_far = next < n && r > ranges[next] * (1.0 + tolerance) + kOrderSlack_m;
    const bool too_near = below >= 0.0 && r < below * (1.0 - tolerance) - kOrderSlack_m;
    if (!too_far && !too_near)
      continue;
    if (rows[i] < 0 || rows[i] >= zone.height())
      throw std::range_error("zones: a pixel's row in the ordering check was struck");
    zone(x, rows[i]) = kUnknownZone;
  }
}

} // namespace

std::uint64_t mark_out_of_order(const TerrainRows& terrain, const ZoneOptions& options,
                                imaging::Image<std::uint8_t>& zone,
                                std::pmr::memory_resource* memory, int band_columns) {
  if (options.order_tolerance <= 0.0)
    return 0;
  const int width = zone.width();
  const int band = band_columns > 0 ? std::min(band_columns, width) : width;
  LongestChain chain(memory);
  std::uint64_t tests = 0;
  for (int first = 0; first < width; first += band) {
    Columns columns(first, std::min(band, width - first), zone.height(), memory);
    columns.gather(terrain, zone);
    for (int x = first; x < first + static_cast<int>(columns.count.size()); ++x) {
      tests += chain.find(columns.ranges_of(x));
      mark_contradictions(chain, columns.ranges_of(x), columns.rows_of(x), options.order_tolerance,
                          x, zone);
    }
  }
  return tests;
}

} // namespace marsokhod::nav::detail
