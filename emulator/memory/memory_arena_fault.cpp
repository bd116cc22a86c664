// The memory fault a node raises when an allocation cannot be met.

#include "marsokhod/emulator/memory/memory_arena_fault.hpp"

#include <fmt/format.h>

#include <utility>

namespace marsokhod::emulator {
namespace {

std::string describe(const std::string& process, std::size_t requested, std::size_t alignment,
                     const std::string& region, std::size_t free_bytes, std::size_t largest) {
  return fmt::format("memory fault in process '{}': {} bytes (alignment {}) requested in {} "
                     "memory, {} bytes free, largest free block {} bytes",
                     process, requested, alignment, region, free_bytes, largest);
}

} // namespace

MemoryFault::MemoryFault(std::string process, std::size_t requested_bytes, std::size_t alignment,
                         std::string region, std::size_t free_bytes, std::size_t largest_free_block)
    : std::runtime_error(
          describe(process, requested_bytes, alignment, region, free_bytes, largest_free_block)),
      process_(std::move(process)), requested_bytes_(requested_bytes), alignment_(alignment),
      region_(std::move(region)), free_bytes_(free_bytes), largest_free_block_(largest_free_block) {
}

} // namespace marsokhod::emulator
