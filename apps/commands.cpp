#include "command.hpp"

namespace marsokhod::apps {

// Each subcommand's factory, defined in its own <name>_command.cpp.

const std::vector<CommandFactory>& command_factories() {
  static const std::vector<CommandFactory> factories = {
      // Subcommands are added here.
  };
  return factories;
}

} // namespace marsokhod::apps
