// The marsokhod command line: parses the subcommand, runs it, turns errors into exit codes.

#include "cli/command.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <system_error>

namespace marsokhod::apps {
namespace {

void print_error(const std::string& message) {
  fmt::print(stderr, "marsokhod: error: {}\n", message);
}

std::string stdout_problem(int error) {
  return std::string("cannot write standard output: ") +
         (error != 0 ? std::strerror(error) : "write error");
}

bool stdout_failed() {
  return std::ferror(stdout) != 0;
}

// Why an earlier write to stdout failed, when it did (0 when unknown): a flush that follows
// finds nothing left to write and cannot tell any more.
int earlier_stdout_error = 0;

void remember_stdout_error(int error) {
  if (stdout_failed() && earlier_stdout_error == 0)
    earlier_stdout_error = error;
}

// CLI11 prints help and version on std::cout and flushes it (std::endl); a failure there
// leaves its errno behind.
int print_by_cli11(CLI::App& app, const CLI::Error& e) {
  errno = 0;
  const int code = app.exit(e);
  remember_stdout_error(errno);
  return code;
}

// Everything printed goes through stdout's buffer (std::cout is synchronised with it). The
// results only count when they reached the file or pipe: a failed flush, or an earlier failed
// write, turns any exit code into 1.
int checked_stdout(int code) {
  errno = 0;
  std::cout.flush();
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (flushed && !stdout_failed())
    return code;
  print_error(stdout_problem(error != 0 ? error : earlier_stdout_error));
  return kRuntimeError;
}

int parse_and_run(CLI::App& app, const std::vector<Command>& commands, int argc,
                  const char* const* argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return print_by_cli11(app, e);
  } catch (const CLI::CallForAllHelp& e) {
    return print_by_cli11(app, e);
  } catch (const CLI::CallForVersion& e) {
    return print_by_cli11(app, e);
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
    } catch (const std::system_error& e) {
      // fmt throws this when a write to stdout fails; checked_stdout reports it, once.
      remember_stdout_error(e.code().value());
      if (!stdout_failed())
        print_error(e.what());
      return kRuntimeError;
    } catch (const std::exception& e) {
      if (!stdout_failed())
        print_error(e.what());
      return kRuntimeError;
    }
  }
  print_error("a subcommand is required; run 'marsokhod --help' for the list");
  return kUsageError;
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
  return checked_stdout(parse_and_run(app, commands, argc, argv));
}

} // namespace marsokhod::apps
