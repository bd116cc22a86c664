// A seeded, deterministic mutation engine for text and binary input files.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace marsokhod::fuzz {

/// The bytes of one input file.
using Bytes = std::string;

/// Which format-aware tweaks apply on top of the byte- and line-level damage.
enum class Syntax : std::uint8_t {
  binary, ///< images: byte damage, header numbers and tokens only
  toml,   ///< `key = value` lines: one value replaced
  json,   ///< `"key": value`: one value replaced
  tsv,    ///< tab-separated lines: one field replaced
};

/// The hostile tokens spliced into inputs or put in place of a number: edge numbers, brackets,
/// quotes, separators and path pieces (a 10000-deep "[[[[" and a very long line are added by
/// the engine itself).
const std::vector<std::string>& hostile_tokens();

/// Turns a valid seed into a damaged variant. Deterministic: the same (seed, index) gives the
/// same bytes on every run and every machine (std::mt19937_64 and plain modulo; no library
/// distributions, whose results differ between standard libraries).
class MutationEngine {
public:
  explicit MutationEngine(std::uint64_t seed) : seed_(seed) {}

  /// The `index`-th mutant of `base`: one to four damage steps chosen from the index's own
  /// random stream, so any mutant can be rebuilt alone from (seed, index).
  Bytes mutate(const Bytes& base, Syntax syntax, std::uint64_t index) const;

private:
  std::uint64_t seed_;
};

/// A stable 64-bit hash (FNV-1a) for naming saved inputs and deriving per-reader seeds.
std::uint64_t stable_hash(std::string_view text, std::uint64_t start = 14695981039346656037ULL);

} // namespace marsokhod::fuzz
