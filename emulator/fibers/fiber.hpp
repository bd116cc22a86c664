// Boost.Context for the kernel: the one place that includes it, and the fiber switch it uses.
#pragma once

// AddressSanitizer builds use the ucontext backend, which tells ASan about every stack switch;
// every other build uses fcontext, the fast assembler backend. Include this header, never
// <boost/context/fiber.hpp> directly, so that every translation unit sees the same backend.

#if defined(__SANITIZE_ADDRESS__)
#ifndef BOOST_USE_UCONTEXT
#define BOOST_USE_UCONTEXT
#endif
#ifndef BOOST_USE_ASAN
#define BOOST_USE_ASAN
#endif
#endif

#include <boost/context/fiber.hpp>

#include <utility>

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

/// Suspends the running context and resumes `target`, with Boost's public fiber::resume. When
/// this context is resumed in turn, the context that resumed it is stored in `*slot`, read at
/// that moment (the resumer sets it), which must then be empty.
inline void switch_fiber(boost::context::fiber& target, boost::context::fiber* const& slot) {
  boost::context::fiber from = std::move(target).resume();
  *slot = std::move(from);
}

} // namespace marsokhod::emulator::detail
