// Heartbeats, watchdogs, faults and failover around one emulated cycle.

#include "marsokhod/overswitch/supervision/failover_supervisor.hpp"

#include "marsokhod/emulator/memory/memory_arena.hpp"
#include "marsokhod/overswitch/protection/scrubber.hpp"
#include "marsokhod/overswitch/supervision/heartbeat.hpp"
#include "marsokhod/overswitch/supervision/link_boot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace marsokhod::overswitch {

FailoverSupervisor::FailoverSupervisor(const emulator::PlatformSpec& platform,
                                       std::vector<Fault> faults, Protection protection)
    : platform_(&platform), faults_(std::move(faults)), protection_(protection),
      scheduled_(faults_.size(), false) {
  if (!platform.overswitch)
    throw std::invalid_argument(fmt::format(
        "platform {} has no [overswitch] table: no failover to supervise", platform.name));
}

FailoverSupervisor::~FailoverSupervisor() = default;

void FailoverSupervisor::attach(nav_program::CycleControl& control) {
  control_ = &control;
  const emulator::OverswitchSpec& spec = *platform_->overswitch;
  std::vector<emulator::Node*> modules;
  for (const std::string& name : spec.modules)
    modules.push_back(&control.node(name));
  overswitch_ = std::make_unique<Overswitch>(
      control.kernel(), spec, modules,
      [this](emulator::Node& spare, emulator::Node& from, std::function<void()> done) {
        boot(spare, from, std::move(done));
      });
  overswitch_->on_booted([this](const Failover& failover) { booted(failover); });
  overswitch_->on_safe_stop([this] {
    const std::string why = overswitch_->events().back().detail;
    control_->kernel().schedule_after(
        0, emulator::event_priority::normal, [this, why] { control_->abandon(why); });
  });
  control.on_link_trouble(
      [this](const std::string& module, int link, nav_program::LinkTrouble trouble) {
        link_trouble(module, link, trouble);
      });
  control.on_heartbeat([this](const std::string& node) {
    const auto& names = platform_->overswitch->modules;
    if (std::find(names.begin(), names.end(), node) != names.end())
      overswitch_->kick(control_->node(node));
  });
  for (emulator::Node* module : modules) {
    if (timeline_ != nullptr)
      timeline_->record(module->name(), module->memory(), control.kernel());
    protect(*module);
    if (module->running())
      if (emulator::SharedOutput* output = control.device_output(module->name()))
        start_heartbeat(*module, *output, spec.heartbeat_period, heartbeats_stop_);
  }
  overswitch_->start();
  for (std::size_t i = 0; i < faults_.size(); ++i)
    if (faults_[i].stage.empty()) {
      scheduled_[i] = true;
      schedule(faults_[i], faults_[i].offset);
    }
}

void FailoverSupervisor::stage_started(const std::string& process, emulator::Tick at) {
  for (std::size_t i = 0; i < faults_.size(); ++i)
    if (!scheduled_[i] && faults_[i].stage == process) {
      scheduled_[i] = true;
      schedule(faults_[i], at + faults_[i].offset);
    }
}

void FailoverSupervisor::program_finished() {
  if (injected_.size() <= overswitch_->failovers().size()) {
    wind_down();
    return;
  }
  const emulator::OverswitchSpec& spec = *platform_->overswitch;
  control_->kernel().schedule_after(spec.heartbeat_period + spec.watchdog_timeout +
                                        spec.boot_allowance,
                                    emulator::event_priority::normal, [this] { wind_down(); });
}

void FailoverSupervisor::wind_down() {
  heartbeats_stop_ = true;
  overswitch_->stop();
}

void FailoverSupervisor::detach() {
  if (timeline_ != nullptr)
    timeline_->stop();
  if (overswitch_)
    overswitch_->stop();
  control_ = nullptr;
}

// Power changes settle before anything else at their instant.
void FailoverSupervisor::schedule(const Fault& fault, emulator::Tick at) {
  control_->kernel().schedule_at(
      at, emulator::event_priority::power, [this, fault] { inject(fault); });
}

