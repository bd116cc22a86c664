// The navigation program's shape: its processes, the channels between them, its device uses.

#include "navigation/program_processes.hpp"

#include "marsokhod/occam_port/navigation/navigation_program.hpp"

#include <array>

namespace marsokhod::occam_port {
namespace detail {

std::span<const ProcessSpec> program_processes() {
  using emulator::Priority;
  static constexpr std::array<ProcessSpec, 10> processes{{
      {"acquire", Priority::low, 256, 512},
      {"features", Priority::low, 1536, 512},
      {"matching", Priority::low, 5120, 512},
      {"refine", Priority::low, 1536, 512},
      {"range", Priority::low, 1024, 512},
      {"zones", Priority::low, 4096, 512},
      {"path", Priority::low, 2048, 512},
      {"drive", Priority::low, 1024, 512},
      {"motion", Priority::high, 768, 256},
      {"telemetry", Priority::low, 512, 512},
  }};
  return processes;
}

} // namespace detail

const ProgramShape& navigation_program_shape() {
  static const ProgramShape shape = [] {
    ProgramShape made;
    for (const detail::ProcessSpec& process : detail::program_processes())
      made.processes.emplace_back(process.name);
    made.channels = {{"images", "acquire", "features"},  {"features", "features", "matching"},
                     {"matched", "matching", "refine"},  {"disparity", "refine", "range"},
                     {"terrain", "range", "zones"},      {"zones", "zones", "path"},
                     {"path", "path", "drive"},          {"commands", "drive", "motion"},
                     {"plan_out", "drive", "telemetry"}, {"wheels", "motion", "telemetry"}};
    made.devices = {{"acquire", "images from the frame store"},
                    {"telemetry", "telemetry to the host or ground"}};
    return made;
  }();
  return shape;
}

} // namespace marsokhod::occam_port
