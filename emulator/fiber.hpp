#pragma once

// The one place that includes Boost.Context. AddressSanitizer builds use the ucontext
// backend, which tells ASan about every stack switch; every other build uses fcontext, the
// fast assembler backend. Include this header, never <boost/context/fiber.hpp> directly, so
// that every translation unit sees the same backend.

#if defined(__SANITIZE_ADDRESS__)
#ifndef BOOST_USE_UCONTEXT
#define BOOST_USE_UCONTEXT
#endif
#ifndef BOOST_USE_ASAN
#define BOOST_USE_ASAN
#endif
#endif

#include <boost/context/fiber.hpp>

#include <type_traits>
#include <utility>

// x86-64 fcontext builds switch with their own copy of Boost's jump (fiber_switch.cpp).
#if !defined(BOOST_USE_UCONTEXT) && !defined(BOOST_USE_WINFIB) && defined(__x86_64__) &&           \
    defined(__ELF__)
#define MARSOKHOD_RETURNING_SWITCH 1
#else
#define MARSOKHOD_RETURNING_SWITCH 0
#endif

#if MARSOKHOD_RETURNING_SWITCH
extern "C" boost::context::detail::transfer_t
marsokhod_jump_fcontext(boost::context::detail::fcontext_t to, void* data);
#endif

namespace marsokhod::emulator {
class Process;
}

namespace marsokhod::emulator::detail {

/// A process's fiber. When a process ends, its fiber does not return but parks, ready to
/// run the next process spawned with the same stack size (spawning then costs no stack set-up).
struct Context {
  boost::context::fiber fiber; ///< the saved context while not running
  Process* process = nullptr;  ///< who runs on it now; nullptr while parked
  std::size_t stack_bytes = 0;
};

using ForcedUnwind = boost::context::detail::forced_unwind;

/// Suspends the running context and resumes `target`. When this context is resumed in turn,
/// the context that resumed it is stored in `*slot`, read at that moment (the resumer sets
/// it), which must then be empty.
inline void switch_fiber(boost::context::fiber& target, boost::context::fiber* const& slot) {
#if MARSOKHOD_RETURNING_SWITCH
  // A fiber of the fcontext backend is its context pointer and nothing else; an empty one
  // holds nullptr, so the slot can be written without a move assignment's checks.
  using boost::context::fiber;
  using boost::context::detail::fcontext_t;
  static_assert(std::is_standard_layout_v<fiber> && sizeof(fiber) == sizeof(fcontext_t));
  fcontext_t& to = *reinterpret_cast<fcontext_t*>(&target);
  const fcontext_t from = marsokhod_jump_fcontext(std::exchange(to, nullptr), nullptr).fctx;
  *reinterpret_cast<fcontext_t*>(slot) = from;
#else
  boost::context::fiber from = std::move(target).resume();
  *slot = std::move(from);
#endif
}

} // namespace marsokhod::emulator::detail
