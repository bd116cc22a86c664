// The hardware costs of the protections.

#include "marsokhod/overswitch/protection/protection.hpp"

#include <algorithm>

namespace marsokhod::overswitch {

bool any(const Protection& protection) {
  return protection.edac || protection.link_checksums || protection.terrain_check;
}

emulator::PlatformSpec protected_platform(const emulator::PlatformSpec& platform,
                                          const Protection& protection) {
  emulator::PlatformSpec out = platform;
  if (!protection.edac || !out.overswitch)
    return out;
  const auto& modules = out.overswitch->modules;
  for (emulator::NodeSpec& node : out.nodes)
    if (std::find(modules.begin(), modules.end(), node.name) != modules.end())
      node.cpu.costs.wait_states += kEdacWaitStates;
  return out;
}

} // namespace marsokhod::overswitch
