// What `marsokhod emulate` prints: the timing tables, the memory plan and the JSON summary.
#pragma once

#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace marsokhod::apps {

/// Where a cycle ran and on what, for the report's first line and the JSON.
struct EmulationSubject {
  std::string platform; ///< name
  std::string platform_file;
  std::string placement_file;
  std::string pair; ///< "world seed 1" or the left image's path
};

/// The per-stage, per-process, per-node and per-link tables and the memory plan, as text.
std::string emulation_tables(const nav_program::CycleEmulation& run);

/// The JSON summary (docs/emulated-navigation.md lists the keys).
nlohmann::ordered_json emulation_json(const nav_program::CycleEmulation& run,
                                      const EmulationSubject& subject, double host_seconds,
                                      const std::map<std::string, std::filesystem::path>& outputs);

} // namespace marsokhod::apps
