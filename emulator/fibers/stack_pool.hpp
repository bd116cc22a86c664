// Guard-paged fiber stacks from mmap, kept for reuse.
#pragma once

#include "fibers/fiber.hpp"

#include <cstddef>
#include <map>
#include <vector>

namespace marsokhod::emulator::detail {

/// Guard-paged fiber stacks from mmap, kept for reuse so that spawning a process in a loop
/// costs no system call after the first few. The lowest page of each stack is PROT_NONE:
/// an overflow faults at once instead of corrupting a neighbour.
class StackPool {
public:
  StackPool() = default;
  StackPool(const StackPool&) = delete;
  StackPool& operator=(const StackPool&) = delete;
  ~StackPool();

  /// A stack of at least `usable_bytes` (rounded up to pages) plus the guard page.
  boost::context::stack_context allocate(std::size_t usable_bytes);
  void release(boost::context::stack_context& stack) noexcept;

  static std::size_t page_size();

private:
  std::map<std::size_t, std::vector<void*>> free_; // by mapping size
  std::size_t colour_ = 0;
};

/// Boost.Context StackAllocator that draws from a StackPool.
class PooledStack {
public:
  PooledStack(StackPool& pool, std::size_t usable_bytes) : pool_(&pool), bytes_(usable_bytes) {}
  boost::context::stack_context allocate() { return pool_->allocate(bytes_); }
  void deallocate(boost::context::stack_context& stack) noexcept { pool_->release(stack); }

private:
  StackPool* pool_;
  std::size_t bytes_;
};

} // namespace marsokhod::emulator::detail
