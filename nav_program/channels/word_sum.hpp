// The program's word sums: the checksum of a link message and of a kept terrain row.
#pragma once

#include "marsokhod/emulator/node/node.hpp"

#include <cstddef>
#include <cstdint>
#include <span>

namespace marsokhod::nav_program::detail {

/// The 32-bit sum of the words of `bytes`, the last one padded with zero bytes: any single bit
/// inverted in them changes it.
std::uint32_t word_sum(std::span<const std::byte> bytes);

/// Charges `node` for the sum of `bytes`: occam's `sum := sum PLUS msg[i]` over the words
/// compiles to ldnl, sum and lend per word, the word read from external memory.
void charge_word_sum(emulator::Node& node, std::size_t bytes);

} // namespace marsokhod::nav_program::detail
