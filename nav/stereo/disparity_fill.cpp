// Filling the pixels the left-right check rejected, and the 3x3 median of disparities.

#include "marsokhod/nav/stereo/disparity_fill.hpp"

#include "lanes/simd_lanes.hpp"
#include "work/work_report.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace marsokhod::nav {
namespace {

constexpr float kUnknownDisparity = std::numeric_limits<float>::infinity();

// The first x from `x` on (or width) whose validity is zero (Zero) or not zero (!Zero), eight
// bytes at a time: in a little-endian word the lowest set bit of the word itself (of its
// zero-byte mask) lies in its first nonzero (zero) byte; the mask's false positives lie only
// above a true zero byte. One branch a word instead of one a pixel.
template <bool Zero>
int run_end(const std::uint8_t* valid, int x, int width) {
  constexpr std::uint64_t kLow = 0x0101010101010101ULL;
  constexpr std::uint64_t kHigh = 0x8080808080808080ULL;
  if constexpr (std::endian::native == std::endian::little) {
    for (; x + 8 <= width; x += 8) {
      std::uint64_t word;
      std::memcpy(&word, valid + x, sizeof word);
      const std::uint64_t hits = Zero ? word : (word - kLow) & ~word & kHigh;
      if (hits != 0)
        return x + std::countr_zero(hits) / 8;
    }
  }
  while (x < width && (valid[x] == 0) == Zero)
    ++x;
  return x;
}

// Fills the unreliable runs of one row; returns false when the row has no reliable pixel.
bool fill_row(float* disparity, const std::uint8_t* valid, int width, std::uint64_t& written) {
  int x = 0;
  bool any_reliable = false;
  while (x < width) {
    if (valid[x] != 0) {
      any_reliable = true;
      x = run_end<false>(valid, x, width);
      continue;
    }
    const int run_start = x;
    x = run_end<true>(valid, x, width);
    const float before = run_start > 0 ? disparity[run_start - 1] : kUnknownDisparity;
    const float after = x < width ? disparity[x] : kUnknownDisparity;
    const float value = std::min(before, after);
    std::fill(disparity + run_start, disparity + x, value);
    written += static_cast<std::uint64_t>(x - run_start);
  }
  return any_reliable;
}

// The row nearest to y that has a reliable pixel, preferring the lower one; -1 if none.
int nearest_filled_row(const std::pmr::vector<std::uint8_t>& filled, int y) {
  const int height = static_cast<int>(filled.size());
  for (int distance = 1; distance < height; ++distance) {
    if (y + distance < height && filled[static_cast<std::size_t>(y + distance)] != 0)
      return y + distance;
    if (y - distance >= 0 && filled[static_cast<std::size_t>(y - distance)] != 0)
      return y - distance;
  }
  return -1;
}

// The three values of each column of a 3x3 window, sorted (rows above, at and below).
struct SortedColumns {
  float* low;
  float* middle;
  float* high;
};

using detail::Floats4;

template <class T>
T smaller(T a, T b) {
  if constexpr (std::is_same_v<T, Floats4>)
    return detail::floats_min(a, b);
  else
    return a < b ? a : b;
}
template <class T>
T larger(T a, T b) {
  if constexpr (std::is_same_v<T, Floats4>)
    return detail::floats_max(a, b);
  else
    return a < b ? b : a;
}
template <class T>
T middle_of(T a, T b, T c) {
  return larger(smaller(a, b), smaller(larger(a, b), c));
}

// Four pixels at a time in vector lanes, the rest one by one.
template <class Body>
void for_each_lane_group(int from, int to, Body body) {
  int x = from;
  for (; x + detail::kFloatLanes <= to; x += detail::kFloatLanes)
    body.template operator()<Floats4>(x);
  for (; x < to; ++x)
    body.template operator()<float>(x);
}

template <class T>
T load_as(const float* from) {
  if constexpr (std::is_same_v<T, float>)
    return *from;
  else
    return detail::load_lanes<Floats4>(from);
}

template <class T>
void store_as(float* to, T value) {
  if constexpr (std::is_same_v<T, float>)
    *to = value;
  else
    detail::store_lanes(to, value);
}

// The columns go by value: through a reference, every store could change them.
void sort_columns(const float* above, const float* here, const float* below, int width,
                  SortedColumns out) {
  for_each_lane_group(
      0, width,
      [=]<class T>(int x) {
        const T a = load_as<T>(above + x);
        const T b = load_as<T>(here + x);
        const T c = load_as<T>(below + x);
        const T lower = smaller(a, b);
        const T upper = larger(a, b);
        store_as(out.low + x, smaller(lower, c));
        const T top = larger(lower, c);
        store_as(out.middle + x, smaller(upper, top));
        store_as(out.high + x, larger(upper, top));
      });
}

// The median of nine from three sorted columns: the median of the largest low, the middle
// middle and the smallest high (exact: Paeth, Graphics Gems, 1990). Columns x-1, x, x+1 for
// x in 1 .. width-2.
void inner_medians(SortedColumns columns, int width, float* out) {
  for_each_lane_group(
      1, width - 1,
      [=]<class T>(int x) {
        const T low = larger(larger(load_as<T>(columns.low + x - 1), load_as<T>(columns.low + x)),
                             load_as<T>(columns.low + x + 1));
        const T high =
            smaller(smaller(load_as<T>(columns.high + x - 1), load_as<T>(columns.high + x)),
                    load_as<T>(columns.high + x + 1));
        const T middle =
            middle_of(load_as<T>(columns.middle + x - 1), load_as<T>(columns.middle + x),
                      load_as<T>(columns.middle + x + 1));
        store_as(out + x, middle_of(low, middle, high));
      });
}

// The median at a border column, whose missing neighbour repeats the border.
float border_median(const SortedColumns& columns, int left, int x, int right) {
  const float low = larger(larger(columns.low[left], columns.low[x]), columns.low[right]);
  const float high = smaller(smaller(columns.high[left], columns.high[x]), columns.high[right]);
  return middle_of(low, middle_of(columns.middle[left], columns.middle[x], columns.middle[right]),
                   high);
}

} // namespace

