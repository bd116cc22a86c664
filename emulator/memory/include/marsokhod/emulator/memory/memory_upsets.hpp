// Single-event upsets and stuck bits in a node's memory, and the SEC-DED EDAC that corrects them.
#pragma once

#include "marsokhod/emulator/memory/memory_arena.hpp"

#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace marsokhod::emulator {

/// What an upset or a stuck bit did to the word it struck.
enum class UpsetEffect : std::uint8_t {
  flipped,       ///< unprotected memory: the bit is inverted and the program reads it so
  corrected,     ///< EDAC: the one error of its word, corrected on every read
  uncorrectable, ///< EDAC: a second error in a word that already held one: flagged, not corrected
};

const char* to_string(UpsetEffect effect);

/// The check bits a SEC-DED code adds to a 32-bit word: a modified Hamming code, 7 check bits per
/// 32 data bits (IDT49C460 and DP8402A data sheets), 21.9 % more memory.
inline constexpr unsigned kEdacCheckBits = 7;

/// Particle hits and stuck cells in one node's memory. Without EDAC a hit inverts the bit in
/// the arena's bytes, so the program computes with it. With EDAC on external memory (a
/// flow-through SEC-DED unit between the T805 and its RAM), a single error in a 39-bit word
/// (32 data and 7 check bits) is corrected on every read: the bytes the program sees stay
/// right, and the error waits in the word until a scrub rewrites it. A second error in the same
/// word before that is beyond the code: flagged uncorrectable, the bytes corrupted. On-chip RAM
/// has no EDAC. A stuck bit is a permanent error: it is forced back to its value whenever the
/// node computes (reassert_stuck), and under EDAC it is a single error no scrub clears.
class MemoryUpsets {
public:
  explicit MemoryUpsets(MemoryArena& arena) : arena_(&arena) {}

  void set_edac_on_external(bool on) { edac_external_ = on; }
  bool edac_on_external() const { return edac_external_; }
  /// The word holding `address` is covered by EDAC.
  bool protects(Address address) const;

  /// Inverts data bit `bit` (0..7) of the byte at `address`. std::out_of_range outside
  /// populated memory or for a bit above 7.
  UpsetEffect upset(Address address, unsigned bit);
  /// Inverts check bit `check_bit` (0..6) of the word at `word`: corrected like any single
  /// error, its data untouched. std::invalid_argument where EDAC does not cover the word.
  UpsetEffect upset_check_bit(Address word, unsigned check_bit);
  /// From now on bit `bit` of the byte at `address` reads `value`, whatever is written.
  UpsetEffect stick(Address address, unsigned bit, bool value);

  bool has_stuck() const { return !stuck_.empty(); }
  /// Forces every stuck bit of unprotected memory back to its value (a write to its word has
  /// been undone by the cell).
  void reassert_stuck();

  /// A scrub of [from, from + bytes): each word read through the EDAC and written back
  /// corrected, so its upsets are gone (stuck cells stay). Returns the words it corrected.
  std::size_t scrub(Address from, std::size_t bytes);

  /// Words now holding an error the EDAC corrects on each read.
  std::size_t latent_words() const { return latent_.size(); }
  /// Single errors met by scrubs so far.
  std::uint64_t scrubbed() const { return scrubbed_; }

private:
  struct Stuck {
    Address address;
    std::byte mask;
    bool value;
  };
  /// An EDAC-covered word with errors: how many, and how many of them are stuck cells.
  struct WordErrors {
    unsigned upsets = 0;
    unsigned stuck = 0;
  };
  UpsetEffect add_error(Address word, bool stuck);

  MemoryArena* arena_;
  bool edac_external_ = false;
  std::map<Address, WordErrors> latent_;
  std::vector<Stuck> stuck_;
  std::uint64_t scrubbed_ = 0;
};

} // namespace marsokhod::emulator
