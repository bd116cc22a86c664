// The scan-line dynamic programme on a band of eight lines in vector lanes (private).

#include "matching/band_dp.hpp"

#include "lanes/simd_lanes.hpp"
#include "matching/matching_cost.hpp"

#include <algorithm>

namespace marsokhod::nav::detail {
namespace {

// Above any path cost (at most kPaddingCost + kMaxPenalty), yet far from overflowing 16 signed
// bits when P1 is added.
constexpr std::int16_t kUnreachable = 0x3FFF;

// The cheapest way into a disparity from the previous pixel's path costs at d - 1, d and d + 1
// (or any disparity, at the large-step penalty), less the previous pixel's smallest.
struct Step {
  Step(Lanes16 previous_min, int small_step, Lanes16 jump_penalty)
      : stay(-previous_min), small(broadcast16(small_step) - previous_min), jump(jump_penalty) {}
  Lanes16 operator()(Lanes16 below, Lanes16 here, Lanes16 above) const {
    return lanes_min(lanes_min(here + stay, lanes_min(below, above) + small), jump);
  }
  Lanes16 stay;
  Lanes16 small;
  Lanes16 jump;
};

// The forward path costs L of one pixel in place: `path` points at the pixel's first disparity
// in a buffer whose entries just outside the window hold unreachable. Stores L - C, which the
// backward pass completes into S, and returns the pixel's smallest L per lane.
Lanes16 forward_pixel(std::uint16_t* path, const std::uint16_t* cost, std::uint16_t* out, int cells,
                      const Step& step) {
  Lanes16 smallest = broadcast16(kUnreachable);
  Lanes16 below = load_lanes<Lanes16>(path - kBandRows);
  Lanes16 here = load_lanes<Lanes16>(path);
#pragma GCC unroll 2
  for (int k = 0; k < cells; ++k) {
    const Lanes16 above = load_lanes<Lanes16>(path + (k + 1) * kBandRows);
    const Lanes16 best = step(below, here, above);
    const Lanes16 total = load_lanes<Lanes16>(cost + k * kBandRows) + best;
    store_lanes(path + k * kBandRows, total);
    store_lanes(out + k * kBandRows, best);
    smallest = lanes_min(smallest, total);
    below = here;
    here = above;
  }
  return smallest;
}

// The smallest S of a pixel and where it is, as one key per lane: S (capped at kPaddingCost,
// which no candidate reaches) times 32 plus the cell index within a chunk of 32 cells, so that
// one minimum finds both and ties go to the smaller disparity.
constexpr int kChunk = 32;
constexpr int kChunkBits = 5;

struct PixelChoice {
  Lanes16 smallest = broadcast16(kUnreachable); // of the backward path costs
  Lanes16 cost = broadcast16(kUnreachable);     // the chosen S, capped
  Lanes16 index{};                              // the chosen cell

