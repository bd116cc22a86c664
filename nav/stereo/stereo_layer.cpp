// Matching one pyramid layer band by band: costs, dynamic programme, left-right check.

#include "stereo/stereo_layer.hpp"

#include "lanes/simd_lanes.hpp"
#include "matching/band_dp.hpp"
#include "matching/band_layout.hpp"
#include "matching/band_output.hpp"
#include "matching/matching_cost.hpp"
#include "matching/right_view.hpp"
#include "work/work_report.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <limits>
#include <span>

namespace marsokhod::nav::detail {
namespace {

constexpr float kUnknownDisparity = std::numeric_limits<float>::infinity();
static_assert(kBandRows == kMatchedBandRows, "the public band height is the matcher's");

// Buffers reused by every band of the layer.
struct BandWorkspace {
  BandWorkspace(int width, int max_disparity, std::pmr::memory_resource* memory)
      : wanted_low(static_cast<std::size_t>(tile_count(width)), 0, memory),
        wanted_high(static_cast<std::size_t>(tile_count(width)), 0, memory), layout(memory),
        costs(memory), jumps(static_cast<std::size_t>(width * kBandRows), 0, memory),
        choice(memory), right_band(static_cast<std::size_t>(width * kBandRows), 0, memory),
        right_best(static_cast<std::size_t>(width * kBandRows), 0, memory),
        right_lines(width, max_disparity, memory) {}

