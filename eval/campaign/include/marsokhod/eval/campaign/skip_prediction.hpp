// Which runs of a campaign their fault cannot change, so that they need not be emulated.
#pragma once

#include "marsokhod/eval/campaign/campaign_scene.hpp"
#include "marsokhod/eval/campaign/fault_draw.hpp"
#include "marsokhod/overswitch/supervision/failover_supervisor.hpp"

#include <optional>

namespace marsokhod::eval {

/// The fault of `draw` as it would strike the scene's fault-free run, when it cannot change that
/// run: an upset at a bit known before the run that lands in a check bit, in memory the EDAC
/// corrects, or in memory no block holds at the strike (docs/faults.md, "Speed"). Nothing for
/// every other fault: a stuck cell forces its value back after a clean write, and a bit drawn
/// over the allocated blocks depends on what the run holds.
std::optional<overswitch::InjectedFault> unchanging_fault(const CampaignDraw& draw,
                                                          const CampaignScene& scene,
                                                          const emulator::PlatformSpec& platform,
                                                          bool edac);

} // namespace marsokhod::eval
