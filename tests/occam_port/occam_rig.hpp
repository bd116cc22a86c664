// A kernel and one T805-30 node from the shipped pc-card platform, for the occam layer tests.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <string>

namespace marsokhod::occam_port::testing {

inline emulator::NodeSpec pc_card_node() {
  const auto platform =
      emulator::load_platform(std::string(MARSOKHOD_SOURCE_DIR) + "/platforms/pc-card.toml");
  return platform.nodes.front();
}

/// One emulated node; `cycles(n)` converts data-book cycle counts to simulated time.
struct OccamRig {
  emulator::Kernel kernel;
  emulator::Node node{kernel, pc_card_node()};

  emulator::Tick cycles(std::int64_t n) const { return n * node.cpu_spec().cycle; }
  emulator::Process& spawn(std::string name, std::function<void()> body,
                           emulator::Priority priority = emulator::Priority::low) {
    return node.spawn(std::move(name), std::move(body), emulator::NodeSpawnOptions{priority});
  }
};

} // namespace marsokhod::occam_port::testing
