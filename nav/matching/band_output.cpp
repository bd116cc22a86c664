// A band's disparities checked left against right and written into the layer (private).

#include "matching/band_output.hpp"

#include "lanes/simd_lanes.hpp"
#include "matching/consistency_lines.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace marsokhod::nav::detail {
namespace {

constexpr float kUnknown = std::numeric_limits<float>::infinity();
using Bytes8 = std::uint8_t __attribute__((vector_size(8)));

// Transposes four vectors of four floats.
void transpose4x4(Floats4& a, Floats4& b, Floats4& c, Floats4& d) {
  const Floats4 ab_low = __builtin_shufflevector(a, b, 0, 4, 1, 5);
  const Floats4 ab_high = __builtin_shufflevector(a, b, 2, 6, 3, 7);
  const Floats4 cd_low = __builtin_shufflevector(c, d, 0, 4, 1, 5);
  const Floats4 cd_high = __builtin_shufflevector(c, d, 2, 6, 3, 7);
  a = __builtin_shufflevector(ab_low, cd_low, 0, 1, 4, 5);
  b = __builtin_shufflevector(ab_low, cd_low, 2, 3, 6, 7);
  c = __builtin_shufflevector(ab_high, cd_high, 0, 1, 4, 5);
  d = __builtin_shufflevector(ab_high, cd_high, 2, 3, 6, 7);
}

// The layer's rows of the band's first `rows` lines.
struct BandRows {
  BandRows(LayerOutput& output, int y0, int lines) : rows(lines) {
    for (int lane = 0; lane < rows; ++lane) {
      disparity[lane] = output.disparity.row(y0 + lane - output.first_row);
      valid[lane] = output.valid.row(y0 + lane - output.first_row);
    }
  }
  float* disparity[kBandRows] = {};
  std::uint8_t* valid[kBandRows] = {};
  int rows;
};

// Writes columns x0 .. x0 + 7: `valid[lane]` holds, for line `lane`, -1 in each column whose
// pixel is reliable, 0 elsewhere. The rows go by value: through a reference, every store could
// change them.
void store_block(const float* subpixel, const Lanes16 (&valid)[kBandRows], int x0, BandRows out) {
  const Floats4 unknown = Floats4{} + kUnknown;
  for (int group = 0; group < kBandRows; group += kFloatLanes) {
    for (int half = 0; half < kBandRows; half += kFloatLanes) {
      // Lanes group .. group + 3 of columns x0 + half .. x0 + half + 3, then by line.
      Floats4 lines[kFloatLanes];
      for (int i = 0; i < kFloatLanes; ++i)
        lines[i] = load_lanes<Floats4>(subpixel + (x0 + half + i) * kBandRows + group);
      transpose4x4(lines[0], lines[1], lines[2], lines[3]);
      for (int i = 0; i < kFloatLanes && group + i < out.rows; ++i) {
        const Lanes16 mask = valid[group + i];
        const Ints4 reliable = half == 0 ? low_mask(mask) : high_mask(mask);
        store_lanes(out.disparity[group + i] + x0 + half, reliable ? lines[i] : unknown);
      }
    }
  }
  for (int lane = 0; lane < out.rows; ++lane) {
    // -1 becomes 255, 0 stays 0.
    store_lanes(out.valid[lane] + x0, __builtin_convertvector(valid[lane], Bytes8));
  }
}

int largest_lane(Lanes16 v) {
  return -smallest_lane(-v);
}

} // namespace

RightLines::RightLines(int width, int max_disparity, std::pmr::memory_resource* memory)
    : width_(width), pad_(max_disparity + 1), stride_(width + pad_),
      data_(static_cast<std::size_t>(stride_ * kBandRows), -1, memory) {}

void RightLines::load(const std::int16_t* right) {
  int r = 0;
  for (; r + kBandRows <= width_; r += kBandRows) {
    Lanes16 block[kBandRows];
    for (int i = 0; i < kBandRows; ++i)
      block[i] = load_lanes<Lanes16>(right + (r + i) * kBandRows);
    transpose8x8(block);
    for (int lane = 0; lane < kBandRows; ++lane)
      store_lanes(data_.data() + lane * stride_ + pad_ + r, block[lane]);
  }
  for (; r < width_; ++r)
    for (int lane = 0; lane < kBandRows; ++lane)
      data_[static_cast<std::size_t>(lane * stride_ + pad_ + r)] = right[r * kBandRows + lane];
}

