// The memory sweep of `marsokhod emulate --sweep-external-kb LIST` and of `reproduce` as a
// table, JSON, CSV and a chart.
#pragma once

#include "emulation/emulate_report.hpp"

#include "marsokhod/eval/timing/memory_sweep.hpp"
#include "marsokhod/imaging/pictures/line_chart.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {

/// The sweep as a table, as JSON (`sweep`: list of {external_kb, emulated_seconds,
/// memory_fault, terrain_kept, zone_grid_bytes, recomputed_units}) and as CSV.
std::string sweep_table(const std::vector<eval::SweepPoint>& points);
nlohmann::ordered_json sweep_json(const std::vector<eval::SweepPoint>& points,
                                  const EmulationSubject& subject);
std::string sweep_csv(const std::vector<eval::SweepPoint>& points);

/// Writes sweep.csv, sweep.json and sweep.png (the cycle's time against the memory, the sizes
/// where it cannot run marked, and `marks`, such as the platform's own memory) into `folder`;
/// returns their paths by key.
std::map<std::string, std::filesystem::path>
write_sweep(const std::filesystem::path& folder, const std::vector<eval::SweepPoint>& points,
            const EmulationSubject& subject, const std::vector<imaging::LineChart::Mark>& marks);

} // namespace marsokhod::apps
