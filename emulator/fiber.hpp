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

} // namespace marsokhod::emulator::detail