  // Folds the smallest key of the chunk starting at cell `start`; an earlier chunk wins a tie.
  void fold(Lanes16 key, int start) {
    const Lanes16 chunk_cost = key >> kChunkBits;
    const Lanes16 chunk_index = key & (kChunk - 1);
    if (start == 0) {
      cost = chunk_cost;
      index = chunk_index;
      return;
    }
    const Lanes16 better = chunk_cost < cost;
    cost = better ? chunk_cost : cost;
    index = better ? chunk_index + broadcast16(start) : index;
  }
};

// The backward pass over cells start .. end - 1 of one pixel, at most one chunk: `below` and
// `here` carry the previous pixel's path costs at k - 1 and k across calls. Returns the
// chunk's smallest key.
inline Lanes16 backward_chunk(std::uint16_t* path, const std::uint16_t* cost,
                              std::uint16_t* forward, int start, int end, const Step& step,
                              Lanes16& below, Lanes16& here, Lanes16& smallest) {
  const Lanes16 cap = broadcast16(kPaddingCost);
  Lanes16 key = broadcast16(0x7FFF);
  Lanes16 in_chunk{};
#pragma GCC unroll 2
  for (int k = start; k < end; ++k) {
    const Lanes16 above = load_lanes<Lanes16>(path + (k + 1) * kBandRows);
    const Lanes16 total = load_lanes<Lanes16>(cost + k * kBandRows) + step(below, here, above);
    store_lanes(path + k * kBandRows, total);
    smallest = lanes_min(smallest, total);
    const Lanes16 s = load_lanes<Lanes16>(forward + k * kBandRows) + total;
    store_lanes(forward + k * kBandRows, s);
    key = lanes_min(key, (lanes_min(s, cap) << kChunkBits) + in_chunk);
    in_chunk += 1;
    below = here;
    here = above;
  }
  return key;
}

// The backward path costs of one pixel in place, as forward_pixel(); `forward` holds the
// forward pass's L - C, which becomes S = L_forward + L_backward - C.
PixelChoice backward_pixel(std::uint16_t* path, const std::uint16_t* cost, std::uint16_t* forward,
                           int cells, const Step& step) {
  PixelChoice choice;
  Lanes16 below = load_lanes<Lanes16>(path - kBandRows);
  Lanes16 here = load_lanes<Lanes16>(path);
  if (cells <= kChunk) {
    choice.fold(backward_chunk(path, cost, forward, 0, cells, step, below, here, choice.smallest),
                0);
    return choice;
  }
  for (int start = 0; start < cells; start += kChunk) {
    const int end = std::min(cells, start + kChunk);
    choice.fold(backward_chunk(path, cost, forward, start, end, step, below, here, choice.smallest),
                start);
  }
  return choice;
}

// After a pixel wrote window [first, first + cells), clears what is left of the window before.
void clear_stale(std::uint16_t* path_origin, int old_first, int old_cells, int first, int cells) {
  const Lanes16 unreachable = broadcast16(kUnreachable);
  for (int d = old_first; d < old_first + old_cells; ++d)
    if (d < first || d >= first + cells)
      store_lanes(path_origin + (d + 1) * kBandRows, unreachable);
}

// The S of the cells beside each lane's chosen one, unreachable where there is none. Read lane
// by lane: the cell before the first and the one after the last exist (a neighbouring pixel's
// or the buffer's margin) and are masked out.
void neighbours(const std::uint16_t* s, int cells, Lanes16 index, Lanes16& before, Lanes16& after) {
  const Lanes16 at = index * kBandRows + Lanes16{0, 1, 2, 3, 4, 5, 6, 7};
  Lanes16 found_before;
  Lanes16 found_after;
  for (int lane = 0; lane < kBandRows; ++lane) {
    const std::uint16_t* cell = s + at[lane];
    found_before[lane] = static_cast<std::int16_t>(cell[-kBandRows]);
    found_after[lane] = static_cast<std::int16_t>(cell[kBandRows]);
  }
  const Lanes16 unreachable = broadcast16(kUnreachable);
  before = index > 0 ? found_before : unreachable;
  after = index + 1 < broadcast16(cells) ? found_after : unreachable;
}

// Vertex of the parabola through (-1, before), (0, best), (1, after), within half a pixel,
// from rise = before - after and the curvature before - 2 best + after; 0 where not usable.
// Both are small whole numbers, so their floats equal the float arithmetic on the costs.
Floats4 parabola_offsets(Floats4 rise, Floats4 curvature, Ints4 usable) {
  const Floats4 offset = rise / (2.0F * curvature);
  const Floats4 clamped = floats_min(Floats4{} + 0.5F, floats_max(offset, Floats4{} - 0.5F));
  return usable ? clamped : Floats4{};
}

// The chosen disparities plus their sub-pixel offsets, lanes 0..7 into out[0..7]. The costs
// are at most kUnreachable, so the curvature and the rise fit 16 signed bits.
void store_subpixel(float* out, Lanes16 disparity, Lanes16 before, Lanes16 best, Lanes16 after) {
  const Lanes16 curvature = before - best - best + after;
  const Lanes16 padding = broadcast16(kPaddingCost);
  const Lanes16 usable = (curvature > 0) & (before < padding) & (after < padding);
  const Lanes16 safe = usable ? curvature : broadcast16(1);
  const Lanes16 rise = before - after;
  store_lanes(out, low_floats(disparity) +
                       parabola_offsets(low_floats(rise), low_floats(safe), low_mask(usable)));
  store_lanes(out + 4,
              high_floats(disparity) +
                  parabola_offsets(high_floats(rise), high_floats(safe), high_mask(usable)));
}

} // namespace

BandDp::BandDp(int width, int max_disparity, std::pmr::memory_resource* memory)
    : width_(width), forward_(memory),
      path_(static_cast<std::size_t>((max_disparity + 3) * kBandRows), kUnreachable, memory) {}

// Tile by tile: a tile's pixels share one window, so the stale part of the window before is
// cleared once, after the tile's first pixel.
void BandDp::forward_pass(const BandLayout& layout, const std::uint16_t* costs,
                          const std::uint16_t* jumps, int small_step) {
  std::uint16_t* origin = path_.data();
  int window_first = 0;
  int window_cells = 0;
  Lanes16 previous_min{};
  for (int x0 = 0; x0 < width_; x0 += kTileWidth) {
    const int pixels = std::min(kTileWidth, width_ - x0);
    const int first = layout.first(x0);
    const int cells = layout.cells(x0);
    std::uint16_t* path = origin + (first + 1) * kBandRows;
    const std::size_t tile_at = layout.offset(x0) * kBandRows;
    for (int p = 0; p < pixels; ++p) {
      const int x = x0 + p;
      const std::size_t at = tile_at + static_cast<std::size_t>(p * cells * kBandRows);
      const Lanes16 jump = x == 0 ? Lanes16{} : load_lanes<Lanes16>(jumps + x * kBandRows);
      previous_min = forward_pixel(path, costs + at, aggregated_cells() + at, cells,
                                   Step(previous_min, small_step, jump));
      if (p == 0 && (first != window_first || cells != window_cells)) {
        clear_stale(origin, window_first, window_cells, first, cells);
        window_first = first;
        window_cells = cells;
      }
    }
  }
  clear_stale(origin, window_first, window_cells, 0, 0);
}

void BandDp::backward_pass(const BandLayout& layout, const std::uint16_t* costs,
                           const std::uint16_t* jumps, int small_step, BandChoice& choice) {
  std::uint16_t* origin = path_.data();
  int window_first = 0;
  int window_cells = 0;
  Lanes16 previous_min{};
  for (int x0 = (width_ - 1) / kTileWidth * kTileWidth; x0 >= 0; x0 -= kTileWidth) {
    const int pixels = std::min(kTileWidth, width_ - x0);
    const int first = layout.first(x0);
    const int cells = layout.cells(x0);
    std::uint16_t* path = origin + (first + 1) * kBandRows;
    const std::size_t tile_at = layout.offset(x0) * kBandRows;
    for (int p = pixels - 1; p >= 0; --p) {
      const int x = x0 + p;
      const std::size_t at = tile_at + static_cast<std::size_t>(p * cells * kBandRows);
      const Lanes16 jump =
          x == width_ - 1 ? Lanes16{} : load_lanes<Lanes16>(jumps + (x + 1) * kBandRows);
      // S replaces the forward costs, cell by cell, once they are used.
      std::uint16_t* s = aggregated_cells() + at;
      const PixelChoice best =
          backward_pixel(path, costs + at, s, cells, Step(previous_min, small_step, jump));
      previous_min = best.smallest;
      if (p == pixels - 1 && (first != window_first || cells != window_cells)) {
        clear_stale(origin, window_first, window_cells, first, cells);
        window_first = first;
        window_cells = cells;
      }
      Lanes16 before;
      Lanes16 after;
      neighbours(s, cells, best.index, before, after);
      const Lanes16 disparity = best.index + broadcast16(first);
      const auto out = static_cast<std::size_t>(x * kBandRows);
      store_lanes(choice.disparity.data() + out, disparity);
      store_subpixel(choice.subpixel.data() + out, disparity, before, best.cost, after);
    }
  }
  clear_stale(origin, window_first, window_cells, 0, 0);
}

void BandDp::run(const BandLayout& layout, const std::uint16_t* costs, const std::uint16_t* jumps,
                 int small_step, BandChoice& choice) {
  if (forward_.size() < (layout.total() + 2) * kBandRows)
    forward_.resize((layout.total() + 2) * kBandRows);
  const std::size_t size = static_cast<std::size_t>(width_ * kBandRows);
  choice.disparity.resize(size);
  choice.subpixel.resize(size);
  forward_pass(layout, costs, jumps, small_step);
  backward_pass(layout, costs, jumps, small_step, choice);
}

} // namespace marsokhod::nav::detail
