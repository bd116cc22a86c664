// The memory plan: code, workspaces and the buffers each process keeps, node by node.

#include "marsokhod/occam_port/navigation/memory_plan.hpp"

#include "navigation/program_processes.hpp"

#include "marsokhod/nav/stereo/layered_matching.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace marsokhod::occam_port {
namespace {

struct Geometry {
  int width;
  int height;
  int levels;

  std::size_t pixels() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  // The halved layers above the original: floor(w / 2^l) x floor(h / 2^l) each.
  std::size_t pyramid_pixels() const {
    std::size_t total = 0;
    for (int level = 1; level < levels; ++level)
      total += static_cast<std::size_t>(width >> level) * static_cast<std::size_t>(height >> level);
    return total;
  }
};

PlannedBuffer image(std::string_view what, const Geometry& g, int bytes_per_pixel) {
  return {buffer_name(what, g.height, g.width, bytes_per_pixel),
          g.pixels() * static_cast<std::size_t>(bytes_per_pixel)};
}

// The terrain no process keeps: one row of level points at a time, worked out again from the
// disparity.
PlannedBuffer terrain_row(const Geometry& g) {
  return {buffer_name("terrain row (forward, left, elevation, range)", 1, g.width, 16),
          static_cast<std::size_t>(g.width) * 16};
}

// A buffer that arrived from the previous process, one still held when handing over to the
// next, or both.
PlannedBuffer in(PlannedBuffer b) {
  b.received = true;
  return b;
}
PlannedBuffer out(PlannedBuffer b) {
  b.handed = true;
  return b;
}
PlannedBuffer through(PlannedBuffer b) {
  return in(out(std::move(b)));
}

// The stages reading the terrain hold it whole (four REAL32 maps) or as the disparity plus one
// row worked out again; range makes it, zones passes it on, path reads it.
std::vector<PlannedBuffer> terrain_stage_buffers(std::string_view process, const Geometry& g,
                                                 bool kept) {
  const PlannedBuffer maps = image("terrain points (forward, left, elevation, range)", g, 16);
  const PlannedBuffer disparity = image("seeable disparity (the terrain, kept)", g, 4);
  if (process == "range") {
    // Range holds what it received until it has handed the terrain on.
    std::vector<PlannedBuffer> buffers{through(image("seeable disparity", g, 4)),
                                       through(image("validity", g, 1))};
    buffers.push_back(kept ? out(maps) : terrain_row(g));
    return buffers;
  }
  std::vector<PlannedBuffer> buffers;
  if (kept)
    buffers.push_back(process == "zones" ? through(maps) : in(maps));
  else
    buffers.insert(buffers.end(),
                   {process == "zones" ? through(disparity) : in(disparity), terrain_row(g)});
  if (process == "zones") {
    buffers.push_back(in(image("validity", g, 1))); // let go before the hand-over
    buffers.push_back(out(image("zone map", g, 1)));
    return buffers;
  }
  buffers.push_back(in(image("zone map", g, 1)));
  buffers.push_back(image("row sweep costs", g, 4));
  buffers.push_back(image("row sweep steps", g, 1));
  return buffers;
}

// What each process holds at its peak: the images and maps it receives, keeps and hands on.
std::vector<PlannedBuffer> buffers_of(std::string_view process, const Geometry& g,
                                      bool terrain_kept) {
  if (process == "acquire")
    return {out(image("camera image", g, 1))};
  // Features and matching hold everything until their last hand-over.
  if (process == "features")
    return {
        through(image("left image", g, 1)), through(image("right image", g, 1)),
        out({fmt::format("pyramid layers 1..{}, both eyes", g.levels - 1), 2 * g.pyramid_pixels()}),
        out(image("census features, left", g, 1)), out(image("census features, right", g, 1))};
  if (process == "matching")
    return {through(image("left layer", g, 1)), through(image("census features, left", g, 1)),
            through(image("census features, right", g, 1)),
            out({"coarser layer's disparity and validity", g.pixels() / 4 * 5}),
            out({buffer_name("a band of disparity and validity", nav::kMatchedBandRows, g.width, 5),
                 static_cast<std::size_t>(nav::kMatchedBandRows * g.width) * 5})};
  // Refine lets go of the image, the filled disparity and the mask before its hand-over.
  if (process == "refine")
    return {in(image("left image", g, 1)), in(image("disparity, filled and smoothed", g, 4)),
            through(image("validity", g, 1)), image("texture mask", g, 1),
            out(image("seeable disparity", g, 4))};
  if (process == "range" || process == "zones" || process == "path")
    return terrain_stage_buffers(process, g, terrain_kept);
  if (process == "drive")
    return {
        in({buffer_name("ground path", g.height, 1, 16), static_cast<std::size_t>(g.height) * 16})};
  return {};
}

} // namespace

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
                     const Geometry& geometry, std::optional<std::size_t> external_bytes,
                     bool terrain_kept) {
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
                                     buffers_of(process.name, geometry, terrain_kept)});
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
  const Geometry geometry{width, height, pyramid_levels};
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

} // namespace marsokhod::occam_port
