// BandLayout: the tiles and disparity windows of a band of scan lines (private to matching).
#pragma once

// How the matcher lays out the candidates of a band of scan lines (private).
//
// The matcher processes kBandRows scan lines at once, one per lane of a 16-bit vector register:
// each line keeps its own dynamic programme, but they advance together, pixel column by pixel
// column and disparity by disparity. A tile (kTileWidth columns of the band) searches one
// window of disparities, the hull of what its pixels want.

#include <cstddef>
#include <memory_resource>
#include <span>
#include <vector>

namespace marsokhod::nav::detail {

inline constexpr int kBandRows = 8;
inline constexpr int kTileWidth = 8;

inline int tile_count(int width) {
  return (width + kTileWidth - 1) / kTileWidth;
}

/// The disparities a pyramid layer may take.
struct DisparityLimits {
  int low = 0;
  int high = 0;
};

/// The windows of a band's tiles and where each pixel's cells (one vector per disparity of its
/// tile's window) start.
class BandLayout {
public:
  explicit BandLayout(std::pmr::memory_resource* memory);

  /// Each tile searches what it wants clamped to the layer's limits and to what its pixels can
  /// reach (x - d >= 0); a tile wanting nothing inside gets the nearest allowed disparity.
  void lay_out(int width, DisparityLimits limits, std::span<const int> wanted_low,
               std::span<const int> wanted_high);

  /// Throws std::range_error when a tile's window has left the layer's limits, a pixel's reach
  /// or the offsets: the layout's memory was struck since lay_out. It stands for the range
  /// checks occam compiles into every subscript, which would stop the program at the first
  /// index such a layout gives (a run-time error).
  void check() const;

  int width() const { return width_; }
  int first(int x) const { return first_[static_cast<std::size_t>(x / kTileWidth)]; }
  int cells(int x) const { return cells_[static_cast<std::size_t>(x / kTileWidth)]; }
  /// Index of pixel x's first cell.
  std::size_t offset(int x) const {
    const std::size_t tile = static_cast<std::size_t>(x / kTileWidth);
    return offset_[tile] + static_cast<std::size_t>((x % kTileWidth) * cells_[tile]);
  }
  /// Cells of the whole band (per scan line).
  std::size_t total() const { return offset_.back(); }

private:
  int width_ = 0;
  DisparityLimits limits_;
  std::pmr::vector<int> first_;
  std::pmr::vector<int> cells_;
  std::pmr::vector<std::size_t> offset_;
};

} // namespace marsokhod::nav::detail
