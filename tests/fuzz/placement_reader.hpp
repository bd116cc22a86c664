// The placement reader's entry in the registry: its seeds and its checked call.
#pragma once

#include "fuzz/reader_targets.hpp"

#include <filesystem>
#include <vector>

namespace marsokhod::fuzz {

/// The shipped placement files, platforms/placements/onboard.toml and pc-card.toml.
std::vector<Seed> placement_seeds();

/// Loads the input against the shipped platform it is for and the navigation program, and
/// checks that every process of the program is placed exactly once on a powered node.
void read_placement(const std::filesystem::path& input);

} // namespace marsokhod::fuzz