void FailoverSupervisor::inject(const Fault& fault) {
  emulator::Node* node = nullptr;
  try {
    node = &control_->node(fault.module);
  } catch (const std::out_of_range&) {
    error_ = fmt::format("fault {}: the platform has no module {}", describe(fault), fault.module);
    control_->abandon(*error_);
    return;
  }
  injected_.push_back({fault, control_->kernel().now(), std::nullopt, {}});
  switch (fault.kind) {
  case Fault::Kind::hang:
    node->hang();
    return;
  case Fault::Kind::power_loss:
    node->power_off();
    return;
  case Fault::Kind::leak:
    leak(*node, fault);
    return;
  case Fault::Kind::upset:
  case Fault::Kind::stuck:
    strike(*node, injected_.back());
    return;
  case Fault::Kind::link_down:
  case Fault::Kind::link_bit:
  case Fault::Kind::ack_lost:
    strike_link(*node, injected_.back());
    return;
  }
}

// By default the leak takes the largest free block of the memory the buffers come from, so the
// module's next buffer of any size there fails (a halted or unpowered module leaks nothing).
void FailoverSupervisor::leak(emulator::Node& node, const Fault& fault) {
  if (!node.running())
    return;
  emulator::MemoryArena& memory = node.memory();
  const std::size_t free = memory.largest_free_block(memory.default_placement());
  const std::size_t bytes = std::min(free, fault.leak_bytes.value_or(free));
  if (bytes == 0)
    return;
  memory.allocate_block(bytes, emulator::MemoryArena::kWordBytes, memory.default_placement(),
                        "leak");
}

// The bit is struck in whatever the module's memory holds now. Data is left for the program to
// read; what the processor itself runs on (code, a workspace, its reserved words) is not
// emulated bit for bit, so a hit there is taken to send the module astray: it hangs, and its
// watchdog sees it. An error the EDAC cannot correct is flagged, and the module halts.
void FailoverSupervisor::strike(emulator::Node& node, InjectedFault& injected) {
  if (!node.powered()) {
    injected.effect = "none: the module is off";
    return;
  }
  try {
    injected.hit = strike_memory(node, injected.fault);
  } catch (const MemoryTargetError& error) {
    error_ = fmt::format("fault {}: {}", describe(injected.fault), error.what());
    control_->abandon(*error_);
    return;
  }
  const MemoryHit& hit = *injected.hit;
  if (hit.effect == emulator::UpsetEffect::uncorrectable) {
    injected.effect = "EDAC: uncorrectable, module halted";
    control_->halt(node.name(), fmt::format("word #{:08X}", hit.address & ~3U),
                   "EDAC: uncorrectable error, two in one word");
    return;
  }
  if (hit.effect == emulator::UpsetEffect::corrected) {
    injected.effect = "EDAC: corrected on every read";
    return;
  }
  if (hit.corrupts_control() && node.running()) {
    injected.effect = "module hung: " + hit.buffer() + " struck";
    node.hang();
    return;
  }
  injected.effect = hit.corrupts_data() ? "data corrupted" : "none: free memory";
}

// EDAC on the module's external memory, and, on a running module, its scrubber.
void FailoverSupervisor::protect(emulator::Node& module) {
  module.upsets().set_edac_on_external(protection_.edac);
  if (protection_.edac && protection_.scrub_period && module.running())
    start_scrubber(module, *protection_.scrub_period, heartbeats_stop_);
}

// The spare takes the place of the oldest module that failed with a share of the program.
void FailoverSupervisor::boot(emulator::Node& spare, emulator::Node& from,
                              std::function<void()> done) {
  const std::string& failed = overswitch_->failovers().back().failed;
  if (control_->code_bytes(failed) > 0)
    vacated_.push_back(failed);
  const std::size_t code = vacated_.empty() ? 0 : control_->code_bytes(vacated_.front());
  boot_over_link(control_->platform(), control_->links(), spare, from, code, std::move(done));
}

void FailoverSupervisor::booted(const Failover& failover) {
  emulator::Node& spare = control_->node(failover.spare);
  protect(spare);
  if (emulator::SharedOutput* output = control_->device_output(spare.name()))
    start_heartbeat(spare, *output, platform_->overswitch->heartbeat_period, heartbeats_stop_);
  if (vacated_.empty() || control_->program_finished())
    return;
  const std::string vacated = vacated_.front();
  vacated_.erase(vacated_.begin());
  control_->kernel().schedule_after(0, emulator::event_priority::normal,
                                    [this, vacated, spare = failover.spare] {
                                      control_->restart({{vacated, spare}});
                                    });
}

} // namespace marsokhod::overswitch
