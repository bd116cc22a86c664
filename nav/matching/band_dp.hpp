// BandDp and BandChoice: a band's forward and backward passes and its choices (private).
#pragma once

// The scan-line dynamic programme on a band of lines at once (private to the stereo matcher).

#include "matching/band_layout.hpp"

#include "marsokhod/nav/matching/scanline_dp.hpp"

#include <cstdint>
#include <memory_resource>

namespace marsokhod::nav::detail {

/// Each line's chosen disparities and their sub-pixel refinement, at [x * kBandRows + lane].
struct BandChoice {
  explicit BandChoice(std::pmr::memory_resource* memory) : disparity(memory), subpixel(memory) {}
  std::pmr::vector<std::int16_t> disparity;
  std::pmr::vector<float> subpixel;
};

/// Runs the forward and the backward pass of the scan-line programme (see scanline_disparities)
/// on the kBandRows lines of a band, one per lane, and chooses each pixel's disparity: the
/// smallest S, the smaller disparity on a tie, refined by a parabola through S(d-1), S(d),
/// S(d+1) when both neighbours are candidates.
class BandDp {
public:
  BandDp(int width, int max_disparity, std::pmr::memory_resource* memory);

  /// Room for bands of up to `cells` cells a line, taken at once.
  void reserve(std::size_t cells) { forward_.reserve((cells + 2) * kBandRows); }
  /// `costs`: layout.total() cells of kBandRows lanes; `jumps`: for each pixel x, the large-step
  /// penalty between x - 1 and x of each lane ([x * kBandRows + lane]).
  void run(const BandLayout& layout, const std::uint16_t* costs, const std::uint16_t* jumps,
           int small_step, BandChoice& choice);

  /// S of every cell of the last band run, laid out as its costs were.
  const std::uint16_t* aggregated() const { return forward_.data() + kBandRows; }

private:
  void forward_pass(const BandLayout& layout, const std::uint16_t* costs,
                    const std::uint16_t* jumps, int small_step);
  void backward_pass(const BandLayout& layout, const std::uint16_t* costs,
                     const std::uint16_t* jumps, int small_step, BandChoice& choice);

  std::uint16_t* aggregated_cells() { return forward_.data() + kBandRows; }

  int width_;
  // The forward pass's L - C, then S, cell by cell, with one cell of margin on each side.
  std::pmr::vector<std::uint16_t> forward_;
  // Path costs of the last pixel by disparity (d = -1 .. max + 1 at (d + 1) * kBandRows),
  // unreachable outside the pixel's window.
  std::pmr::vector<std::uint16_t> path_;
};

} // namespace marsokhod::nav::detail
