// The --seeds option of the evaluations: A..B or one seed, a usage error otherwise.
#pragma once

#include "cli/command.hpp"

#include "marsokhod/eval/common/errors.hpp"
#include "marsokhod/eval/terrain/terrain_evaluation.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <string>

namespace marsokhod::apps {

/// The seeds of `--seeds TEXT`; a malformed range is a UsageError naming the option.
inline eval::SeedRange seed_range_option(const std::string& text, std::uint64_t max_seeds = 10000) {
  try {
    return eval::parse_seed_range(text, max_seeds);
  } catch (const eval::OptionError& error) {
    throw UsageError(fmt::format("--seeds {}", error.what()));
  }
}

} // namespace marsokhod::apps
