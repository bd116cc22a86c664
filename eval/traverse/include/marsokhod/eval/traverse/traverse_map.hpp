// The traverse seen from above: the site's relief, its true obstacles, every cycle's plan and
// the driven track.
#pragma once

#include "marsokhod/eval/traverse/traverse.hpp"
#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <cstdint>

namespace marsokhod::eval {

/// Ground per map pixel.
inline constexpr double kTraverseMapCellM = 0.10;

/// An RGB map of the course at kTraverseMapCellM a pixel, north up, over the course's start,
/// goal, plans and tracks with 5 m around them (within the site): the terrain hillshaded
/// (sun from the north-west), tinted blue where a cycle's zones saw free ground and orange
/// where they prohibited it (steps and slopes), true obstacles red over both, each cycle's
/// planned path blue, the driven track yellow, turns on the spot cyan rings, emergency stops
/// magenta squares, the emulated computer's fault a violet square, unsafe events red crosses,
/// the start green and the goal (its tolerance circle) white; the border shows the outcome
/// (green success, orange hand-over or timeout, red unsafe).
imaging::Image<std::uint8_t> traverse_map(const world::Terrain& terrain,
                                          const TraverseResult& result);

} // namespace marsokhod::eval
