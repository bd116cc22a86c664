// Work reports to CPU time: one unit's cycles from the cost table, times the units reported.

#include "marsokhod/occam_port/navigation/emulated_meter.hpp"

#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/occam_port/navigation/work_costs.hpp"

namespace marsokhod::occam_port {

// The cost model is linear in the units (integer and FPU streams of n units overlap exactly
// as one unit's do, n times over), so one unit's cycles are worked out once per kind.
EmulatedMeter::EmulatedMeter(emulator::Node& node, bool buffers_external) : node_(&node) {
  for (std::size_t k = 0; k < nav::kWorkKinds; ++k)
    cycles_per_unit_[k] = node.cycles_of(work_mix(static_cast<nav::Work>(k), 1, buffers_external));
}

void EmulatedMeter::operator()(nav::Work kind, std::uint64_t count) {
  counts_(kind, count);
  if (count == 0)
    return;
  const emulator::Tick time = node_->cycles(count * cycles_per_unit(kind));
  charged_ += time;
  node_->kernel().consume(time);
}

} // namespace marsokhod::occam_port
