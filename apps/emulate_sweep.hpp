// The memory sweep of `marsokhod emulate --sweep-external-kb LIST`.
#pragma once

#include "emulate_report.hpp"

#include "marsokhod/imaging/pictures/line_chart.hpp"
#include "marsokhod/occam_port/navigation/navigation_program.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {

/// One cycle of the sweep: every node's external memory replaced by `external_kb`.
struct SweepPoint {
  std::uint64_t external_kb = 0;
  double emulated_seconds = 0.0; ///< to the end, or to the fault
  std::optional<occam_port::MemoryFaultFigures> memory_fault;
  bool terrain_kept = true;
  std::size_t zone_grid_bytes = 0;
  std::uint64_t recomputed_units = 0; ///< all kinds of recomputed work together
};

/// Runs the cycle for each memory size in turn (the setup's external memory replaced),
/// reporting progress on stderr unless `quiet`.
std::vector<SweepPoint> sweep_external_memory(const occam_port::CycleInput& input,
                                              occam_port::CycleSetup setup,
                                              const std::vector<std::uint64_t>& external_kb,
                                              bool quiet);

/// The sweep as a table, as JSON (`sweep`: list of {external_kb, emulated_seconds,
/// memory_fault, terrain_kept, zone_grid_bytes, recomputed_units}) and as CSV.
std::string sweep_table(const std::vector<SweepPoint>& points);
nlohmann::ordered_json sweep_json(const std::vector<SweepPoint>& points,
                                  const EmulationSubject& subject);
std::string sweep_csv(const std::vector<SweepPoint>& points);

/// Writes sweep.csv, sweep.json and sweep.png (the cycle's time against the memory, the sizes
/// where it cannot run marked, and `marks`, such as the platform's own memory) into `folder`;
/// returns their paths by key.
std::map<std::string, std::filesystem::path>
write_sweep(const std::filesystem::path& folder, const std::vector<SweepPoint>& points,
            const EmulationSubject& subject, const std::vector<imaging::LineChart::Mark>& marks);

} // namespace marsokhod::apps
