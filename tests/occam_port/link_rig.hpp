// Two onboard modules joined by a link, for the occam layer's external channel tests.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/links/link_network.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/occam_port/channel.hpp"

#include <filesystem>

namespace marsokhod::occam_port::testing {

/// module0 and module1 of the onboard computer, joined by their link 0 at 10 Mbit/s.
struct TwoModules {
  emulator::PlatformSpec platform = emulator::load_platform(
      std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "platforms" / "onboard.toml");
  emulator::Kernel kernel;
  emulator::LinkNetwork network{kernel, platform};
  emulator::Node m0{kernel, *platform.find_node("module0")};
  emulator::Node m1{kernel, *platform.find_node("module1")};
  TwoModules() {
    network.attach(m0);
    network.attach(m1);
  }
  /// A channel from module `from` to the other over link 0.
  template <typename T>
  void wire(Chan<T>& channel, emulator::Node& from, emulator::Node& to) {
    channel.place_on_link(*from.link(0), *to.link(0));
  }
};

} // namespace marsokhod::occam_port::testing
