// The memory plan: code, workspaces and the buffers each process keeps, node by node.

#include "marsokhod/nav_program/placement/memory_plan.hpp"

#include "processes/program_processes.hpp"

#include "marsokhod/nav/stereo/layered_matching.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace marsokhod::nav_program {

std::size_t ProcessPlan::buffer_bytes() const {
  return std::accumulate(
      buffers.begin(), buffers.end(), std::size_t{0},
      [](std::size_t sum, const PlannedBuffer& b) { return sum + b.bytes; });
}

std::size_t NodePlan::free_for_buffers() const {
  const std::size_t used = reserved_bytes + code_bytes + workspace_bytes;
  return memory_bytes > used ? memory_bytes - used : 0;
}

std::size_t ProcessPlan::received_bytes() const {
  std::size_t sum = 0;
  for (const PlannedBuffer& b : buffers)
    sum += b.received ? b.bytes : 0;
  return sum;
}

std::size_t ProcessPlan::handed_bytes() const {
  std::size_t sum = 0;
  for (const PlannedBuffer& b : buffers)
    sum += b.handed ? b.bytes : 0;
  return sum;
}

// The cycle's stages run one after another, but each hands its output on while the next one
// receives it: at the hand-over the one holds what it hands on and the other what it has
// received. The node's peak is the largest process or hand-over.
std::size_t NodePlan::buffer_bytes() const {
  std::size_t peak = 0;
  for (std::size_t i = 0; i < processes.size(); ++i) {
    const std::size_t next = i + 1 < processes.size() ? processes[i + 1].received_bytes() : 0;
    peak = std::max({peak, processes[i].buffer_bytes(), processes[i].handed_bytes() + next});
  }
  return peak;
}

bool MemoryPlan::fits() const {
  return std::all_of(
      nodes.begin(), nodes.end(), [](const NodePlan& n) { return n.fits(); });
}

std::string buffer_name(std::string_view what, int rows, int columns, int bytes_per_element) {
  return fmt::format("{}, {} rows x {} px x {} B", what, rows, columns, bytes_per_element);
}

namespace {

MemoryPlan plan_with(const emulator::PlatformSpec& platform, const Placement& placement,
                     const detail::BufferGeometry& geometry,
                     std::optional<std::size_t> external_bytes, bool terrain_kept) {
  MemoryPlan plan{geometry.width, geometry.height, nav::kMatchedBandRows, terrain_kept, 0, {}};
  for (const emulator::NodeSpec& node : platform.nodes) {
    NodePlan node_plan;
    node_plan.node = node.name;
    node_plan.memory_bytes =
        node.memory.on_chip_bytes + external_bytes.value_or(node.memory.external_bytes);
    node_plan.reserved_bytes = node.memory.reserved_on_chip_bytes;
    for (const detail::ProcessSpec& process : detail::program_processes()) {
      if (placement.node_of(process.name) != node.name)
        continue;
      node_plan.code_bytes += process.code_bytes;
      node_plan.workspace_bytes += process.workspace_bytes;
      node_plan.processes.push_back({std::string(process.name), process.code_bytes,
                                     process.workspace_bytes,
                                     process.buffers(geometry, terrain_kept)});
    }
    if (!node_plan.processes.empty())
      plan.nodes.push_back(std::move(node_plan));
  }
  return plan;
}

// Half of what the zones' node has beside the zones' own buffers: the other half is left to the
// allocator's fragments (buffers come and go in the arena) and the kernels' smaller scratch.
std::size_t zone_grid_budget(const MemoryPlan& plan) {
  for (const NodePlan& node : plan.nodes)
    for (const ProcessPlan& process : node.processes) {
      if (process.process != "zones")
        continue;
      const std::size_t free = node.free_for_buffers();
      const std::size_t own = process.buffer_bytes();
      return free > own ? (free - own) / 2 : 1;
    }
  return 0;
}

} // namespace

MemoryPlan plan_memory(const emulator::PlatformSpec& platform, const Placement& placement,
                       int width, int height, int pyramid_levels,
                       std::optional<std::size_t> external_bytes) {
  const detail::BufferGeometry geometry{width, height, pyramid_levels};
  // The terrain's four maps are kept where the nodes hold them; otherwise only the disparity,
  // and its rows are worked out again where they are read.
  MemoryPlan plan = plan_with(platform, placement, geometry, external_bytes, true);
  if (!plan.fits())
    plan = plan_with(platform, placement, geometry, external_bytes, false);
  // The grid's size follows the ground in view, which no plan knows: it gets a budget, and
  // the zones cut it into as many strips as the budget needs (one where it holds it all).
  plan.zone_grid_bytes = zone_grid_budget(plan);
  return plan;
}

std::string describe(const MemoryPlan& plan) {
  std::string text =
      fmt::format("memory plan for {}x{} images: the original layer matched in bands of {} rows, "
                  "the terrain {}, the other stages on whole images\n",
                  plan.image_width, plan.image_height, plan.band_rows,
                  plan.terrain_kept ? "kept as four maps"
                                    : "kept as the disparity and worked out again row by row "
                                      "where it is read");
  if (plan.zone_grid_bytes > 0)
    text += fmt::format("  the zones' ground grid in strips along the ground of at most {} B "
                        "each, its halo binned again\n",
                        plan.zone_grid_bytes);
  for (const NodePlan& node : plan.nodes) {
    text += fmt::format("  {}: {} B = {} reserved + {} code + {} workspaces + {} free for "
                        "buffers; peak of buffers {} B: {}\n",
                        node.node, node.memory_bytes, node.reserved_bytes, node.code_bytes,
                        node.workspace_bytes, node.free_for_buffers(), node.buffer_bytes(),
                        node.fits() ? "fit" : "DO NOT FIT");
    for (const ProcessPlan& process : node.processes) {
      text += fmt::format("    {:<10} {:>7} B", process.process, process.buffer_bytes());
      for (const PlannedBuffer& buffer : process.buffers)
        text += fmt::format("  [{}]", buffer.what);
      text += '\n';
    }
  }
  return text;
}

} // namespace marsokhod::nav_program
