// One emulated navigation cycle: the network built from the platform, the processes started
// where the placement says, the run, and its figures.

#include "navigation/cycle_accounting.hpp"
#include "navigation/cycle_state.hpp"
#include "navigation/placement_checks.hpp"
#include "navigation/program_processes.hpp"

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/links/link_frame_store.hpp"
#include "marsokhod/emulator/links/link_network.hpp"
#include "marsokhod/emulator/memory/memory_arena_fault.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace marsokhod::occam_port {
namespace {

using detail::CycleState;
using detail::ProcessContext;

/// Host stack of each process: the nav kernels keep their buffers in the node's memory, but
/// their frames (SIMD blocks, small arrays) need more than the kernel's default.
constexpr std::size_t kProcessStackBytes = 512 * 1024;

void check_input(const CycleInput& input) {
  if (input.rig == nullptr)
    throw std::invalid_argument("emulated cycle: no rig");
  nav::check_images_fit(input.left, input.right, *input.rig);
  nav::validate(input.options.zones);
  nav::validate(input.options.planner);
  nav::validate(input.options.drive);
}

emulator::PlatformSpec what_if(const emulator::PlatformSpec& platform,
                               std::optional<std::size_t> external_bytes) {
  emulator::PlatformSpec changed = platform;
  if (external_bytes)
    for (emulator::NodeSpec& node : changed.nodes)
      node.memory.external_bytes = *external_bytes;
  return changed;
}

std::vector<std::byte> image_bytes(imaging::ImageView<const std::uint8_t> image) {
  std::vector<std::byte> bytes;
  bytes.reserve(static_cast<std::size_t>(image.width() * image.height()));
  for (int y = 0; y < image.height(); ++y) {
    const auto* row = reinterpret_cast<const std::byte*>(image.row(y));
    bytes.insert(bytes.end(), row, row + image.width());
  }
  return bytes;
}

/// The network of one cycle: kernel, links, nodes, devices. Members in this order so that the
/// nodes (and every process still on them) go first, then the links and the kernel.
struct Network {
  emulator::Kernel kernel;
  std::unique_ptr<emulator::LinkNetwork> links;
  std::vector<std::unique_ptr<emulator::FrameStore>> devices;
  std::vector<std::unique_ptr<emulator::Node>> nodes;

  emulator::Node& node(const std::string& name) {
    return **std::find_if(
        nodes.begin(), nodes.end(), [&name](const auto& n) { return n->name() == name; });
  }
};

void build(Network& net, const emulator::PlatformSpec& platform, const CycleInput& input,
           CycleState& cycle) {
  net.links = std::make_unique<emulator::LinkNetwork>(net.kernel, platform);
  for (const emulator::NodeSpec& spec : platform.nodes) {
    net.nodes.push_back(std::make_unique<emulator::Node>(net.kernel, spec));
    net.links->attach(*net.nodes.back());
  }
  const std::vector<std::byte> left = image_bytes(input.left);
  const std::vector<std::byte> right = image_bytes(input.right);
  // Both kinds of device serve the program: the frame store holds the pair's images, and the
  // host PC of a card serves them the same way.
  for (const emulator::DeviceSpec& device : platform.devices) {
    emulator::DeviceSpec serving = device;
    serving.kind = emulator::DeviceKind::frame_store;
    serving.cameras = 2;
    serving.image_width = input.left.width();
    serving.image_height = input.left.height();
    serving.bits_per_pixel = 8;
    net.devices.push_back(std::make_unique<emulator::FrameStore>(
        *net.links, serving, [left, right](int camera) { return camera == 0 ? left : right; },
        [&cycle](int, std::vector<std::byte> bytes) {
          cycle.telemetry.push_back(std::move(bytes));
        }));
  }
  for (const emulator::NodeSpec& node : platform.nodes)
    if (const emulator::WireSpec* wire = detail::device_wire(platform, node.name))
      cycle.device_ports[node.name] =
          net.links->port(node.name, wire->a.owner == node.name ? wire->a.link : wire->b.link);
}

// Channels between nodes go on the wire joining them: load_placement has checked that there
// is a sound one, and that no two channels share a direction.
void place_channels(Network& net, const emulator::PlatformSpec& platform,
                    const Placement& placement, CycleState& cycle) {
  for (const ProgramShape::Channel& channel : navigation_program_shape().channels) {
    const std::string& from = placement.node_of(channel.from);
    const std::string& to = placement.node_of(channel.to);
    if (from == to)
      continue;
    const emulator::WireSpec* wire = detail::wire_between(platform, from, to);
    if (wire == nullptr || wire->broken)
      throw std::logic_error("channel " + channel.name + " has no wire from " + from + " to " + to);
    const bool forward = wire->a.owner == from;
    cycle.channels.named(channel.name)
        ->place_on_link(net.links->require_port(from, forward ? wire->a.link : wire->b.link),
                        net.links->require_port(to, forward ? wire->b.link : wire->a.link));
  }
}

void record_fault(CycleState& cycle, emulator::Node& node, const emulator::MemoryFault& fault,
                  const std::string& what) {
  if (cycle.fault)
    return;
  cycle.fault = MemoryFaultFigures{node.name(), fault.process(),    fault.requested_bytes(),
                                   what,        fault.free_bytes(), fault.largest_free_block()};
}

void spawn_processes(Network& net, const Placement& placement, CycleState& cycle) {
  for (const detail::ProcessSpec& spec : detail::program_processes()) {
    emulator::Node& node = net.node(placement.node_of(spec.name));
    const std::string name(spec.name);
    auto body = [&cycle, &node, name] {
      ProcessContext context(cycle, node, name);
      try {
        detail::run_process(context);
        context.end_stage();
      } catch (const emulator::MemoryFault& fault) {
        record_fault(cycle, node, fault, context.what());
        cycle.kernel->stop();
      } catch (const std::exception& error) {
        if (!cycle.error)
          cycle.error = fmt::format("process {} on {}: {}", name, node.name(), error.what());
        cycle.kernel->stop();
      }
      for (std::size_t k = 0; k < nav::kWorkKinds; ++k) {
        const auto kind = static_cast<nav::Work>(k);
        cycle.work(kind, context.emulated_meter().counts().count(kind));
        cycle.recomputed_work(kind, context.emulated_recompute_meter().counts().count(kind));
      }
    };
    try {
      node.spawn(name, std::move(body),
                 emulator::NodeSpawnOptions{spec.priority, kProcessStackBytes, spec.workspace_bytes,
                                            nullptr});
    } catch (const emulator::MemoryFault& fault) {
      record_fault(cycle, node, fault,
                   fmt::format("workspace of {}, {} B", name, spec.workspace_bytes));
      return;
    }
  }
}

// The program's code, loaded before it starts: a block per node the size of its processes'.
bool load_code(Network& net, const MemoryPlan& plan, CycleState& cycle) {
  for (const NodePlan& node_plan : plan.nodes) {
    emulator::Node& node = net.node(node_plan.node);
    try {
      node.memory().allocate_block(node_plan.code_bytes, emulator::MemoryArena::kWordBytes,
                                   emulator::Placement::on_chip_then_external, "code");
    } catch (const emulator::MemoryFault& fault) {
      record_fault(cycle, node, fault, fmt::format("code, {} B", node_plan.code_bytes));
      return false;
    }
  }
  return true;
}

void collect_figures(Network& net, const emulator::PlatformSpec& platform,
                     const Placement& placement, const detail::CycleAccounting& accounting,
                     CycleEmulation& out) {
  for (const detail::ProcessSpec& spec : detail::program_processes()) {
    ProcessFigures figures{std::string(spec.name), placement.node_of(spec.name), 0, 0};
    if (const auto found = accounting.cpu_time().find({figures.node, figures.name});
        found != accounting.cpu_time().end())
      figures.cpu = found->second;
    for (const emulator::OwnerUsage& owner : net.node(figures.node).memory().owners())
      if (owner.owner == figures.name)
        figures.peak_bytes = owner.peak_bytes;
    out.processes.push_back(std::move(figures));
  }
  for (const emulator::NodeSpec& spec : platform.nodes) {
    emulator::Node& node = net.node(spec.name);
    out.nodes.push_back({spec.name, node.powered(), node.cpu().busy_time(),
                         node.memory().usage().peak_bytes,
                         spec.memory.on_chip_bytes + spec.memory.external_bytes});
  }
  for (const auto& link : net.links->links())
    for (int end = 0; end < 2; ++end) {
      const emulator::LinkPort& port = link->port(end);
      if (port.bytes_sent() > 0)
        out.links.push_back(
            {port.name(), link->port(1 - end).name(), port.bytes_sent(), port.output_busy_time()});
    }
}

} // namespace

