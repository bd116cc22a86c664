#include "stereo_layer.hpp"

#include "band_dp.hpp"
#include "band_layout.hpp"
#include "consistency_lines.hpp"
#include "matching_cost.hpp"
#include "right_view.hpp"
#include "work_report.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <limits>
#include <span>

namespace marsokhod::nav::detail {
namespace {

constexpr float kUnknown = std::numeric_limits<float>::infinity();

// Buffers reused by every band of the layer.
struct BandWorkspace {
  BandWorkspace(int width, std::pmr::memory_resource* memory)
      : wanted_low(static_cast<std::size_t>(tile_count(width)), 0, memory),
        wanted_high(static_cast<std::size_t>(tile_count(width)), 0, memory), layout(memory),
        costs(memory), jumps(static_cast<std::size_t>(width * kBandRows), 0, memory),
        choice(memory), right(static_cast<std::size_t>(width), 0, memory),
        right_band(static_cast<std::size_t>(width * kBandRows), 0, memory),
        right_best(static_cast<std::size_t>(width * kBandRows), 0, memory) {}

  std::pmr::vector<int> wanted_low; // per tile
  std::pmr::vector<int> wanted_high;
  BandLayout layout;
  std::pmr::vector<std::uint16_t> costs;
  std::pmr::vector<std::uint16_t> jumps;
  BandChoice choice;
  std::pmr::vector<std::int16_t> right;      // the right view of one line
  std::pmr::vector<std::int16_t> right_band; // the right view of every line, by lane
  std::pmr::vector<std::int16_t> right_best; // scratch of choose_right_view
};

// The large-step penalty between pixels x - 1 and x of each line of the band.
void edge_penalties(ImageView<const std::uint8_t> image, int y0, const DpPenalties& penalties,
                    std::pmr::vector<std::uint16_t>& jumps) {
  const int width = image.width();
  for (int lane = 0; lane < kBandRows; ++lane) {
    const std::uint8_t* row = image.row(std::min(y0 + lane, image.height() - 1));
    for (int x = 1; x < width; ++x) {
      const bool edge = std::abs(row[x] - row[x - 1]) > penalties.edge_threshold;
      jumps[static_cast<std::size_t>(x * kBandRows + lane)] =
          static_cast<std::uint16_t>(edge ? penalties.large_step_at_edge : penalties.large_step);
    }
  }
}

// The left-right check of one line of the band; writes the reliable disparities and returns
// the largest (whole) one, -1 if none.
template <class Meter>
int check_lane(BandWorkspace& band, int lane, int y0, int tolerance, LayerOutput& output,
               Meter& meter) {
  const int width = output.disparity.width();
  const StridedLine<std::int16_t> left{band.choice.disparity.data() + lane, kBandRows};
  for (int x = 0; x < width; ++x)
    band.right[static_cast<std::size_t>(x)] =
        band.right_band[static_cast<std::size_t>(x * kBandRows + lane)];
  std::uint8_t* valid = output.valid.row(y0 + lane);
  output.valid_pixels +=
      static_cast<std::uint64_t>(check_line(left, band.right.data(), width, tolerance, valid));
  report(meter, Work::consistency_check, static_cast<std::uint64_t>(width));
  float* disparity = output.disparity.row(y0 + lane);
  const float* subpixel = band.choice.subpixel.data() + lane;
  constexpr float kUnknownHere = std::numeric_limits<float>::infinity();
  int largest = -1;
  for (int x = 0; x < width; ++x) {
    const bool reliable = valid[x] != 0;
    disparity[x] = reliable ? subpixel[x * kBandRows] : kUnknownHere;
    largest = reliable ? std::max(largest, static_cast<int>(left[x])) : largest;
  }
  return largest;
}

// Without the left-right check: every pixel keeps its choice and counts as reliable.
void accept_all(const BandChoice& choice, int y0, int rows, LayerOutput& output) {
  const int width = output.disparity.width();
  for (int lane = 0; lane < rows; ++lane) {
    float* disparity = output.disparity.row(y0 + lane);
    std::uint8_t* valid = output.valid.row(y0 + lane);
    for (int x = 0; x < width; ++x) {
      disparity[x] = choice.subpixel[static_cast<std::size_t>(x * kBandRows + lane)];
      valid[x] = 255;
    }
  }
  output.valid_pixels += static_cast<std::uint64_t>(width * rows);
}

} // namespace

template <class Meter>
LayerOutput match_layer(const LayerInput& input, const StereoOptions& options, Meter& meter,
                        std::pmr::memory_resource* memory) {
  const int width = input.left.width();
  const int height = input.left.height();
  LayerOutput output{Image<float>(width, height, 1, kUnknown, memory),
                     Image<std::uint8_t>(width, height, 1, 0, memory), 0, 0};
  BandWorkspace band(width, memory);
  MatchingCost matching(options.feature, width, input.limits.high, memory);
  BandDp dp(width, input.limits.high, memory);
  const bool prior = options.ground_prior && input.guide == nullptr;
  const int bands = (height + kBandRows - 1) / kBandRows;
  int bound = input.limits.high;
  for (int step = 0; step < bands; ++step) {
    // With the prior the bands go bottom-up, so each is bounded by the one below it.
    const int y0 = (prior ? bands - 1 - step : step) * kBandRows;
    const int rows = std::min(kBandRows, height - y0);
    const auto pixels = static_cast<std::uint64_t>(width * rows);
    if (input.guide != nullptr) {
      input.guide->wanted(y0, width, options.search_band, band.wanted_low, band.wanted_high);
    } else {
      std::fill(band.wanted_low.begin(), band.wanted_low.end(), input.limits.low);
      std::fill(band.wanted_high.begin(), band.wanted_high.end(), bound);
    }
    band.layout.lay_out(width, input.limits, band.wanted_low, band.wanted_high);
    report(meter, Work::search_range_pixel, pixels);
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
    dp.run(band.layout, band.costs.data(), band.jumps.data(), options.penalties.small_step,
           band.choice);
    report(meter, Work::dp_transition, 2 * cells);
    report(meter, Work::disparity_choice, cells);
    int largest = -1;
    if (!input.check) {
      accept_all(band.choice, y0, rows, output);
      output.candidates += cells;
      continue;
    }
    // Choosing the right view is one more minimum over the band's cells.
    report(meter, Work::disparity_choice,
           choose_right_view(band.layout, dp.aggregated(), band.right_band.data(),
                             band.right_best.data()) *
               static_cast<std::uint64_t>(rows));
    for (int lane = 0; lane < rows; ++lane)
      largest = std::max(largest, check_lane(band, lane, y0, options.lr_tolerance, output, meter));
    output.candidates += cells;
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
