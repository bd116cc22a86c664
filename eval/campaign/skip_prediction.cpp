// A run whose upset lands where it changes nothing, found from the fault-free run's memory.

#include "marsokhod/eval/campaign/skip_prediction.hpp"

#include "marsokhod/overswitch/faults/memory_strike.hpp"

namespace marsokhod::eval {

std::optional<overswitch::InjectedFault> unchanging_fault(const CampaignDraw& d,
                                                          const CampaignScene& scene,
                                                          const emulator::PlatformSpec& platform,
                                                          bool edac) {
  if (d.fault.kind != overswitch::Fault::Kind::upset || !d.fault.stage.empty())
    return std::nullopt;
  std::optional<overswitch::MemoryHit> hit =
      overswitch::locate_before_strike(platform.find_node(d.fault.module)->memory, edac, d.fault);
  if (!hit || hit->reserved)
    return std::nullopt;
  const overswitch::MemoryTimeline::Holding holding =
      scene.timeline.holding(d.fault.module, hit->address, d.fault.offset);
  if (!holding.sure)
    return std::nullopt;
  hit->block = holding.block;
  overswitch::InjectedFault fault{d.fault, d.fault.offset, hit, {}};
  if (hit->check_bit || (edac && !hit->on_chip)) {
    fault.hit->effect = emulator::UpsetEffect::corrected;
    fault.effect = "EDAC: corrected on every read";
    return fault;
  }
  if (holding.block)
    return std::nullopt;
  fault.effect = "none: free memory";
  return fault;
}

} // namespace marsokhod::eval
