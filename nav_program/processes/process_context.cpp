// A running process of the navigation program: its meter, its stage and its device link.

#include "processes/cycle_state.hpp"
#include "processes/program_processes.hpp"

#include "marsokhod/emulator/links/shared_output.hpp"
#include "marsokhod/nav_program/run/cycle_supervisor.hpp"

#include <stdexcept>

namespace marsokhod::nav_program::detail {

BlockChannel* CycleChannels::named(std::string_view name) {
#define MARSOKHOD_CHANNEL(channel, from, to)                                                       \
  if (name == #channel)                                                                            \
    return &channel;
#include "channels/channel_list.def"
  return nullptr;
}

// A kernel's buffers are image-sized: far beyond the 4 KB on chip, they go wherever the node
// places data, which is external memory unless a what-if run says otherwise.
ProcessContext::ProcessContext(CycleState& cycle, emulator::Node& node, const ProcessSpec& spec)
    : cycle_(&cycle), node_(&node), spec_(&spec), name_(spec.name),
      meter_(node, node.memory().default_placement() != emulator::Placement::on_chip,
             cycle.occam_style),
      recompute_meter_(node, node.memory().default_placement() != emulator::Placement::on_chip,
                       cycle.occam_style) {}

void ProcessContext::doing(std::string what) {
  what_ = std::move(what);
  node_->memory().set_label(name_, what_);
}

void ProcessContext::start_stage() {
  if (started_)
    return;
  started_ = node_->kernel().now();
  if (cycle_->supervisor != nullptr)
    cycle_->supervisor->stage_started(name_, *started_);
}

// A track per stage, so that overlapping stages of one node never have to nest.
void ProcessContext::end_stage() {
  const emulator::Tick now = node_->kernel().now();
  const emulator::Tick start = started_.value_or(now);
  cycle_->stages.push_back({name_, spec_->group, start, now});
  if (emulator::TraceSink* sink = node_->kernel().trace()) {
    const emulator::TrackId track = sink->track(node_->name(), "stage " + name_);
    sink->begin_slice(track, start, name_);
    sink->end_slice(track, now);
  }
}

emulator::LinkPort& ProcessContext::device_port() {
  return device_output().port();
}

emulator::SharedOutput& ProcessContext::device_output() {
  const auto found = cycle_->device_outputs.find(node_->name());
  if (found == cycle_->device_outputs.end() || found->second == nullptr)
    throw std::logic_error("process " + name_ + ": node " + node_->name() +
                           " has no link to a device");
  return *found->second;
}

} // namespace marsokhod::nav_program::detail
