// A cycle's zones placed on the ground: what the navigation saw and prohibited, for the map.
#pragma once

#include "marsokhod/eval/traverse/traverse.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/world/scene/rover_placement.hpp"

namespace marsokhod::eval {

/// Books into `cycle` the world-frame centres of the cell_m cells the cycle's zones judged:
/// traversable and margin ground in `seen`, steps and slopes in `prohibited` (a cell with
/// both is prohibited), each cell once, in cell order. `placement` is the rover's true pose
/// and attitude, whose level frame the navigation's points are in.
void book_zones(const world::RoverPlacement& placement, const nav::NavigationResult& navigation,
                double cell_m, TraverseCycle& cycle);

} // namespace marsokhod::eval
