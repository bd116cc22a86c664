// The pixels the rover crosses from where it stands to the start of its path.
#pragma once

#include "marsokhod/nav/path/path_planner.hpp"
#include "marsokhod/nav/terrain/elevation.hpp"

#include <memory_resource>
#include <vector>

namespace marsokhod::nav {

/// The pixels the rover's centre passes over on its way from where it stands straight to the
/// start of a path (the first leg of the drive commands): in each row below the start's, the
/// known pixel whose ground point lies nearest the line from the rover centre to the start's
/// ground point, when it lies within `tolerance_m` of that line and short of the start. Rows
/// the line does not cross in view give no pixel; a start with no known point gives none.
std::pmr::vector<PixelPoint>
start_approach(const TerrainPoints& terrain, PixelPoint start, double tolerance_m = 0.05,
               std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
