// Upsets, stuck bits and the EDAC over a node's memory.

#include "marsokhod/emulator/memory/memory_upsets.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace marsokhod::emulator {
namespace {

Address word_of(Address address) {
  return address & ~Address{MemoryArena::kWordBytes - 1};
}

std::byte bit_mask(unsigned bit) {
  return std::byte{static_cast<unsigned char>(1U << bit)};
}

} // namespace

const char* to_string(UpsetEffect effect) {
  switch (effect) {
  case UpsetEffect::flipped:
    return "flipped";
  case UpsetEffect::corrected:
    return "corrected";
  case UpsetEffect::uncorrectable:
    return "uncorrectable";
  }
  return "?";
}

bool MemoryUpsets::protects(Address address) const {
  return edac_external_ && arena_->contains(address) && !arena_->is_on_chip(address);
}

// A word's first error is corrected on every read; with a second the code can only flag it, and
// the program reads the corrupted word from then on.
UpsetEffect MemoryUpsets::add_error(Address word, bool stuck) {
  WordErrors& errors = latent_[word];
  (stuck ? errors.stuck : errors.upsets) += 1;
  return errors.upsets + errors.stuck > 1 ? UpsetEffect::uncorrectable : UpsetEffect::corrected;
}

UpsetEffect MemoryUpsets::upset(Address address, unsigned bit) {
  if (bit > 7)
    throw std::out_of_range(fmt::format("bit {} does not exist in a byte", bit));
  std::byte* byte = arena_->pointer(address);
  if (!protects(address)) {
    *byte ^= bit_mask(bit);
    return UpsetEffect::flipped;
  }
  const UpsetEffect effect = add_error(word_of(address), false);
  if (effect == UpsetEffect::uncorrectable)
    *byte ^= bit_mask(bit);
  return effect;
}

UpsetEffect MemoryUpsets::upset_check_bit(Address word, unsigned check_bit) {
  if (check_bit >= kEdacCheckBits)
    throw std::out_of_range(
        fmt::format("check bit {} does not exist: a word has {}", check_bit, kEdacCheckBits));
  if (!protects(word))
    throw std::invalid_argument(fmt::format("#{:08X} has no check bits: no EDAC covers it", word));
  return add_error(word_of(word), false);
}

UpsetEffect MemoryUpsets::stick(Address address, unsigned bit, bool value) {
  if (bit > 7)
    throw std::out_of_range(fmt::format("bit {} does not exist in a byte", bit));
  const std::byte* byte = arena_->pointer(address); // refuses an address outside memory
  if (protects(address)) {
    // The cell is wrong only while it disagrees with what was written; the EDAC corrects it on
    // every read, so the model counts it as a permanent single error of its word.
    return add_error(word_of(address), true);
  }
  (void)byte;
  stuck_.push_back({address, bit_mask(bit), value});
  reassert_stuck();
  return UpsetEffect::flipped;
}

void MemoryUpsets::reassert_stuck() {
  for (const Stuck& cell : stuck_) {
    std::byte* byte = arena_->pointer(cell.address);
    *byte = cell.value ? (*byte | cell.mask) : (*byte & ~cell.mask);
  }
}

std::size_t MemoryUpsets::scrub(Address from, std::size_t bytes) {
  std::size_t corrected = 0;
  auto it = latent_.lower_bound(word_of(from));
  while (it != latent_.end() && it->first < from + bytes) {
    WordErrors& errors = it->second;
    if (errors.upsets + errors.stuck == 1 && errors.upsets == 1) {
      ++corrected;
      it = latent_.erase(it);
      continue;
    }
    ++it;
  }
  scrubbed_ += corrected;
  return corrected;
}

} // namespace marsokhod::emulator
