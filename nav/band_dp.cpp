#include "band_dp.hpp"

#include "matching_cost.hpp"
#include "simd_lanes.hpp"

#include <algorithm>

namespace marsokhod::nav::detail {
namespace {

// Above any path cost (at most kPaddingCost + kMaxPenalty), yet far from overflowing 16 signed
// bits when P1 is added.
constexpr std::int16_t kUnreachable = 0x3FFF;

// The path costs of one pixel in place: `path` points at disparity `first` of the buffer, whose
// entries first - 1 and first + cells hold the neighbour's costs (or unreachable). Writes each
// cell's cost to `out` and returns the pixel's smallest per lane.
Lanes16 step_pixel(std::uint16_t* path, const std::uint16_t* cost, std::uint16_t* out, int cells,
                   Lanes16 jump, int small_step, Lanes16 previous_min) {
  const Lanes16 stay_shift = -previous_min;
  const Lanes16 step_shift = broadcast16(small_step) - previous_min;
  Lanes16 smallest = broadcast16(kUnreachable);
  Lanes16 below = load_lanes<Lanes16>(path - kBandRows);
  Lanes16 here = load_lanes<Lanes16>(path);
  for (int k = 0; k < cells; ++k) {
    const Lanes16 above = load_lanes<Lanes16>(path + (k + 1) * kBandRows);
    const Lanes16 best =
        lanes_min(lanes_min(here + stay_shift, lanes_min(below, above) + step_shift), jump);
    const Lanes16 total = load_lanes<Lanes16>(cost + k * kBandRows) + best;
    store_lanes(path + k * kBandRows, total);
    store_lanes(out + k * kBandRows, total);
    smallest = lanes_min(smallest, total);
    below = here;
    here = above;
  }
  return smallest;
}

// After a pixel wrote window [first, first + cells), clears what is left of the window before.
void clear_stale(std::uint16_t* path_origin, int old_first, int old_cells, int first, int cells) {
  const Lanes16 unreachable = broadcast16(kUnreachable);
  for (int d = old_first; d < old_first + old_cells; ++d)
    if (d < first || d >= first + cells)
      store_lanes(path_origin + (d + 1) * kBandRows, unreachable);
}

// Vertex of the parabola through (-1, before), (0, best), (1, after), within half a pixel;
// 0 where a neighbour is no candidate or the costs do not curve upwards.
Floats4 parabola_offsets(Floats4 before, Floats4 best, Floats4 after) {
  const Floats4 curvature = before - 2.0F * best + after;
  const auto usable = (curvature > 0.0F) & (before < static_cast<float>(kPaddingCost)) &
                      (after < static_cast<float>(kPaddingCost));
  const Floats4 safe = usable ? curvature : Floats4{} + 1.0F;
  Floats4 offset = (before - after) / (2.0F * safe);
  offset = offset < -0.5F ? Floats4{} - 0.5F : offset;
  offset = offset > 0.5F ? Floats4{} + 0.5F : offset;
  return usable ? offset : Floats4{};
}

// The chosen disparities plus their sub-pixel offsets, lanes 0..7 into out[0..7].
void store_subpixel(float* out, Lanes16 disparity, Lanes16 before, Lanes16 best, Lanes16 after) {
  store_lanes(out, low_floats(disparity) +
                       parabola_offsets(low_floats(before), low_floats(best), low_floats(after)));
  store_lanes(out + 4,
              high_floats(disparity) +
                  parabola_offsets(high_floats(before), high_floats(best), high_floats(after)));
}

// The smallest S of a pixel and where it is, as one key per lane: S (capped at kPaddingCost,
// which no candidate reaches) times 32 plus the cell index within a chunk of 32 cells, so that
// one minimum finds both and ties go to the smaller disparity.
constexpr int kChunk = 32;
constexpr int kChunkBits = 5;

struct Choice {
  Lanes16 best_cost = broadcast16(kUnreachable);
  Lanes16 best_index{};

