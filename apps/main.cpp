// The marsokhod executable's entry point.

#include "command.hpp"

int main(int argc, char** argv) {
  return marsokhod::apps::run_command_line(argc, argv);
}
