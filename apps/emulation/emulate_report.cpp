// The emulated cycle's report: tables for people, JSON for scripts.

#include "emulation/emulate_report.hpp"

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/eval/timing/memory_sweep.hpp"

#include <fmt/format.h>

namespace marsokhod::apps {
namespace {

using nav_program::CycleEmulation;

double seconds(emulator::Tick t) {
  return emulator::to_seconds(t);
}

double fraction(emulator::Tick part, emulator::Tick whole) {
  return whole > 0 ? static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

// Units of each nav::Work kind, by name.
nlohmann::ordered_json work_json(const nav::CountingMeter& work) {
  nlohmann::ordered_json units = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < nav::kWorkKinds; ++k)
    units[std::string(nav::to_string(static_cast<nav::Work>(k)))] =
        work.count(static_cast<nav::Work>(k));
  return units;
}

nlohmann::ordered_json plan_json(const nav_program::MemoryPlan& plan) {
  nlohmann::ordered_json nodes = nlohmann::ordered_json::array();
  for (const nav_program::NodePlan& node : plan.nodes) {
    nlohmann::ordered_json processes = nlohmann::ordered_json::array();
    for (const nav_program::ProcessPlan& process : node.processes) {
      nlohmann::ordered_json buffers = nlohmann::ordered_json::array();
      for (const nav_program::PlannedBuffer& buffer : process.buffers)
        buffers.push_back({{"what", buffer.what}, {"bytes", buffer.bytes}});
      processes.push_back({{"process", process.process},
                           {"code_bytes", process.code_bytes},
                           {"workspace_bytes", process.workspace_bytes},
                           {"buffer_bytes", process.buffer_bytes()},
                           {"buffers", buffers}});
    }
    nodes.push_back({{"node", node.node},
                     {"memory_bytes", node.memory_bytes},
                     {"reserved_bytes", node.reserved_bytes},
                     {"code_bytes", node.code_bytes},
                     {"workspace_bytes", node.workspace_bytes},
                     {"free_for_buffers", node.free_for_buffers()},
                     {"buffer_bytes", node.buffer_bytes()},
                     {"fits", node.fits()},
                     {"processes", processes}});
  }
  return {{"image_width", plan.image_width},
          {"image_height", plan.image_height},
          {"band_rows", plan.band_rows},
          {"terrain_kept", plan.terrain_kept},
          {"zone_grid_bytes", plan.zone_grid_bytes},
          {"fits", plan.fits()},
          {"nodes", nodes}};
}

} // namespace

std::string emulation_tables(const CycleEmulation& run) {
  std::string text = "stage        start s     end s  seconds\n";
  for (const nav_program::StageFigures& stage : run.stages)
    text += fmt::format("  {:<10} {:>8.3f}  {:>8.3f} {:>8.3f}\n", stage.name, seconds(stage.start),
                        seconds(stage.end), seconds(stage.end - stage.start));
  text += "process    node       cpu s    peak B\n";
  for (const nav_program::ProcessFigures& process : run.processes)
    text += fmt::format("  {:<10} {:<8} {:>7.3f} {:>9}\n", process.name, process.node,
                        seconds(process.cpu), process.peak_bytes);
  text += "node       busy    peak B of memory B\n";
  for (const nav_program::NodeFigures& node : run.nodes)
    text += node.powered ? fmt::format("  {:<8} {:>5.1f} % {:>9} of {}\n", node.name,
                                       100.0 * fraction(node.busy, run.emulated), node.peak_bytes,
                                       node.memory_bytes)
                         : fmt::format("  {:<8} not powered\n", node.name);
  text += "link direction                     bytes  busy s\n";
  for (const nav_program::LinkFigures& link : run.links)
    text += fmt::format("  {:<14} -> {:<14} {:>8} {:>7.3f}\n", link.from, link.to, link.bytes,
                        seconds(link.busy));
  return text + nav_program::describe(run.plan);
}

nlohmann::ordered_json emulation_json(const CycleEmulation& run, const EmulationSubject& subject,
                                      double host_seconds,
                                      const std::map<std::string, std::filesystem::path>& outputs) {
  nlohmann::ordered_json json;
  json["platform"] = subject.platform;
  json["platform_file"] = subject.platform_file;
  json["placement_file"] = subject.placement_file;
  json["pair"] = subject.pair;
  json["emulated_seconds"] = seconds(run.emulated);
  json["host_seconds"] = host_seconds;
  json["stages"] = nlohmann::ordered_json::array();
  for (const nav_program::StageFigures& stage : run.stages)
    json["stages"].push_back({{"name", stage.name},
                              {"start_seconds", seconds(stage.start)},
                              {"emulated_seconds", seconds(stage.end - stage.start)}});
  json["processes"] = nlohmann::ordered_json::array();
  for (const nav_program::ProcessFigures& p : run.processes)
    json["processes"].push_back({{"name", p.name},
                                 {"node", p.node},
                                 {"cpu_seconds", seconds(p.cpu)},
                                 {"peak_bytes", p.peak_bytes}});
  json["nodes"] = nlohmann::ordered_json::array();
  for (const nav_program::NodeFigures& n : run.nodes)
    json["nodes"].push_back({{"name", n.name},
                             {"powered", n.powered},
                             {"busy_fraction", fraction(n.busy, run.emulated)},
                             {"peak_bytes", n.peak_bytes},
                             {"memory_bytes", n.memory_bytes}});
  json["links"] = nlohmann::ordered_json::array();
  for (const nav_program::LinkFigures& l : run.links)
    json["links"].push_back(
        {{"from", l.from}, {"to", l.to}, {"bytes", l.bytes}, {"busy_seconds", seconds(l.busy)}});
  json["occam_style_factor"] = run.occam_style;
  json["memory_plan"] = plan_json(run.plan);
  json["memory_fault"] = eval::memory_fault_json(run.memory_fault);
  json["found"] = run.result && run.result->found();
  if (run.result && !run.result->found())
    json["reason"] = run.result->reason();
  json["work"] = work_json(run.work);
  json["recomputed_work"] = work_json(run.recomputed_work);
  json["context_switches"] = run.context_switches;
  nlohmann::ordered_json files = nlohmann::ordered_json::object();
  for (const auto& [key, path] : outputs)
    files[key] = path.string();
  json["outputs"] = files;
  return json;
}

} // namespace marsokhod::apps