  static Lanes16 key(Lanes16 s, Lanes16 in_chunk) {
    return (lanes_min(s, broadcast16(kPaddingCost)) << kChunkBits) + in_chunk;
  }
  // Folds the smallest key of the chunk starting at cell `start`; an earlier chunk wins a tie.
  void fold(Lanes16 chunk_key, int start) {
    const Lanes16 cost = chunk_key >> kChunkBits;
    const Lanes16 better = cost < best_cost;
    best_cost = better ? cost : best_cost;
    best_index = better ? (chunk_key & (kChunk - 1)) + broadcast16(start) : best_index;
  }
};

// The S of the cells beside each lane's chosen one, unreachable where there is none. Exactly
// one cell matches each wanted index, so masks and ors gather it without a select per cell.
void neighbours(const std::uint16_t* s, int cells, Lanes16 index, Lanes16& before, Lanes16& after) {
  const Lanes16 want_before = index - 1;
  const Lanes16 want_after = index + 1;
  Lanes16 found_before{};
  Lanes16 found_after{};
  Lanes16 cell{};
  for (int k = 0; k < cells; ++k) {
    const Lanes16 here = load_lanes<Lanes16>(s + k * kBandRows);
    found_before |= here & (cell == want_before);
    found_after |= here & (cell == want_after);
    cell += 1;
  }
  const Lanes16 unreachable = broadcast16(kUnreachable);
  before = index > 0 ? found_before : unreachable;
  after = want_after < broadcast16(cells) ? found_after : unreachable;
}

} // namespace

BandDp::BandDp(int width, int max_disparity, std::pmr::memory_resource* memory)
    : width_(width), forward_(memory),
      path_(static_cast<std::size_t>((max_disparity + 3) * kBandRows), kUnreachable, memory) {}

void BandDp::forward_pass(const BandLayout& layout, const std::uint16_t* costs,
                          const std::uint16_t* jumps, int small_step) {
  std::uint16_t* origin = path_.data();
  int window_first = 0;
  int window_cells = 0;
  Lanes16 previous_min{};
  for (int x = 0; x < width_; ++x) {
    const int first = layout.first(x);
    const int cells = layout.cells(x);
    const std::size_t at = layout.offset(x) * kBandRows;
    const Lanes16 jump = x == 0 ? Lanes16{} : load_lanes<Lanes16>(jumps + x * kBandRows);
    previous_min = step_pixel(origin + (first + 1) * kBandRows, costs + at, forward_.data() + at,
                              cells, jump, small_step, previous_min);
    if (first != window_first || cells != window_cells) {
      clear_stale(origin, window_first, window_cells, first, cells);
      window_first = first;
      window_cells = cells;
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
  for (int x = width_ - 1; x >= 0; --x) {
    const int first = layout.first(x);
    const int cells = layout.cells(x);
    const std::size_t at = layout.offset(x) * kBandRows;
    const Lanes16 jump =
        x == width_ - 1 ? Lanes16{} : load_lanes<Lanes16>(jumps + (x + 1) * kBandRows);
    // S replaces the forward costs, cell by cell, once they are used.
    std::uint16_t* forward = forward_.data() + at;
    std::uint16_t* path = origin + (first + 1) * kBandRows;
    const Lanes16 stay_shift = -previous_min;
    const Lanes16 step_shift = broadcast16(small_step) - previous_min;
    Lanes16 smallest = broadcast16(kUnreachable);
    Lanes16 below = load_lanes<Lanes16>(path - kBandRows);
    Lanes16 here = load_lanes<Lanes16>(path);
    Choice best;
    for (int start = 0; start < cells; start += kChunk) {
      const int end = std::min(cells, start + kChunk);
      Lanes16 chunk_key = broadcast16(0x7FFF);
      Lanes16 in_chunk{};
      for (int k = start; k < end; ++k) {
        const Lanes16 above = load_lanes<Lanes16>(path + (k + 1) * kBandRows);
        const Lanes16 step =
            lanes_min(lanes_min(here + stay_shift, lanes_min(below, above) + step_shift), jump);
        const Lanes16 cost = load_lanes<Lanes16>(costs + at + k * kBandRows);
        const Lanes16 total = cost + step;
        store_lanes(path + k * kBandRows, total);
        smallest = lanes_min(smallest, total);
        const Lanes16 s = load_lanes<Lanes16>(forward + k * kBandRows) + total - cost;
        store_lanes(forward + k * kBandRows, s);
        chunk_key = lanes_min(chunk_key, Choice::key(s, in_chunk));
        in_chunk += 1;
        below = here;
        here = above;
      }
      best.fold(chunk_key, start);
    }
    previous_min = smallest;
    if (first != window_first || cells != window_cells) {
      clear_stale(origin, window_first, window_cells, first, cells);
      window_first = first;
      window_cells = cells;
    }
    Lanes16 before;
    Lanes16 after;
    neighbours(forward, cells, best.best_index, before, after);
    const Lanes16 disparity = best.best_index + broadcast16(first);
    const std::size_t out = static_cast<std::size_t>(x * kBandRows);
    store_lanes(choice.disparity.data() + out, disparity);
    store_subpixel(choice.subpixel.data() + out, disparity, before, best.best_cost, after);
  }
  clear_stale(origin, window_first, window_cells, 0, 0);
}

void BandDp::run(const BandLayout& layout, const std::uint16_t* costs, const std::uint16_t* jumps,
                 int small_step, BandChoice& choice) {
  if (forward_.size() < layout.total() * kBandRows)
    forward_.resize(layout.total() * kBandRows);
  const std::size_t size = static_cast<std::size_t>(width_ * kBandRows);
  choice.disparity.resize(size);
  choice.subpixel.resize(size);
  forward_pass(layout, costs, jumps, small_step);
  backward_pass(layout, costs, jumps, small_step, choice);
}

} // namespace marsokhod::nav::detail
