#include "zone_rules.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace marsokhod::nav::detail {
namespace {

constexpr auto kUnknown = static_cast<std::uint8_t>(Zone::unknown);

// The longest sequence of each column's judged pixels, read from the bottom row up, whose
// ground distance never decreases, by patience sorting run on every column at once, row by
// row, so that the images are read in memory order: column x's chain ends are tails[x * height
// + k], the end of the best chain of k + 1 pixels so far (the one with the smallest distance).
// Ground that simply recedes extends the longest chain, which costs one comparison against
// `last`, kept per column in one short array.
class ColumnChains {
public:
  ColumnChains(const TerrainPoints& terrain, std::pmr::memory_resource* memory)
      : terrain_(terrain), width_(terrain.width()), height_(terrain.height()),
        parent_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), -1, memory),
        tails_(parent_.size(), -1, memory), length_(static_cast<std::size_t>(width_), 0, memory),
        last_(static_cast<std::size_t>(width_), 0.0F, memory),
        kept_(width_, height_, 1, 0, memory) {}

  std::uint64_t build(const Image<std::uint8_t>& zone) {
    std::uint64_t tests = 0;
    for (int y = height_ - 1; y >= 0; --y) {
      const std::uint8_t* judged = zone.row(y);
      const float* range = terrain_.range.row(y);
      for (int x = 0; x < width_; ++x) {
        if (judged[x] == kUnknown)
          continue;
        tests += add(x, y * width_ + x, range[x]);
      }
    }
    for (int x = 0; x < width_; ++x) {
      const int n = length_[static_cast<std::size_t>(x)];
      for (int p = n == 0 ? -1 : tail(x, n - 1); p >= 0; p = parent_[static_cast<std::size_t>(p)])
        kept_.data()[p] = 1;
    }
    return tests;
  }

  bool kept(int x, int y) const { return kept_(x, y) != 0; }

private:
  int& tail(int x, int k) {
    return tails_[static_cast<std::size_t>(x) * static_cast<std::size_t>(height_) +
                  static_cast<std::size_t>(k)];
  }
  float range_of(int pixel) const { return terrain_.range.data()[pixel]; }

  // Adds pixel p (column x, distance r) to its column's chains; returns the comparisons made.
  std::uint64_t add(int x, int p, float r) {
    const auto column = static_cast<std::size_t>(x);
    int& n = length_[column];
    if (n == 0 || last_[column] <= r) {
      parent_[static_cast<std::size_t>(p)] = n == 0 ? -1 : tail(x, n - 1);
      tail(x, n++) = p;
      last_[column] = r;
      return 1;
    }
    // The first chain end farther than r: r may follow every end before it.
    std::uint64_t tests = 1;
    int low = 0;
    int high = n - 1;
    while (low < high) {
      const int mid = (low + high) / 2;
      ++tests;
      if (range_of(tail(x, mid)) <= r)
        low = mid + 1;
      else
        high = mid;
    }
    parent_[static_cast<std::size_t>(p)] = low == 0 ? -1 : tail(x, low - 1);
    tail(x, low) = p;
    if (low == n - 1)
      last_[column] = r;
    return tests;
  }

  const TerrainPoints& terrain_;
  int width_;
  int height_;
  std::pmr::vector<int> parent_;
  std::pmr::vector<int> tails_;
  std::pmr::vector<int> length_;
  std::pmr::vector<float> last_;
  Image<std::uint8_t> kept_;
};

} // namespace

std::uint64_t mark_out_of_order(const TerrainPoints& terrain, const ZoneOptions& options,
                                Image<std::uint8_t>& zone, std::pmr::memory_resource* memory) {
  if (options.order_tolerance <= 0.0)
    return 0;
  ColumnChains chains(terrain, memory);
  std::uint64_t tests = chains.build(zone);
  const double tolerance = options.order_tolerance;
  const int width = zone.width();
  // The distance of the nearest chain pixel already passed in each column, -1 for none: below
  // the pixel on the way up, above it on the way down.
  std::pmr::vector<float> passed(static_cast<std::size_t>(width), -1.0F, memory);
  for (int y = zone.height() - 1; y >= 0; --y) {
    std::uint8_t* judged = zone.row(y);
    const float* range = terrain.range.row(y);
    for (int x = 0; x < width; ++x) {
      if (judged[x] == kUnknown)
        continue;
      float& below = passed[static_cast<std::size_t>(x)];
      if (chains.kept(x, y)) {
        below = range[x];
        continue;
      }
      ++tests;
      if (below >= 0.0F && range[x] < below * (1.0 - tolerance) - kOrderSlack_m)
        judged[x] = kUnknown;
    }
  }
  std::fill(passed.begin(), passed.end(), -1.0F);
  for (int y = 0; y < zone.height(); ++y) {
    std::uint8_t* judged = zone.row(y);
    const float* range = terrain.range.row(y);
    for (int x = 0; x < width; ++x) {
      if (judged[x] == kUnknown)
        continue;
      float& above = passed[static_cast<std::size_t>(x)];
      if (chains.kept(x, y)) {
        above = range[x];
        continue;
      }
      ++tests;
      if (above >= 0.0F && range[x] > above * (1.0 + tolerance) + kOrderSlack_m)
        judged[x] = kUnknown;
    }
  }
  return tests;
}

} // namespace marsokhod::nav::detail
