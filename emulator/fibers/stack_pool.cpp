// Guard-paged fiber stacks from mmap, kept for reuse.

#include "fibers/stack_pool.hpp"

#include <new>
#include <sys/mman.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>
#endif

namespace marsokhod::emulator::detail {

namespace {

std::size_t round_up(std::size_t bytes, std::size_t page) {
  return (bytes + page - 1) / page * page;
}

void* map_stack(std::size_t mapping_bytes) {
  void* base = ::mmap(nullptr, mapping_bytes, PROT_READ | PROT_WRITE,
                      MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (base == MAP_FAILED)
    throw std::bad_alloc();
  // The guard page sits at the low end because stacks grow downwards.
  if (::mprotect(base, StackPool::page_size(), PROT_NONE) != 0) {
    ::munmap(base, mapping_bytes);
    throw std::bad_alloc();
  }
  return base;
}

} // namespace

std::size_t StackPool::page_size() {
  static const std::size_t size = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  return size;
}

StackPool::~StackPool() {
  for (auto& [bytes, stacks] : free_)
    for (void* base : stacks)
      ::munmap(base, bytes);
}

boost::context::stack_context StackPool::allocate(std::size_t usable_bytes) {
  const std::size_t page = page_size();
  const std::size_t mapping = round_up(usable_bytes, page) + page;
  void* base = nullptr;
  auto& stacks = free_[mapping];
  if (stacks.empty()) {
    base = map_stack(mapping);
  } else {
    base = stacks.back();
    stacks.pop_back();
  }
  // Stack tops a whole number of pages apart would all fall into the same L1 cache sets;
  // start each one at a different 256-byte colour within its top page so that the hot frames
  // of a handful of communicating processes do not evict each other.
  const std::size_t colour = (colour_++ % 16) * 256;
  boost::context::stack_context stack;
  stack.size = mapping - page - colour;
  stack.sp = static_cast<char*>(base) + mapping - colour;
  return stack;
}

void StackPool::release(boost::context::stack_context& stack) noexcept {
  const std::size_t page = page_size();
  // The colour is what the stack lacks of whole pages (usable sizes are page multiples).
  const std::size_t colour = (page - stack.size % page) % page;
  const std::size_t mapping = stack.size + colour + page;
  void* base = static_cast<char*>(stack.sp) + colour - mapping;
#if defined(__SANITIZE_ADDRESS__)
  // A fiber that ended leaves its frames' red zones poisoned; the next owner starts clean.
  ASAN_UNPOISON_MEMORY_REGION(static_cast<char*>(base) + page, mapping - page);
#endif
  try {
    free_[mapping].push_back(base);
  } catch (...) {
    ::munmap(base, mapping);
  }
}

} // namespace marsokhod::emulator::detail
