// The cycle's time against the nodes' external memory: one emulated cycle per size.
#pragma once

#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace marsokhod::eval {

/// One cycle of the sweep: every node's external memory replaced by `external_kb`.
struct SweepPoint {
  std::uint64_t external_kb = 0;
  double emulated_seconds = 0.0; ///< to the end, or to the fault
  std::optional<nav_program::MemoryFaultFigures> memory_fault;
  bool terrain_kept = true;
  std::size_t zone_grid_bytes = 0;
  std::uint64_t recomputed_units = 0; ///< all kinds of recomputed work together
};

/// Runs the cycle once for each memory size in turn (the setup's external memory replaced);
/// `progress(point, done)` (may be empty) is told of each point made.
std::vector<SweepPoint>
sweep_external_memory(const nav_program::CycleInput& input, nav_program::CycleSetup setup,
                      const std::vector<std::uint64_t>& external_kb,
                      const std::function<void(const SweepPoint&, std::size_t done)>& progress);

/// The JSON `memory_fault`: {node, process, requested_bytes, what}, or null without one.
nlohmann::ordered_json
memory_fault_json(const std::optional<nav_program::MemoryFaultFigures>& fault);

/// {external_kb, emulated_seconds (null when it does not fit), memory_fault, terrain_kept,
/// zone_grid_bytes, recomputed_units}.
void to_json(nlohmann::ordered_json& json, const SweepPoint& point);

} // namespace marsokhod::eval
