// One emulated navigation cycle: the network built from the platform, the processes started
// where the placement says, the run, and its figures.

#include "processes/program_processes.hpp"
#include "run/cycle_accounting.hpp"
#include "run/cycle_run.hpp"

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace marsokhod::nav_program {
namespace {

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

void collect_figures(detail::CycleNetwork& net, const emulator::PlatformSpec& platform,
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
  detail::CycleAccounting accounting(setup.trace);
  detail::CycleRun run(input, setup, platform, out.plan, &accounting);
  detail::CycleNetwork& net = run.network();
  if (setup.supervisor != nullptr)
    setup.supervisor->attach(run);
  const bool started = run.start();
  const emulator::RunResult result = !started           ? emulator::RunResult{}
                                     : setup.time_limit ? net.kernel.run_until(*setup.time_limit)
                                                        : net.kernel.run();
  if (setup.supervisor != nullptr)
    setup.supervisor->detach();
  detail::CycleState& cycle = run.state();
  if (cycle.error)
    throw std::runtime_error(*cycle.error);
  const bool supervised_end =
      setup.supervisor != nullptr &&
      (run.finished() || run.abandoned() || result.reason == emulator::StopReason::time_limit);
  if (!cycle.fault && !supervised_end && result.reason != emulator::StopReason::finished)
    throw std::logic_error(fmt::format("the navigation program stopped ({}) at {} us",
                                       emulator::to_string(result.reason),
                                       emulator::to_microseconds(net.kernel.now())));
  out.emulated = run.finished() ? run.finished_at() : net.kernel.now();
  out.occam_style = setup.occam_style;
  out.stages = std::move(cycle.stages);
  out.memory_fault = cycle.fault;
  out.work = cycle.work;
  out.recomputed_work = cycle.recomputed_work;
  out.telemetry = std::move(net.telemetry);
  out.uploads = std::move(net.uploads);
  out.restarts = run.restarts();
  out.halts = run.halts();
  out.finished = run.finished();
  out.abandoned = run.abandoned();
  out.context_switches = net.kernel.context_switches();
  collect_figures(net, platform, run.placement(), accounting, out);
  if (!cycle.fault && run.finished()) {
    out.result = std::move(cycle.products);
    out.mission_after = cycle.mission_after;
  }
  return out;
}

std::string describe(const MemoryFaultFigures& fault) {
  return fmt::format("memory fault on {}: process {} wanted {} B for {}; {} B were free, the "
                     "largest free block {} B",
                     fault.node, fault.process, fault.requested_bytes, fault.what, fault.free_bytes,
                     fault.largest_free_block);
}

} // namespace marsokhod::nav_program
