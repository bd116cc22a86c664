// CycleNetwork: the emulated machine one cycle runs on (private to the layer).
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/links/link_frame_store.hpp"
#include "marsokhod/emulator/links/link_network.hpp"
#include "marsokhod/emulator/links/shared_output.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/nav_program/run/cycle_supervisor.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace marsokhod::nav_program::detail {

/// The kernel, links, devices and nodes of one cycle, with each node's shared device-link
/// output. Members in this order so that the nodes (and every process still on them) go first,
/// then the outputs they may be waiting at, the devices, the links and the kernel.
struct CycleNetwork {
  /// Where a node's device link ends: the device and its link number.
  struct DeviceEnd {
    emulator::FrameStore* device = nullptr;
    int link = 0;
  };

  emulator::Kernel kernel;
  std::unique_ptr<emulator::LinkNetwork> links;
  std::vector<std::unique_ptr<emulator::FrameStore>> devices;
  std::map<std::string, std::unique_ptr<emulator::SharedOutput>> device_outputs;
  std::map<std::string, DeviceEnd> device_ends;
  /// Every upload a device received, in order; `telemetry` holds their bytes.
  std::vector<DeviceUpload> uploads;
  std::vector<std::vector<std::byte>> telemetry;
  std::function<void(const std::string& node)> heartbeat_sink;
  std::function<void(const std::string& node, int link, LinkTrouble trouble)> trouble_sink;
  std::vector<std::unique_ptr<emulator::Node>> nodes;

  /// std::out_of_range for a node the platform does not have.
  emulator::Node& node(const std::string& name);
};

/// Builds the network of `platform` with the devices serving `input`'s images.
void build_network(CycleNetwork& net, const emulator::PlatformSpec& platform,
                   const CycleInput& input);

} // namespace marsokhod::nav_program::detail
