// The marsokhod executable's entry point.

#include "cli/command.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
  // A reader that closed the pipe is then a write error (EPIPE) the command line reports with
  // exit 1, not a silent death by signal.
  std::signal(SIGPIPE, SIG_IGN);
  int code = marsokhod::apps::run_command_line(argc, argv);
  // Closing is the last chance for the system to report a write error (some file systems only
  // do then). A run that already failed has said why.
  errno = 0;
  if (std::fclose(stdout) != 0 && code == marsokhod::apps::kSuccess) {
    fmt::print(stderr, "marsokhod: error: cannot write standard output: {}\n",
               errno != 0 ? std::strerror(errno) : "write error");
    code = marsokhod::apps::kRuntimeError;
  }
  return code;
}