  std::pmr::vector<int> wanted_low; // per tile
  std::pmr::vector<int> wanted_high;
  BandLayout layout;
  std::pmr::vector<std::uint16_t> costs;
  std::pmr::vector<std::uint16_t> jumps;
  BandChoice choice;
  std::pmr::vector<std::int16_t> right_band; // the right view of every line, by lane
  std::pmr::vector<std::int16_t> right_best; // scratch of choose_right_view
  RightLines right_lines;                    // the right view of every line, by line
};

// The large-step penalty between pixels x - 1 and x of each line of the band. Blocks of 8
// columns are transposed into lanes so that 8 lines are compared at once.
void edge_penalties(imaging::ImageView<const std::uint8_t> image, int y0,
                    const DpPenalties& penalties, std::pmr::vector<std::uint16_t>& jumps) {
  const int width = image.width();
  const std::uint8_t* rows[kBandRows];
  for (int lane = 0; lane < kBandRows; ++lane)
    rows[lane] = image.row(std::min(y0 + lane, image.height() - 1));
  // Grey steps lie within 0..255, so clamping the threshold to -1..255 keeps every comparison.
  const Lanes16 threshold = broadcast16(std::clamp(penalties.edge_threshold, -1, 255));
  const Lanes16 at_edge = broadcast16(penalties.large_step_at_edge);
  const Lanes16 plain = broadcast16(penalties.large_step);
  std::uint16_t* out = jumps.data();
  int x = 1;
  Lanes16 previous{}; // column x0 - 1
  for (int x0 = 0; x0 + kBandRows <= width; x0 += kBandRows) {
    Lanes16 grey[kBandRows];
    for (int lane = 0; lane < kBandRows; ++lane)
      grey[lane] = widen_bytes(rows[lane] + x0);
    transpose8x8(grey);
    if (x0 == 0)
      previous = grey[0];
    for (int i = x0 == 0 ? 1 : 0; i < kBandRows; ++i) {
      const Lanes16 step = grey[i] - previous;
      const Lanes16 size = step < 0 ? -step : step;
      store_lanes(out + (x0 + i) * kBandRows, size > threshold ? at_edge : plain);
      previous = grey[i];
    }
    x = x0 + kBandRows;
  }
  for (; x < width; ++x)
    for (int lane = 0; lane < kBandRows; ++lane) {
      const bool edge = std::abs(rows[lane][x] - rows[lane][x - 1]) > penalties.edge_threshold;
      out[x * kBandRows + lane] =
          static_cast<std::uint16_t>(edge ? penalties.large_step_at_edge : penalties.large_step);
    }
}

// The unseen columns of the band's lines, none for lines past the layer or when none are known.
std::array<std::int16_t, kBandRows> band_unseen(std::span<const std::int16_t> unseen, int y0,
                                                int rows) {
  std::array<std::int16_t, kBandRows> lanes{};
  if (!unseen.empty())
    for (int lane = 0; lane < rows; ++lane)
      lanes[static_cast<std::size_t>(lane)] = unseen[static_cast<std::size_t>(y0 + lane)];
  return lanes;
}

// The most cells a band of the layer lays out: with a guide, the largest of its bands' layouts;
// without one, each column's whole search range. The band buffers are reserved for it once, so
// that growing them band after band leaves no holes behind in the memory they come from.
std::size_t most_cells(const LayerInput& input, const StereoOptions& options, int bands,
                       BandWorkspace& band) {
  const int width = input.left.width();
  if (input.guide == nullptr)
    return static_cast<std::size_t>(width) *
           static_cast<std::size_t>(input.limits.high - input.limits.low + 1);
  std::size_t most = 0;
  for (int step = 0; step < bands; ++step) {
    input.guide->wanted(step * kBandRows, width, options.search_band, band.wanted_low,
                        band.wanted_high);
    band.layout.lay_out(width, input.limits, band.wanted_low, band.wanted_high);
    most = std::max(most, band.layout.total());
  }
  return most;
}

// The whole layer, or one band's rows when the layer goes out band by band.
LayerOutput layer_output(const LayerInput& input, std::pmr::memory_resource* memory) {
  const int width = input.left.width();
  const int rows =
      input.bands != nullptr ? std::min(kBandRows, input.left.height()) : input.left.height();
  return {imaging::Image<float>(width, rows, 1, kUnknownDisparity, memory),
          imaging::Image<std::uint8_t>(width, rows, 1, 0, memory), 0, 0, 0};
}

// Hands the band just written on, when the layer goes out band by band.
void hand_on(const LayerInput& input, const LayerOutput& output, int y0, int rows) {
  if (input.bands == nullptr)
    return;
  const int width = output.disparity.width();
  (*input.bands)(MatchedBand{y0, output.disparity.view().sub(0, 0, width, rows),
                             output.valid.view().sub(0, 0, width, rows)});
}

} // namespace

template <class Meter>
LayerOutput match_layer(const LayerInput& input, const StereoOptions& options, Meter& meter,
                        std::pmr::memory_resource* memory) {
  const int width = input.left.width();
  const int height = input.left.height();
  LayerOutput output = layer_output(input, memory);
  BandWorkspace band(width, input.limits.high, memory);
  MatchingCost matching(options.feature, width, input.limits.high, memory);
  BandDp dp(width, input.limits.high, memory);
  const bool prior = options.ground_prior && input.guide == nullptr;
  const int bands = (height + kBandRows - 1) / kBandRows;
  int bound = input.limits.high;
  const std::size_t most = most_cells(input, options, bands, band);
  band.costs.reserve(most * kBandRows);
  dp.reserve(most);
  for (int step = 0; step < bands; ++step) {
    // With the prior the bands go bottom-up, so each is bounded by the one below it.
    const int y0 = (prior ? bands - 1 - step : step) * kBandRows;
    const int rows = std::min(kBandRows, height - y0);
    const auto pixels = static_cast<std::uint64_t>(width * rows);
    if (input.bands != nullptr)
      output.first_row = y0;
    if (input.guide != nullptr) {
      input.guide->wanted(y0, width, options.search_band, band.wanted_low, band.wanted_high);
    } else {
      std::fill(band.wanted_low.begin(), band.wanted_low.end(), input.limits.low);
      std::fill(band.wanted_high.begin(), band.wanted_high.end(), bound);
    }
    band.layout.lay_out(width, input.limits, band.wanted_low, band.wanted_high);
    report(meter, Work::search_range_pixel, pixels);
    // The layout is memory of the module: checked after each report, where an upset may fall.
    band.layout.check();
    matching.load_band(*input.left_features, *input.right_features, y0, band.layout);
    // Grown, never shrunk, so that bands do not clear memory they then overwrite.
    if (band.costs.size() < band.layout.total() * kBandRows)
      band.costs.resize(band.layout.total() * kBandRows);
    const std::uint64_t distances = matching.compute(band.layout, band.costs.data());
    const auto cells =
        static_cast<std::uint64_t>(band.layout.total()) * static_cast<std::uint64_t>(rows);
    report(meter, Work::column_distance, distances * static_cast<std::uint64_t>(rows));
    report(meter, Work::match_candidate, cells);
    edge_penalties(input.left, y0, options.penalties, band.jumps);
    band.layout.check();
    dp.run(band.layout, band.costs.data(), band.jumps.data(), options.penalties.small_step,
           band.choice);
    report(meter, Work::dp_transition, 2 * cells);
    report(meter, Work::disparity_choice, cells);
    if (!input.check) {
      accept_band(band.choice, y0, rows, output);
      output.candidates += cells;
      hand_on(input, output, y0, rows);
      continue;
    }
    // Choosing the right view is one more minimum over the band's cells.
    const std::array<std::int16_t, kBandRows> unseen = band_unseen(input.unseen, y0, rows);
    band.layout.check();
    report(meter, Work::disparity_choice,
           choose_right_view(band.layout, dp.aggregated(), band.right_band.data(),
                             band.right_best.data(), unseen.data()) *
               static_cast<std::uint64_t>(rows));
    band.right_lines.load(band.right_band.data());
    const int largest =
        check_band(band.choice, band.right_lines, y0, rows, options.lr_tolerance, output);
    report(meter, Work::consistency_check, pixels);
    output.candidates += cells;
    hand_on(input, output, y0, rows);
    if (prior && largest >= 0)
      bound = largest + options.prior_margin;
  }
  return output;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template LayerOutput match_layer<M>(const LayerInput&, const StereoOptions&, M&,                 \
                                      std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav::detail