std::string_view to_string(FillPolicy policy) {
  return policy == FillPolicy::none ? "none" : "background";
}

std::optional<FillPolicy> parse_fill_policy(std::string_view text) {
  if (text == "none")
    return FillPolicy::none;
  if (text == "background")
    return FillPolicy::background_along_row;
  return std::nullopt;
}

template <class Meter>
std::uint64_t fill_disparity(imaging::ImageView<float> disparity,
                             imaging::ImageView<const std::uint8_t> valid, FillPolicy policy,
                             Meter& meter, std::pmr::memory_resource* memory) {
  if (disparity.width() != valid.width() || disparity.height() != valid.height())
    throw std::invalid_argument("fill_disparity: disparity and validity differ in size");
  if (policy == FillPolicy::none || disparity.empty())
    return 0;
  const int height = disparity.height();
  std::pmr::vector<std::uint8_t> filled(static_cast<std::size_t>(height), 0, memory);
  std::uint64_t written = 0;
  for (int y = 0; y < height; ++y) {
    std::uint64_t row_written = 0;
    filled[static_cast<std::size_t>(y)] =
        fill_row(disparity.row(y), valid.row(y), disparity.width(), row_written) ? 1 : 0;
    written += row_written;
  }
  for (int y = 0; y < height; ++y) {
    if (filled[static_cast<std::size_t>(y)] != 0)
      continue;
    const int source = nearest_filled_row(filled, y);
    if (source < 0)
      return 0;
    std::copy(disparity.row(source), disparity.row(source) + disparity.width(), disparity.row(y));
  }
  detail::report(meter, Work::fill_pixel, written);
  return written;
}

template <class Meter>
void median3x3(imaging::ImageView<const float> input, imaging::ImageView<float> output,
               Meter& meter, std::pmr::memory_resource* memory) {
  if (input.width() != output.width() || input.height() != output.height())
    throw std::invalid_argument("median3x3: input and output differ in size");
  const int width = input.width();
  const int height = input.height();
  if (width == 0 || height == 0)
    return;
  std::pmr::vector<float> sorted(3 * static_cast<std::size_t>(width), 0.0F, memory);
  const SortedColumns columns{sorted.data(), sorted.data() + width, sorted.data() + 2 * width};
  for (int y = 0; y < height; ++y) {
    sort_columns(input.row(std::max(y - 1, 0)), input.row(y),
                 input.row(std::min(y + 1, height - 1)), width, columns);
    float* out = output.row(y);
    inner_medians(columns, width, out);
    out[0] = border_median(columns, 0, 0, std::min(1, width - 1));
    if (width > 1)
      out[width - 1] = border_median(columns, width - 2, width - 1, width - 1);
    detail::report(meter, Work::median_pixel, static_cast<std::uint64_t>(width));
  }
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template std::uint64_t fill_disparity<M>(imaging::ImageView<float>,                              \
                                           imaging::ImageView<const std::uint8_t>, FillPolicy, M&, \
                                           std::pmr::memory_resource*);                            \
  template void median3x3<M>(imaging::ImageView<const float>, imaging::ImageView<float>, M&,       \
                             std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
