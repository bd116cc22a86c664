// A T805 node: CPU cost model, priorities, timers, memory and link ports.

#include "marsokhod/emulator/node/node.hpp"

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/memory/memory_arena_hooks.hpp"

#include <fmt/format.h>

#include <atomic>
#include <stdexcept>

namespace marsokhod::emulator {

namespace {

CpuTiming timing_of(const CpuSpec& cpu) {
  CpuTiming timing;
  timing.timeslice = cpu.timeslice;
  timing.slices_before_deschedule = cpu.slices_before_deschedule;
  timing.preemption_latency = static_cast<Tick>(cpu.costs.event_latency_cycles) * cpu.cycle;
  return timing;
}

/// The node's memory; a host that cannot map it is an error naming the node.
std::unique_ptr<MemoryArena> make_memory(const NodeSpec& spec) {
  try {
    return std::make_unique<MemoryArena>(spec.memory);
  } catch (const HostMemoryError& error) {
    throw HostMemoryError(fmt::format("node {} ({} KB of external memory): {}", spec.name,
                                      spec.memory.external_bytes / 1024, error.what()));
  }
}

/// Frees a process's workspace however the process ends (return or kill).
class WorkspaceLease {
public:
  WorkspaceLease(MemoryArena& arena, Address address) : arena_(arena), address_(address) {}
  WorkspaceLease(const WorkspaceLease&) = delete;
  WorkspaceLease& operator=(const WorkspaceLease&) = delete;
  ~WorkspaceLease() { arena_.free_block(address_); }

private:
  MemoryArena& arena_;
  Address address_;
};

std::atomic<std::uint64_t> last_serial{0};

} // namespace

Node::Node(Kernel& kernel, const NodeSpec& spec)
    : kernel_(&kernel), serial_(++last_serial), spec_(spec),
      cpu_(std::make_unique<Cpu>(kernel, spec.name, timing_of(spec.cpu))),
      memory_(make_memory(spec)), upsets_(std::make_unique<MemoryUpsets>(*memory_)),
      powered_(spec.powered) {
  cpu_->set_node(this);
  attach_memory(*memory_, kernel, spec_.name);
  if (TraceSink* sink = kernel.trace()) {
    events_track_ = sink->track(spec_.name, "events");
    if (!powered_) {
      // A cold spare: the trace shows from the start that the node is off.
      sink->instant(events_track_, kernel.now(), "power off", spec_.name);
    }
  }
}

Node::~Node() {
  // Processes first: their unwinding may still free memory or touch links.
  cpu_.reset();
}

void Node::no_current_node() {
  throw std::logic_error("Node::current() called outside a process running on a node");
}

void Node::compute(const InstructionMix& mix) {
  compute_cycles(cycles_of(mix));
}

Tick Node::timer_period(Priority priority) const {
  return priority == Priority::high ? spec_.cpu.high_timer_tick : spec_.cpu.low_timer_tick;
}

Process& Node::spawn(std::string name, std::function<void()> body, NodeSpawnOptions options) {
  if (!powered_)
    throw std::logic_error("cannot start process " + name + " on powered-off node " + spec_.name);
  SpawnOptions spawn_options{options.priority, options.stack_bytes, options.exit_hook};
  if (options.workspace_bytes == 0)
    return kernel_->spawn(*cpu_, std::move(name), std::move(body), spawn_options);
  const Address workspace = memory_->reserve_workspace(name, options.workspace_bytes);
  MemoryArena* arena = memory_.get();
  return kernel_->spawn(
      *cpu_, std::move(name),
      [arena, workspace, body = std::move(body)] {
        WorkspaceLease lease(*arena, workspace);
        body();
      },
      spawn_options);
}

void Node::attach_link(int index, Link& link, int end) {
  if (index < 0 || index >= kLinks)
    throw std::out_of_range("node " + spec_.name + " has no link " + std::to_string(index));
  links_[static_cast<std::size_t>(index)] = Attachment{&link, end};
  link.set_powered(end, powered_);
}

LinkPort* Node::link(int index) const {
  if (index < 0 || index >= kLinks)
    return nullptr;
  const Attachment& a = links_[static_cast<std::size_t>(index)];
  return a.link != nullptr ? &a.link->port(a.end) : nullptr;
}

void Node::power_off() {
  if (!powered_)
    return;
  powered_ = false;
  if (TraceSink* sink = kernel_->trace())
    sink->instant(events_track_, kernel_->now(), "power off", spec_.name);
  kernel_->kill_all(*cpu_);
  for (const Attachment& a : links_)
    if (a.link != nullptr)
      a.link->set_powered(a.end, false);
}

void Node::hang() {
  if (!powered_ || hung_)
    return;
  hung_ = true;
  if (TraceSink* sink = kernel_->trace())
    sink->instant(events_track_, kernel_->now(), "hang", spec_.name);
  kernel_->kill_all(*cpu_);
  for (const Attachment& a : links_)
    if (a.link != nullptr)
      a.link->set_powered(a.end, false);
}

void Node::power_on() {
  if (powered_)
    return;
  powered_ = true;
  hung_ = false;
  if (TraceSink* sink = kernel_->trace())
    sink->instant(events_track_, kernel_->now(), "power on", spec_.name);
  for (const Attachment& a : links_)
    if (a.link != nullptr)
      a.link->set_powered(a.end, true);
}

} // namespace marsokhod::emulator
