// The memory fault a node raises when an allocation cannot be met.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace marsokhod::emulator {

/// A node ran out of memory: names the process and the request that could not be met.
class MemoryFault : public std::runtime_error {
public:
  MemoryFault(std::string process, std::size_t requested_bytes, std::size_t alignment,
              std::string region, std::size_t free_bytes, std::size_t largest_free_block);

  const std::string& process() const { return process_; }
  std::size_t requested_bytes() const { return requested_bytes_; }
  std::size_t alignment() const { return alignment_; }
  /// "on-chip", "external" or "on-chip or external".
  const std::string& region() const { return region_; }
  std::size_t free_bytes() const { return free_bytes_; }
  std::size_t largest_free_block() const { return largest_free_block_; }

private:
  std::string process_;
  std::size_t requested_bytes_;
  std::size_t alignment_;
  std::string region_;
  std::size_t free_bytes_;
  std::size_t largest_free_block_;
};

} // namespace marsokhod::emulator
