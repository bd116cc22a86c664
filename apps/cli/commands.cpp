// The list of subcommands, in the order --help shows them.

#include "cli/command.hpp"

namespace marsokhod::apps {

// Each subcommand's factory, defined in its own <name>_command.cpp.
Command make_world_command(CLI::App& parent);
Command make_image_command(CLI::App& parent);
Command make_rig_command(CLI::App& parent);
Command make_eval_command(CLI::App& parent);
Command make_nav_command(CLI::App& parent);
Command make_calibrate_command(CLI::App& parent);
Command make_linktest_command(CLI::App& parent);
Command make_commstime_command(CLI::App& parent);
Command make_emulate_command(CLI::App& parent);
Command make_reproduce_command(CLI::App& parent);
Command make_fault_command(CLI::App& parent);
Command make_campaign_command(CLI::App& parent);
Command make_traverse_command(CLI::App& parent);
Command make_report_command(CLI::App& parent);

const std::vector<CommandFactory>& command_factories() {
  static const std::vector<CommandFactory> factories = {
      // Subcommands are added here.
      make_world_command,     make_image_command,     make_rig_command,      make_nav_command,
      make_calibrate_command, make_eval_command,      make_linktest_command, make_commstime_command,
      make_emulate_command,   make_reproduce_command, make_fault_command,    make_campaign_command,
      make_traverse_command,  make_report_command,
  };
  return factories;
}

} // namespace marsokhod::apps
