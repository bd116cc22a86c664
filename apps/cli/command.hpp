// The subcommand interface of the marsokhod command line and its exit-code errors.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace marsokhod::apps {

/// Exit codes shared by every subcommand.
enum ExitCode : int { kSuccess = 0, kRuntimeError = 1, kUsageError = 2 };

/// A runtime problem to report to the user (bad file, bad data); main prints it and exits 1.
class CommandError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// A usage problem the option parser cannot see (two options that exclude each other at run
/// time, a malformed range); main prints it and exits 2.
class UsageError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// One subcommand: its CLI11 node and what to run when it was chosen. The action returns the
/// exit code and reports problems by throwing CommandError or UsageError.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

/// Each subcommand file defines one of these; commands.cpp lists them in --help order.
using CommandFactory = Command (*)(CLI::App& parent);
const std::vector<CommandFactory>& command_factories();

/// Runs the whole command line; what main() returns. Separate from main so tests can call it.
int run_command_line(int argc, const char* const* argv);

} // namespace marsokhod::apps
