#include "command.hpp"

namespace marsokhod::apps {

// Each subcommand's factory, defined in its own <name>_command.cpp.
Command make_world_command(CLI::App& parent);
Command make_image_command(CLI::App& parent);
Command make_rig_command(CLI::App& parent);

const std::vector<CommandFactory>& command_factories() {
  static const std::vector<CommandFactory> factories = {
      make_world_command,
      make_image_command,
      make_rig_command,
  };
  return factories;
}

} // namespace marsokhod::apps
