// The marsokhod command line: parses the subcommand, runs it, turns errors into exit codes.

#include "command.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <exception>

namespace marsokhod::apps {
namespace {

void print_error(const std::string& message) {
  fmt::print(stderr, "marsokhod: error: {}\n", message);
}

} // namespace

int run_command_line(int argc, const char* const* argv) {
  CLI::App app{"marsokhod: Marsokhod rover stereo navigation on an emulated T805 transputer "
               "network, and the synthetic Mars world to test it in.",
               "marsokhod"};
  // At most one; "none" is reported below, so that an unknown word is named as such first.
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", "marsokhod 0.1.0");
  app.footer("Run 'marsokhod COMMAND --help' for the options of one command.");

  std::vector<Command> commands;
  for (CommandFactory factory : command_factories())
    commands.push_back(factory(app));

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kUsageError;
  }

  for (const Command& command : commands) {
    if (!command.app->parsed())
      continue;
    try {
      return command.run();
    } catch (const UsageError& e) {
      print_error(e.what());
      return kUsageError;
    } catch (const std::exception& e) {
      print_error(e.what());
      return kRuntimeError;
    }
  }
  print_error("a subcommand is required; run 'marsokhod --help' for the list");
  return kUsageError;
}

} // namespace marsokhod::apps
