// The sweep of the nodes' external memory, one emulated cycle per size.

#include "marsokhod/eval/timing/memory_sweep.hpp"

namespace marsokhod::eval {

std::vector<SweepPoint>
sweep_external_memory(const nav_program::CycleInput& input, nav_program::CycleSetup setup,
                      const std::vector<std::uint64_t>& external_kb,
                      const std::function<void(const SweepPoint&, std::size_t done)>& progress) {
  std::vector<SweepPoint> points;
  for (const std::uint64_t kb : external_kb) {
    setup.external_bytes = static_cast<std::size_t>(kb) * 1024;
    const nav_program::CycleEmulation run = nav_program::emulate_navigation_cycle(input, setup);
    points.push_back({kb, emulator::to_seconds(run.emulated), run.memory_fault,
                      run.plan.terrain_kept, run.plan.zone_grid_bytes,
                      run.recomputed_work.total()});
    if (progress)
      progress(points.back(), points.size());
  }
  return points;
}

nlohmann::ordered_json
memory_fault_json(const std::optional<nav_program::MemoryFaultFigures>& fault) {
  if (!fault)
    return nullptr;
  return {{"node", fault->node},
          {"process", fault->process},
          {"requested_bytes", fault->requested_bytes},
          {"what", fault->what}};
}

void to_json(nlohmann::ordered_json& json, const SweepPoint& p) {
  json["external_kb"] = p.external_kb;
  json["emulated_seconds"] =
      p.memory_fault ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(p.emulated_seconds);
  json["memory_fault"] = memory_fault_json(p.memory_fault);
  json["terrain_kept"] = p.terrain_kept;
  json["zone_grid_bytes"] = p.zone_grid_bytes;
  json["recomputed_units"] = p.recomputed_units;
}

} // namespace marsokhod::eval