// Eight columns at a time: the right view's disparity is gathered lane by lane (each lane's
// right pixel differs), the comparison is one vector operation, and an 8 x 8 transpose turns
// the columns' verdicts into the lines' rows.
int check_band(const BandChoice& choice, const RightLines& right, int y0, int rows, int tolerance,
               LayerOutput& output) {
  const int width = output.disparity.width();
  const auto [lowest, highest] =
      std::minmax_element(choice.disparity.begin(), choice.disparity.end());
  if (lowest != choice.disparity.end() && (*lowest < 0 || *highest > right.max_disparity()))
    throw std::range_error("matching: a band's chosen disparities were struck");
  const Lanes16 lane_index{0, 1, 2, 3, 4, 5, 6, 7};
  const Lanes16 live = lane_index < broadcast16(rows);
  // Disparities fit 15 bits, so a larger tolerance admits every difference.
  const Lanes16 slack = broadcast16(std::min(tolerance, 0x7FFF));
  Lanes16 largest = broadcast16(-1);
  Lanes16 reliable{};
  const BandRows out(output, y0, rows);
  const std::int16_t* lines[kBandRows];
  for (int lane = 0; lane < kBandRows; ++lane)
    lines[lane] = right.line(lane);
  int x0 = 0;
  for (; x0 + kBandRows <= width; x0 += kBandRows) {
    Lanes16 valid[kBandRows];
    for (int i = 0; i < kBandRows; ++i) {
      const int x = x0 + i;
      const auto disparity = load_lanes<Lanes16>(choice.disparity.data() + x * kBandRows);
      // Each lane's right pixel x - d; disparities never exceed the lines' lead.
      const Lanes16 at = broadcast16(x) - disparity;
      Lanes16 back;
      for (int lane = 0; lane < kBandRows; ++lane)
        back[lane] = lines[lane][at[lane]];
      const Lanes16 difference = back - disparity;
      const Lanes16 agrees = live & (back >= 0) & (difference <= slack) & (-difference <= slack);
      largest = agrees ? lanes_max(largest, disparity) : largest;
      reliable -= agrees;
      valid[i] = agrees;
    }
    transpose8x8(valid);
    store_block(choice.subpixel.data(), valid, x0, out);
  }
  int best = largest_lane(largest);
  std::uint64_t count = 0;
  for (int lane = 0; lane < kBandRows; ++lane)
    count += static_cast<std::uint64_t>(reliable[lane]);
  // The last columns, line by line.
  for (int lane = 0; lane < rows; ++lane) {
    const StridedLine<std::int16_t> left{choice.disparity.data() + lane, kBandRows};
    const std::int16_t* right_line = lines[lane];
    std::uint8_t* valid = out.valid[lane];
    float* disparity = out.disparity[lane];
    for (int x = x0; x < width; ++x) {
      const int d = left[x];
      const bool agree = agrees(x, d, right_line, width, tolerance);
      valid[x] = agree ? 255 : 0;
      disparity[x] =
          agree ? choice.subpixel[static_cast<std::size_t>(x * kBandRows + lane)] : kUnknown;
      best = agree ? std::max(best, d) : best;
      count += agree ? 1 : 0;
    }
  }
  output.valid_pixels += count;
  return best;
}

void accept_band(const BandChoice& choice, int y0, int rows, LayerOutput& output) {
  const int width = output.disparity.width();
  Lanes16 all[kBandRows];
  for (Lanes16& lane : all)
    lane = broadcast16(-1);
  const BandRows out(output, y0, rows);
  int x0 = 0;
  for (; x0 + kBandRows <= width; x0 += kBandRows)
    store_block(choice.subpixel.data(), all, x0, out);
  for (int lane = 0; lane < rows; ++lane)
    for (int x = x0; x < width; ++x) {
      out.disparity[lane][x] = choice.subpixel[static_cast<std::size_t>(x * kBandRows + lane)];
      out.valid[lane][x] = 255;
    }
  output.valid_pixels += static_cast<std::uint64_t>(width * rows);
}

} // namespace marsokhod::nav::detail
