// Placement files: which node of a platform runs each OCCAM process of the navigation program.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/io/formats/keyed_file_error.hpp"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace marsokhod::nav_program {

/// A placement file is wrong: names the file, the line and the key. what() has the shape of
/// every keyed file's error, emulator::PlatformError's among them, "FILE:LINE: 'KEY': problem"
/// ("FILE: ..." when the line is 0, without the key part when the key is empty), so that both
/// read alike on one command line.
class PlacementError : public io::KeyedFileError {
public:
  using io::KeyedFileError::KeyedFileError;
};

/// The navigation program's shape a placement is checked against. The program supplies it, so
/// that the file is checked against the processes that will really run, not a copy of them.
struct ProgramShape {
  /// A channel between two processes (named as in `processes`); it needs a wire when its ends
  /// run on different nodes.
  struct Channel {
    std::string name;
    std::string from;
    std::string to;
  };
  /// A process that needs a wire from its node to a device: images from the frame store,
  /// telemetry to the host. `purpose` is said in messages.
  struct DeviceUse {
    std::string process;
    std::string purpose;
  };

  std::vector<std::string> processes;
  std::vector<Channel> channels;
  /// Processes that need a wire from their node to a device (of frame_store or host kind).
  std::vector<DeviceUse> devices;
};

/// One process placed on one node.
struct ProcessPlace {
  std::string process;
  std::string node;
  int line = 0; ///< the line of its `node` key, where the file places it
};

/// Which node runs each process of the navigation program (a TOML file per platform).
struct Placement {
  std::string source;               ///< file read
  std::string platform;             ///< platform name the file is for
  std::string description;          ///< free text, empty when the file has none
  std::vector<ProcessPlace> places; ///< in file order

  /// The node of a process; std::out_of_range for a process not placed.
  const std::string& node_of(std::string_view process) const;
};

/// Reads and checks a placement file against the platform and the program: every key known and
/// of its type, the platform's name, each process of the program placed exactly once on a
/// powered node, a direct unbroken wire for every channel between two nodes and from the node
/// of every device use to a powered device. Throws PlacementError naming the file, line and
/// key; std::invalid_argument when the shape itself names a process it does not list (a
/// program error, not the file's).
Placement load_placement(const std::filesystem::path& file, const emulator::PlatformSpec& platform,
                         const ProgramShape& shape);

/// The default placement of a platform: placements/<platform.name>.toml in the folder of the
/// platform file (platform.source), so that a platform and its placement ship together.
/// Throws PlacementError (file = that path, line 0, key "") when absent.
std::filesystem::path default_placement_file(const emulator::PlatformSpec& platform);

} // namespace marsokhod::nav_program
