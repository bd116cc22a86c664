// Drawing run k's scene and fault from SplitMix64(seed, k).

#include "marsokhod/eval/campaign/fault_draw.hpp"

#include "marsokhod/overswitch/faults/split_mix.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace marsokhod::eval {
namespace {

namespace emu = emulator;

void draw_link(overswitch::Fault& fault, const overswitch::FaultMix& mix,
               overswitch::SplitMix& random) {
  fault.link = mix.links[random.below(mix.links.size())];
  fault.direction = mix.direction;
  if (mix.down_for_s) {
    const auto [shortest, longest] = *mix.down_for_s;
    fault.duration = static_cast<emu::Tick>((shortest + random.unit() * (longest - shortest)) *
                                            static_cast<double>(emu::kSecond));
  }
  fault.byte = random.below(mix.byte_within);
}

void check_modules(const overswitch::CampaignSpec& spec, const emu::PlatformSpec& platform) {
  const auto& modules = platform.overswitch->modules;
  for (const overswitch::FaultMix& mix : spec.faults)
    for (const std::string& module : mix.modules)
      if (std::find(modules.begin(), modules.end(), module) == modules.end())
        throw overswitch::CampaignError(
            spec.source, mix.line, "modules",
            fmt::format("'{}' is no module of {}'s overswitch", module, platform.name));
}

// The mix whose share of the total weight `pick` falls in.
const overswitch::FaultMix& mix_at(const std::vector<overswitch::FaultMix>& faults, double pick) {
  for (const overswitch::FaultMix& candidate : faults) {
    if (pick < candidate.weight)
      return candidate;
    pick -= candidate.weight;
  }
  return faults.back();
}

} // namespace

std::vector<std::string> powered_modules(const emu::PlatformSpec& platform) {
  std::vector<std::string> names;
  for (const std::string& module : platform.overswitch->modules)
    if (platform.find_node(module)->powered)
      names.push_back(module);
  return names;
}

FaultDraw::FaultDraw(const overswitch::CampaignSpec& spec, const emu::PlatformSpec& platform)
    : spec_(&spec), powered_(powered_modules(platform)) {
  check_modules(spec, platform);
  for (const overswitch::FaultMix& mix : spec.faults)
    total_weight_ += mix.weight;
}

// Scene, kind by weight, module, then the strike time over the fault-free cycle's share.
CampaignDraw FaultDraw::draw(std::uint64_t run, std::span<const emu::Tick> golden_cycles) const {
  overswitch::SplitMix random(spec_->seed, run);
  CampaignDraw d;
  d.run = run;
  d.scene = random.below(golden_cycles.size());
  const overswitch::FaultMix& mix = mix_at(spec_->faults, random.unit() * total_weight_);
  const std::vector<std::string>& modules = mix.modules.empty() ? powered_ : mix.modules;
  d.fault.kind = mix.kind;
  d.fault.memory = mix.memory;
  d.fault.module = modules[random.below(modules.size())];
  const auto cycle = static_cast<double>(golden_cycles[d.scene]);
  const double share = mix.from_share + random.unit() * (mix.to_share - mix.from_share);
  d.fault.offset = static_cast<emu::Tick>(share * cycle);
  d.fault.draw = random.next();
  if (overswitch::is_link_fault(mix.kind))
    draw_link(d.fault, mix, random);
  return d;
}

} // namespace marsokhod::eval
