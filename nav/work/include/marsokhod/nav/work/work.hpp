// Work metering: the units of work nav kernels report, and the meters that count them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace marsokhod::nav {

/// The units of work a navigation kernel reports (contract 1 of the design: work metering).
/// Kernels report what they actually executed -- per row or per block, counted as they go --
/// never a formula of the image size. occam_port maps each kind to the T805 instructions an
/// occam compiler would emit for it.
enum class Work : std::uint8_t {
  feature_pixel,      ///< one output pixel of the brightness-feature transform
  pyramid_pixel,      ///< one output pixel of a pyramid reduction
  search_range_pixel, ///< one pixel's search range derived from the coarser layer or the prior
  column_distance,    ///< one 3-pixel column of feature distances at one disparity
  match_candidate,    ///< one 3x3 window comparison at one disparity (sum of 3 columns)
  dp_transition,      ///< one cell of the scan-line dynamic programme (min over predecessors)
  dp_backtrack,       ///< one step of the scan-line back-track
  disparity_choice,   ///< one candidate examined choosing a pixel's best disparity
  consistency_check,  ///< one pixel of the left-right check
  fill_pixel,         ///< one pixel written by the fill policy
  median_pixel,       ///< one output pixel of the 3x3 median filter
  range_pixel,        ///< one disparity -> range / 3-D point conversion
  elevation_pixel,    ///< one point -> elevation conversion
  hazard_test,        ///< one neighbour comparison of the prohibited-zone test
  path_relaxation,    ///< one edge relaxation of the row sweep
  path_backtrack,     ///< one step rebuilding the path
  footprint_scan,     ///< one zone-map pixel examined by the footprint check
  footprint_test,     ///< one ground point tested against one leg or turn pose of the footprint
  count_              ///< number of kinds, not a kind
};

inline constexpr std::size_t kWorkKinds = static_cast<std::size_t>(Work::count_);

std::string_view to_string(Work kind);

/// A meter that measures nothing and compiles to nothing: the native default.
struct NullMeter {
  constexpr void operator()(Work /*kind*/, std::uint64_t /*count*/) const noexcept {}
};

/// The meter kernels report to when the caller passes none (stateless, so one suffices).
inline NullMeter null_meter{};

/// A meter behind a virtual call, so that a kernel compiled once can report to a meter chosen
/// at run time (the emulator plugs its cost model in through this).
class DynamicMeter {
public:
  virtual ~DynamicMeter() = default;
  virtual void operator()(Work kind, std::uint64_t count) = 0;
};

/// A meter that adds up every report per kind, to check that reported work follows the work
/// done and to feed the emulator's cost model.
class CountingMeter {
public:
  void operator()(Work kind, std::uint64_t count) noexcept {
    counts_[static_cast<std::size_t>(kind)] += count;
  }
  std::uint64_t count(Work kind) const noexcept { return counts_[static_cast<std::size_t>(kind)]; }
  std::uint64_t total() const noexcept;
  void reset() noexcept { counts_.fill(0); }

private:
  std::array<std::uint64_t, kWorkKinds> counts_{};
};

} // namespace marsokhod::nav
