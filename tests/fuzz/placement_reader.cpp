// The placement reader under mutation: seeds, and the call that judges what it returned.
#include "fuzz/placement_reader.hpp"

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/nav_program/placement/placement.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string_view>

namespace marsokhod::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kPlacementSource = MARSOKHOD_SOURCE_DIR;

// Read once: a mutant changes the placement file only, never the platform it is checked on.
const emulator::PlatformSpec& shipped_platform(const char* file) {
  static const emulator::PlatformSpec onboard =
      emulator::load_platform(kPlacementSource / "platforms/onboard.toml");
  static const emulator::PlatformSpec pc_card =
      emulator::load_platform(kPlacementSource / "platforms/pc-card.toml");
  return std::string_view(file) == "onboard" ? onboard : pc_card;
}

void check_placement(const nav_program::Placement& placement,
                     const emulator::PlatformSpec& platform,
                     const nav_program::ProgramShape& shape) {
  expect(placement.platform == platform.name,
         fmt::format("placement for '{}' accepted on '{}'", placement.platform, platform.name));
  expect(
      placement.places.size() == shape.processes.size(),
      fmt::format("{} places for {} processes", placement.places.size(), shape.processes.size()));
  for (const std::string& process : shape.processes) {
    const auto count = std::count_if(
        placement.places.begin(), placement.places.end(),
        [&](const nav_program::ProcessPlace& place) { return place.process == process; });
    expect(count == 1, fmt::format("process '{}' placed {} times", process, count));
    const emulator::NodeSpec* node = platform.find_node(placement.node_of(process));
    expect(node != nullptr && node->powered, fmt::format("process '{}' on '{}', no powered node",
                                                         process, placement.node_of(process)));
  }
  for (const nav_program::ProcessPlace& place : placement.places)
    expect(place.line > 0, fmt::format("process '{}' without a line", place.process));
}

} // namespace

std::vector<Seed> placement_seeds() {
  return shipped({"platforms/placements/onboard.toml", "platforms/placements/pc-card.toml"});
}

void read_placement(const fs::path& input) {
  const nav_program::ProgramShape shape = nav_program::navigation_program_shape();
  // The shipped platform the file is for: onboard, or pc-card when the file says it is not
  // for onboard. A mutant naming neither is refused against pc-card.
  const emulator::PlatformSpec* platform = &shipped_platform("onboard");
  nav_program::Placement placement;
  try {
    placement = nav_program::load_placement(input, *platform, shape);
  } catch (const nav_program::PlacementError& error) {
    if (error.key() != "placement.platform")
      throw;
    platform = &shipped_platform("pc-card");
    placement = nav_program::load_placement(input, *platform, shape);
  }
  check_placement(placement, *platform, shape);
}

} // namespace marsokhod::fuzz
