// The navigation program's shape: its processes, the channels between them, its device uses.

#include "processes/process_bodies.hpp"
#include "processes/program_processes.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace marsokhod::nav_program {
namespace detail {

std::span<const ProcessSpec> program_processes() {
  using emulator::Priority;
  static constexpr std::array processes{
#define MARSOKHOD_PROCESS(name, priority, code, workspace, group)                                  \
  ProcessSpec{#name, Priority::priority, code, workspace, StageGroup::group,                       \
              &name, &name##_buffers},
#include "processes/process_list.def"
  };
  return processes;
}

const ProcessSpec& program_process(std::string_view name) {
  for (const ProcessSpec& process : program_processes())
    if (process.name == name)
      return process;
  throw std::logic_error("the navigation program has no process " + std::string(name));
}

} // namespace detail

const ProgramShape& navigation_program_shape() {
  static const ProgramShape shape = [] {
    ProgramShape made;
    for (const detail::ProcessSpec& process : detail::program_processes())
      made.processes.emplace_back(process.name);
#define MARSOKHOD_CHANNEL(name, from, to) made.channels.push_back({#name, #from, #to});
#include "channels/channel_list.def"
    made.devices = {{"acquire", "images from the frame store"},
                    {"telemetry", "telemetry to the host or ground"}};
    return made;
  }();
  return shape;
}

Placement load_program_placement(const emulator::PlatformSpec& platform) {
  return load_placement(default_placement_file(platform), platform, navigation_program_shape());
}

} // namespace marsokhod::nav_program
