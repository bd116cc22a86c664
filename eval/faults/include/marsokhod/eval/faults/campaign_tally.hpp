// CampaignTally: a campaign's run records counted by outcome class, fault kind, memory region
// and buffer.
#pragma once

#include "marsokhod/eval/faults/fault_record.hpp"
#include "marsokhod/eval/faults/outcome.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// Runs per outcome class.
struct OutcomeCounts {
  std::array<std::uint64_t, kOutcomes.size()> runs{};

  std::uint64_t& operator[](Outcome outcome) { return runs[static_cast<std::size_t>(outcome)]; }
  std::uint64_t operator[](Outcome outcome) const {
    return runs[static_cast<std::size_t>(outcome)];
  }
  std::uint64_t total() const;
  OutcomeCounts& operator+=(const OutcomeCounts& other);
  friend bool operator==(const OutcomeCounts&, const OutcomeCounts&) = default;
};

/// Counts over a campaign's run records.
struct CampaignTally {
  std::uint64_t runs = 0;
  /// Runs of a scene whose fault-free path is unsafe: the navigation's own error, so they are
  /// left out of the unsafe rate (a fault can never be blamed for it there).
  std::uint64_t golden_unsafe_runs = 0;
  std::uint64_t judged = 0; ///< the others: what the unsafe rate is over
  std::uint64_t unsafe = 0;
  /// Runs whose fault reached the program (FaultVerdict::activated).
  std::uint64_t activated = 0;
  std::uint64_t detected = 0;           ///< a watchdog, a link's guard or the EDAC saw the fault
  std::uint64_t detected_activated = 0; ///< of the activated runs
  std::uint64_t edac_corrected = 0;     ///< memory faults the EDAC corrected
  OutcomeCounts outcomes;
  /// By fault kind's name, memory region ("external", "on-chip", "on-chip reserved") and buffer
  /// (the block's name without its size: "left image", "workspace of matching", "free"); the
  /// last two of memory faults only.
  std::map<std::string, OutcomeCounts> by_kind;
  std::map<std::string, OutcomeCounts> by_region;
  std::map<std::string, OutcomeCounts> by_buffer;
  std::vector<double> detection_latency_s; ///< of the detected runs that have one, in run order
  std::uint64_t telemetry_lost = 0;
  std::uint64_t wheels_commanded_while_failed = 0;
  std::uint64_t path_equals_golden = 0;
};

/// Adds one run's record to the tally.
void count_run(CampaignTally& tally, const RunRecord& record);
CampaignTally tally(std::span<const RunRecord> records);

/// A buffer's name without its size ("left image, 128 rows x 128 px x 1 B" -> "left image"), so
/// that the same buffer at other image sizes counts once.
std::string buffer_group(const std::string& buffer);

} // namespace marsokhod::eval
