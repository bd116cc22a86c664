// FaultDraw: what run k of a campaign is, its scene and its fault, from the campaign's seed and
// k alone.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/overswitch/campaign/campaign_file.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// What run k is: its scene and its fault.
struct CampaignDraw {
  std::uint64_t run = 0;
  std::size_t scene = 0;
  overswitch::Fault fault;
};

/// Draws the runs of a campaign: the scene, then the kind of fault by its weight, the module,
/// the strike time over its share of the scene's fault-free cycle, the seed of what the fault
/// draws when it strikes, and for a link fault its link, duration and byte.
class FaultDraw {
public:
  /// overswitch::CampaignError, naming the file's line, when a module of the mix is no module
  /// of the platform's overswitch.
  FaultDraw(const overswitch::CampaignSpec& spec, const emulator::PlatformSpec& platform);

  /// Run k over scenes whose fault-free cycles are `golden_cycles` (at least one).
  CampaignDraw draw(std::uint64_t run, std::span<const emulator::Tick> golden_cycles) const;

private:
  const overswitch::CampaignSpec* spec_;
  /// The modules the platform powers at the start: a mix without modules draws from them.
  std::vector<std::string> powered_;
  double total_weight_ = 0.0;
};

/// The modules of the platform's overswitch that are powered at the start, in its order.
std::vector<std::string> powered_modules(const emulator::PlatformSpec& platform);

} // namespace marsokhod::eval
