// The program's run on the network: started, and started again on other nodes after a failover.

#include "run/cycle_run.hpp"

#include "processes/mission_record.hpp"
#include "processes/program_processes.hpp"

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/links/link_frame_store.hpp"
#include "marsokhod/emulator/memory/memory_arena_fault.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <exception>
#include <stdexcept>

namespace marsokhod::nav_program::detail {
namespace {

/// Host stack of each process: the nav kernels keep their buffers in the node's memory, but
/// their frames (SIMD blocks, small arrays) need more than the kernel's default.
constexpr std::size_t kProcessStackBytes = 512 * 1024;

void record_fault(CycleState& cycle, emulator::Node& node, const emulator::MemoryFault& fault,
                  const std::string& what) {
  if (cycle.fault)
    return;
  cycle.fault = MemoryFaultFigures{node.name(),
                                   fault.process(),
                                   fault.requested_bytes(),
                                   what,
                                   fault.free_bytes(),
                                   fault.largest_free_block(),
                                   node.kernel().now()};
}

/// Keeps a process in its run's list of live ones until its body ends, killed or not; tells
/// `ended` whether it was killed (its stack unwinding).
class LiveEntry {
public:
  LiveEntry(std::vector<emulator::Process*>& live, emulator::Process* self,
            std::function<void(bool killed)> ended)
      : live_(live), self_(self), ended_(std::move(ended)) {}
  LiveEntry(const LiveEntry&) = delete;
  LiveEntry& operator=(const LiveEntry&) = delete;
  ~LiveEntry() {
    live_.erase(std::remove(live_.begin(), live_.end(), self_), live_.end());
    ended_(std::uncaught_exceptions() > 0);
  }

private:
  std::vector<emulator::Process*>& live_;
  emulator::Process* self_;
  std::function<void(bool killed)> ended_;
};

} // namespace

CycleRun::CycleRun(const CycleInput& input, const CycleSetup& setup,
                   const emulator::PlatformSpec& platform, const MemoryPlan& plan,
                   emulator::TraceSink* trace)
    : input_(&input), setup_(&setup), platform_(&platform), plan_(&plan),
      placement_(*setup.placement) {
  net_.kernel.set_trace(trace);
  for (const NodePlan& node : plan.nodes)
    roles_[node.node] = node.node;
  build_network(net_, platform, input);
  new_state();
}

void CycleRun::new_state() {
  auto cycle = std::make_unique<CycleState>();
  cycle->width = input_->left.width();
  cycle->height = input_->left.height();
  cycle->rig = input_->rig;
  cycle->options = input_->options;
  cycle->plan = plan_;
  cycle->occam_style = setup_->occam_style;
  cycle->kernel = &net_.kernel;
  cycle->supervisor = setup_->supervisor;
  cycle->mission_blocks = mission_blocks_;
  for (const auto& [node, output] : net_.device_outputs)
    cycle->device_outputs[node] = output.get();
  states_.push_back(std::move(cycle));
  place_channels();
}

// Channels between nodes go on the wire joining them: load_placement has checked that there
// is a sound one at the start, and a restart moves the program only onto running nodes.
void CycleRun::place_channels() {
  CycleState& cycle = state();
  for (const ProgramShape::Channel& channel : navigation_program_shape().channels) {
    const std::string& from = placement_.node_of(channel.from);
    const std::string& to = placement_.node_of(channel.to);
    if (from == to)
      continue;
    const emulator::WireSpec* wire = platform_->wire_between(from, to);
    if (wire == nullptr || wire->broken)
      throw std::logic_error("channel " + channel.name + " has no wire from " + from + " to " + to);
    const bool forward = wire->a.owner == from;
    BlockChannel* placed = cycle.channels.named(channel.name);
    placed->place_on_link(net_.links->require_port(from, forward ? wire->a.link : wire->b.link),
                          net_.links->require_port(to, forward ? wire->b.link : wire->a.link));
    if (setup_->supervisor != nullptr)
      placed->guard(
          setup_->supervisor->link_guard(),
          [this](emulator::LinkPort& port, LinkTrouble trouble) { report_trouble(port, trouble); });
  }
}

// From the process that met the trouble: the report goes to the overswitch on its module's
// device link, header and bytes in one turn of the shared output.
void CycleRun::report_trouble(emulator::LinkPort& port, LinkTrouble trouble) {
  emulator::Node& node = emulator::Node::current();
  int link = 0;
  while (link < emulator::Node::kLinks && node.link(link) != &port)
    ++link;
  emulator::SharedOutput* output = device_output(node.name());
  if (output == nullptr)
    return;
  const std::array<std::byte, 3> report{emulator::FrameStore::kReport,
                                        std::byte(static_cast<unsigned char>(link)),
                                        std::byte(static_cast<unsigned char>(trouble))};
  node.execute(emulator::Instruction::out);
  output->output(report);
}

// The code, and the mission state the last cycle left, are in every module's memory before the
// cycle starts.
bool CycleRun::start() {
  const MissionRecord mission = encode_mission(input_->mission);
  for (const NodePlan& node_plan : plan_->nodes) {
    emulator::Node& node = net_.node(node_plan.node);
    try {
      node.memory().allocate_block(node_plan.code_bytes, emulator::MemoryArena::kWordBytes,
                                   emulator::Placement::on_chip_then_external, "code",
                                   emulator::BlockKind::code);
    } catch (const emulator::MemoryFault& fault) {
      record_fault(state(), node, fault, fmt::format("code, {} B", node_plan.code_bytes));
      return false;
    }
    if (!hold_mission(node, mission))
      return false;
  }
  state().mission_blocks = mission_blocks_;
  spawn_processes();
  return !state().fault;
}

bool CycleRun::hold_mission(emulator::Node& node, std::span<const std::byte> record) {
  emulator::MemoryArena& memory = node.memory();
  try {
    memory.set_label("mission", "mission state");
    const emulator::Address block = memory.allocate_block(
        record.size(), emulator::MemoryArena::kWordBytes, emulator::Placement::external, "mission");
    std::memcpy(memory.pointer(block), record.data(), record.size());
    mission_blocks_[node.name()] = block;
  } catch (const emulator::MemoryFault& fault) {
    record_fault(state(), node, fault, fmt::format("mission state, {} B", record.size()));
    return false;
  }
  return true;
}

void CycleRun::spawn_processes() {
  CycleState& cycle = state();
  for (const ProcessSpec& spec : program_processes()) {
    emulator::Node& node = net_.node(placement_.node_of(spec.name));
    const std::string name(spec.name);
    auto body = [this, &cycle, &node, &spec, name] {
      const LiveEntry entry(cycle.live, cycle.kernel->current(), [this, &cycle](bool killed) {
        cycle.killed = cycle.killed || killed;
        process_ended();
      });
      ProcessContext context(cycle, node, spec);
      try {
        spec.body(context);
        context.end_stage();
      } catch (const emulator::MemoryFault& fault) {
        if (setup_->supervisor != nullptr) {
          halt_on_error(
              node, cycle,
              {node.name(), name, context.what(),
               fmt::format("memory fault: {} B asked for, {} B free, largest block {} B",
                           fault.requested_bytes(), fault.free_bytes(), fault.largest_free_block()),
               node.kernel().now()});
        } else {
          record_fault(cycle, node, fault, context.what());
          cycle.kernel->stop();
        }
      } catch (const std::exception& error) {
        // Under a supervisor a process's error is occam's run-time error: its module halts.
        // Without one it is the program's own bug and ends the run.
        if (setup_->supervisor != nullptr) {
          halt_on_error(node, cycle,
                        {node.name(), name, context.what(),
                         fmt::format("run-time error: {}", error.what()), node.kernel().now()});
        } else {
          if (!cycle.error)
            cycle.error = fmt::format("process {} on {}: {}", name, node.name(), error.what());
          cycle.kernel->stop();
        }
      }
      for (std::size_t k = 0; k < nav::kWorkKinds; ++k) {
        const auto kind = static_cast<nav::Work>(k);
        cycle.work(kind, context.emulated_meter().counts().count(kind));
        cycle.recomputed_work(kind, context.emulated_recompute_meter().counts().count(kind));
      }
    };
    try {
      cycle.live.push_back(&node.spawn(name, std::move(body),
                                       emulator::NodeSpawnOptions{spec.priority, kProcessStackBytes,
                                                                  spec.workspace_bytes, nullptr}));
    } catch (const emulator::MemoryFault& fault) {
      record_fault(cycle, node, fault,
                   fmt::format("workspace of {}, {} B", name, spec.workspace_bytes));
      return;
    }
  }
}

// HaltOnError: the module stops at once (from an event: a node cannot hang itself from one of
// its processes); this run cannot finish, and the error is kept with the halts.
void CycleRun::halt_on_error(emulator::Node& node, CycleState& cycle, ModuleHalt halt) {
  cycle.killed = true;
  halts_.push_back(std::move(halt));
  net_.kernel.schedule_after(0, emulator::event_priority::power, [&node] { node.hang(); });
}

void CycleRun::halt(const std::string& node, const std::string& what, const std::string& cause) {
  if (net_.kernel.current() != nullptr)
    throw std::logic_error("a module is halted from an event, not from a process");
  emulator::Node& module = net_.node(node);
  if (!module.running())
    return;
  halts_.push_back({node, {}, what, cause, net_.kernel.now()});
  module.hang();
}

// The program ends when its last process does.
void CycleRun::process_ended() {
  if (killing_ || !state().live.empty() || state().killed)
    return;
  finished_ = true;
  finished_at_ = net_.kernel.now();
  if (setup_->supervisor != nullptr)
    setup_->supervisor->program_finished();
}

void CycleRun::kill_program() {
  killing_ = true;
  const std::vector<emulator::Process*> live = state().live;
  for (emulator::Process* process : live)
    net_.kernel.kill(*process);
  killing_ = false;
}

// Both ends of the device link: a message cut short by the kill must not run into the next.
void CycleRun::reset_device_link(const std::string& node) {
  const auto end = net_.device_ends.find(node);
  if (end == net_.device_ends.end())
    return;
  emulator::LinkPort& port = net_.device_outputs.at(node)->port();
  port.link().set_powered(port.end(), false);
  port.link().set_powered(port.end(), true);
  end->second.device->reset_link(end->second.link);
}

emulator::SharedOutput* CycleRun::device_output(const std::string& node) {
  const auto found = net_.device_outputs.find(node);
  return found == net_.device_outputs.end() ? nullptr : found->second.get();
}

void CycleRun::on_heartbeat(std::function<void(const std::string& node)> sink) {
  net_.heartbeat_sink = std::move(sink);
}

void CycleRun::on_link_trouble(
    std::function<void(const std::string& node, int link, LinkTrouble trouble)> sink) {
  net_.trouble_sink = std::move(sink);
}

// A message cut short on a link, at either end, must not run into the restarted program's.
void CycleRun::reset_channel_links() {
  for (const ProgramShape::Channel& channel : navigation_program_shape().channels) {
    const std::string& from = placement_.node_of(channel.from);
    const std::string& to = placement_.node_of(channel.to);
    if (from == to || !net_.node(from).running() || !net_.node(to).running())
      continue;
    const emulator::WireSpec* wire = platform_->wire_between(from, to);
    if (wire == nullptr)
      continue;
    net_.links->require_port(wire->a.owner, wire->a.link).reset();
    net_.links->require_port(wire->b.owner, wire->b.link).reset();
  }
}

std::size_t CycleRun::code_bytes(const std::string& node) const {
  const auto role = roles_.find(node);
  if (role == roles_.end())
    return 0;
  for (const NodePlan& node_plan : plan_->nodes)
    if (node_plan.node == role->second)
      return node_plan.code_bytes + kMissionRecordBytes;
  return 0;
}

const std::string& CycleRun::node_of(const std::string& process) const {
  return placement_.node_of(process);
}

void CycleRun::restart(const std::map<std::string, std::string>& moved) {
  if (net_.kernel.current() != nullptr)
    throw std::logic_error("a cycle is restarted from an event, not from a process");
  kill_program();
  for (const auto& [from, to] : moved) {
    const auto role = roles_.find(from);
    if (role == roles_.end())
      throw std::logic_error(from + " runs none of the program to move");
    if (!net_.node(to).running())
      throw std::logic_error("the program cannot move onto " + to + ", which is not running");
    take_mission_from_survivor(from, to);
    roles_[to] = role->second;
    roles_.erase(role);
    for (ProcessPlace& place : placement_.places)
      if (place.node == from)
        place.node = to;
  }
  for (const auto& [node, role] : roles_)
    if (net_.node(node).running())
      reset_device_link(node);
  reset_channel_links();
  ++restarts_;
  new_state();
  spawn_processes();
}

// The spare's boot stream carried the survivor's copy of the mission state (code_bytes counts
// it): the cycle goes on from the state the survivor kept, not from the host's.
void CycleRun::take_mission_from_survivor(const std::string& failed, const std::string& spare) {
  mission_blocks_.erase(failed);
  for (const auto& [node, block] : mission_blocks_) {
    emulator::Node& survivor = net_.node(node);
    if (node == spare || !survivor.running())
      continue;
    const std::byte* record = survivor.memory().pointer(block);
    hold_mission(net_.node(spare), std::span(record, kMissionRecordBytes));
    return;
  }
}

void CycleRun::abandon(const std::string& why) {
  if (net_.kernel.current() != nullptr)
    throw std::logic_error("a cycle is abandoned from an event, not from a process");
  kill_program();
  abandoned_ = why;
  net_.kernel.stop();
}

} // namespace marsokhod::nav_program::detail
