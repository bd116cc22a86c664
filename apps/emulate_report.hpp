// What `marsokhod emulate` prints: the timing tables, the memory plan and the JSON summary.
#pragma once

#include "marsokhod/occam_port/navigation/navigation_program.hpp"

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
std::string emulation_tables(const occam_port::CycleEmulation& run);

/// The JSON summary (docs/emulated-navigation.md lists the keys).
nlohmann::ordered_json emulation_json(const occam_port::CycleEmulation& run,
                                      const EmulationSubject& subject, double host_seconds,
                                      const std::map<std::string, std::filesystem::path>& outputs);

/// "memory fault on module1: process zones wanted 65536 B for terrain forward, ...".
std::string memory_fault_message(const occam_port::MemoryFaultFigures& fault);

/// The JSON `memory_fault`: {node, process, requested_bytes, what}, or null without one.
nlohmann::ordered_json
memory_fault_json(const std::optional<occam_port::MemoryFaultFigures>& fault);

} // namespace marsokhod::apps
