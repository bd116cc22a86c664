// Work reports to CPU time: one unit's cycles from the cost table, times the units reported.

#include "marsokhod/nav_program/costs/emulated_meter.hpp"

#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/nav_program/costs/work_costs.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace marsokhod::nav_program {

// The cost model is linear in the units (integer and FPU streams of n units overlap exactly
// as one unit's do, n times over), so one unit's cycles are worked out once per kind.
EmulatedMeter::EmulatedMeter(emulator::Node& node, bool buffers_external, double occam_style)
    : node_(&node) {
  if (!(occam_style > 0.0))
    throw std::invalid_argument(
        fmt::format("an occam style factor of {} is not positive", occam_style));
  for (std::size_t k = 0; k < nav::kWorkKinds; ++k) {
    const std::uint64_t table =
        node.cycles_of(work_mix(static_cast<nav::Work>(k), 1, buffers_external));
    cycles_per_unit_[k] =
        static_cast<std::uint64_t>(std::llround(static_cast<double>(table) * occam_style));
  }
}

void EmulatedMeter::operator()(nav::Work kind, std::uint64_t count) {
  counts_(kind, count);
  if (count == 0)
    return;
  const emulator::Tick time = node_->cycles(count * cycles_per_unit(kind));
  charged_ += time;
  node_->consume(time);
}

} // namespace marsokhod::nav_program