CycleEmulation emulate_navigation_cycle(const CycleInput& input, const CycleSetup& setup) {
  check_input(input);
  if (!(setup.occam_style > 0.0) || !std::isfinite(setup.occam_style))
    throw std::invalid_argument(
        fmt::format("an occam style factor of {} is not a positive number", setup.occam_style));
  const emulator::PlatformSpec platform = what_if(*setup.platform, setup.external_bytes);
  const Placement& placement = *setup.placement;
  CycleEmulation out;
  {
    std::pmr::vector<std::int16_t> unseen;
    const nav::StereoOptions stereo = nav::rover_stereo_options(*input.rig, input.options, unseen);
    nav::validate(stereo);
    out.plan = plan_memory(platform, placement, input.left.width(), input.left.height(),
                           nav::pyramid_levels_for(input.left.width(), input.left.height(), stereo),
                           std::nullopt);
  }
  CycleState cycle;
  cycle.width = input.left.width();
  cycle.height = input.left.height();
  cycle.rig = input.rig;
  cycle.options = input.options;
  cycle.plan = &out.plan;
  cycle.occam_style = setup.occam_style;
  detail::CycleAccounting accounting(setup.trace);
  Network net;
  cycle.kernel = &net.kernel;
  net.kernel.set_trace(&accounting);
  build(net, platform, input, cycle);
  place_channels(net, platform, placement, cycle);
  if (load_code(net, out.plan, cycle))
    spawn_processes(net, placement, cycle);
  const emulator::RunResult run = cycle.fault ? emulator::RunResult{} : net.kernel.run();
  if (cycle.error)
    throw std::runtime_error(*cycle.error);
  if (!cycle.fault && run.reason != emulator::StopReason::finished)
    throw std::logic_error(fmt::format("the navigation program stopped ({}) at {} us",
                                       emulator::to_string(run.reason),
                                       emulator::to_microseconds(net.kernel.now())));
  out.emulated = net.kernel.now();
  out.occam_style = setup.occam_style;
  out.stages = std::move(cycle.stages);
  out.memory_fault = cycle.fault;
  out.work = cycle.work;
  out.recomputed_work = cycle.recomputed_work;
  out.telemetry = std::move(cycle.telemetry);
  out.context_switches = net.kernel.context_switches();
  collect_figures(net, platform, placement, accounting, out);
  if (!cycle.fault)
    out.result = std::move(cycle.products);
  return out;
}

} // namespace marsokhod::occam_port
