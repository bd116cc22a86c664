// Work metering: the names of the work kinds and a counting meter's total.

#include "marsokhod/nav/work/work.hpp"

#include <numeric>

namespace marsokhod::nav {

std::string_view to_string(Work kind) {
  switch (kind) {
  case Work::feature_pixel:
    return "feature_pixel";
  case Work::pyramid_pixel:
    return "pyramid_pixel";
  case Work::search_range_pixel:
    return "search_range_pixel";
  case Work::column_distance:
    return "column_distance";
  case Work::match_candidate:
    return "match_candidate";
  case Work::dp_transition:
    return "dp_transition";
  case Work::dp_backtrack:
    return "dp_backtrack";
  case Work::disparity_choice:
    return "disparity_choice";
  case Work::consistency_check:
    return "consistency_check";
  case Work::fill_pixel:
    return "fill_pixel";
  case Work::median_pixel:
    return "median_pixel";
  case Work::range_pixel:
    return "range_pixel";
  case Work::elevation_pixel:
    return "elevation_pixel";
  case Work::hazard_test:
    return "hazard_test";
  case Work::path_relaxation:
    return "path_relaxation";
  case Work::path_backtrack:
    return "path_backtrack";
  case Work::footprint_scan:
    return "footprint_scan";
  case Work::footprint_test:
    return "footprint_test";
  case Work::count_:
    break;
  }
  return "unknown";
}

std::uint64_t CountingMeter::total() const noexcept {
  return std::accumulate(counts_.begin(), counts_.end(), std::uint64_t{0});
}

} // namespace marsokhod::nav
