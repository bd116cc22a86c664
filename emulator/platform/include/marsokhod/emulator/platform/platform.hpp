// Platform and processor files: the nodes, devices and wiring of a transputer network.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/memory/memory_arena.hpp"
#include "marsokhod/emulator/node/cost_table.hpp"
#include "marsokhod/io/formats/keyed_file_error.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace marsokhod::emulator {

/// A platform or processor file is wrong: names the file, the line and the key.
class PlatformError : public io::KeyedFileError {
public:
  using io::KeyedFileError::KeyedFileError;
};

/// Link framing and handshake timing of a processor type, in bit times of the wire's speed
/// plus one speed-independent latency (T805.md, "Links").
struct LinkTimingSpec {
  /// Data packet: start bit, 1, eight data bits, stop bit.
  double data_packet_bits = 11;
  /// Acknowledge packet: start bit, 0.
  double ack_packet_bits = 2;
  /// From the start bit of a data packet to the receiver's acknowledge, when the return wire
  /// is idle and an input is waiting.
  double ack_delay_bits = 0;
  /// From the end of an acknowledge at the sender to the earliest start bit of its next data
  /// packet: bit-time part and fixed part.
  double ack_turnaround_bits = 0;
  Tick ack_turnaround_fixed = 0;
  /// Idle bit times a wire keeps between two packets.
  double inter_packet_gap_bits = 0;
};

/// One processor node (a transputer module).
struct NodeSpec {
  std::string name;
  std::string speed_grade;
  CpuSpec cpu;
  MemoryConfig memory;
  bool powered = true;
  int links = 4;
  int line = 0; ///< where it is declared, for later messages
};

/// What a device does.
enum class DeviceKind : std::uint8_t {
  frame_store, ///< camera frame store serving images over its links
  host,        ///< the host computer behind a PC card's link adaptor
};

const char* to_string(DeviceKind kind);

/// A non-transputer peer of a link.
struct DeviceSpec {
  std::string name;
  DeviceKind kind = DeviceKind::host;
  int links = 1;
  bool powered = true;
  /// Frame store only: cameras and the image each serves.
  int cameras = 0;
  int image_width = 0;
  int image_height = 0;
  int bits_per_pixel = 0;
  int line = 0;
};

/// One end of a wire: link `link` of the node or device called `owner`.
struct LinkEndpoint {
  std::string owner;
  int link = 0;
  bool device = false;

  std::string text() const;
  friend bool operator==(const LinkEndpoint&, const LinkEndpoint&) = default;
};

/// A pair of wires (one per direction) joining two link endpoints.
struct WireSpec {
  LinkEndpoint a;
  LinkEndpoint b;
  int speed_mbps = 10;
  /// A broken cable: nothing crosses it.
  bool broken = false;
  int line = 0;
};

/// A whole platform: the processor type, nodes, devices and wiring.
/// The overswitch: a hardware block (not a transputer) that powers some of the modules, keeps
/// a watchdog per powered module and chooses which spare to power when one fails (the logic is
/// the overswitch layer's; these are its timings).
struct OverswitchSpec {
  /// The modules it switches, in the order spares are taken; the first `powered_at_once` that
  /// the platform powers are the pair it starts with.
  std::vector<std::string> modules;
  int powered_at_once = 2;
  Tick heartbeat_period = 0; ///< a powered module's heartbeat process kicks its watchdog this often
  Tick watchdog_timeout = 0; ///< a watchdog not kicked for this long declares its module failed
  Tick boot_allowance = 0;   ///< a spare not running this long after its power-on has failed
  /// A message on a link between modules not acknowledged this long after its output began is
  /// given up and reported (OutputOrFail); nothing: the program waits on its links for ever.
  std::optional<Tick> link_timeout;
  int line = 0;
};

struct PlatformSpec {
  std::string name;
  std::string description;
  std::string source; ///< the file it was read from
  std::string processor_type;
  std::vector<int> link_speeds_mbps;
  /// The processor's cycle time by speed grade ("T805-30" -> 33'333 ps), for what-if runs.
  std::map<std::string, Tick, std::less<>> speed_grades;
  LinkTimingSpec link_timing;
  std::vector<NodeSpec> nodes;
  std::vector<DeviceSpec> devices;
  std::vector<WireSpec> wires;
  std::optional<OverswitchSpec> overswitch;

  const NodeSpec* find_node(const std::string& name) const;
  const DeviceSpec* find_device(const std::string& name) const;
  /// The wire at an endpoint, or nullptr when that link is unconnected.
  const WireSpec* wire_at(const LinkEndpoint& endpoint) const;
  /// A wire directly joining nodes `x` and `y`, either way round; a sound one if there is one,
  /// else a broken one (so that a message can say the cable is broken, not missing); nullptr
  /// if none joins them.
  const WireSpec* wire_between(const std::string& x, const std::string& y) const;
};

/// Reads a platform file and the processor file it names (relative to the platform file);
/// throws PlatformError for any unknown key, missing key or impossible value.
PlatformSpec load_platform(const std::filesystem::path& file);

/// Finds a shipped platform file by name ("onboard.toml") in $MARSOKHOD_PLATFORMS, then in
/// ./platforms, then in platforms/ beside the running executable or any folder above it (a
/// build tree inside the source tree). Throws PlatformError listing the places it looked.
std::filesystem::path find_platform_file(const std::string& name);

/// A platform a user names: the file `name` when one exists there or `name` has a '/', else the
/// shipped platform of that name ("onboard", "pc-card.toml"). Throws PlatformError.
PlatformSpec load_named_platform(const std::string& name);

} // namespace marsokhod::emulator
