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
#include <boost/version.hpp>

#include <type_traits>
#include <utility>

// The returning switch (fiber_switch.cpp) is a copy of the x86-64 SysV jump_fcontext of the
// Boost release below and writes a fiber as the bare fcontext_t that release keeps in it: it
// is built only with that release, on that target and backend. Every other build switches with
// Boost's public fiber::resume (fiber_switch.cpp says so when the Boost version is the cause).
#define MARSOKHOD_RETURNING_SWITCH_BOOST_VERSION 107400 // Boost 1.74.0, Debian 12
#if !defined(BOOST_USE_UCONTEXT) && !defined(BOOST_USE_WINFIB) && defined(__x86_64__) &&           \
    defined(__ELF__) && BOOST_VERSION == MARSOKHOD_RETURNING_SWITCH_BOOST_VERSION
#define MARSOKHOD_HAVE_RETURNING_SWITCH 1
#else
#define MARSOKHOD_HAVE_RETURNING_SWITCH 0
#endif

// The kernel switches with it where it is built, unless the build selects Boost's own switch
// (CMake -DMARSOKHOD_FIBER_SWITCH=boost defines MARSOKHOD_FIBER_SWITCH_BOOST).
#if MARSOKHOD_HAVE_RETURNING_SWITCH && !defined(MARSOKHOD_FIBER_SWITCH_BOOST)
#define MARSOKHOD_RETURNING_SWITCH 1
#else
#define MARSOKHOD_RETURNING_SWITCH 0
#endif

#if MARSOKHOD_HAVE_RETURNING_SWITCH
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

// Both switches below suspend the running context and resume `target`. When this context is
// resumed in turn, the context that resumed it is stored in `*slot`, read at that moment (the
// resumer sets it), which must then be empty. Contexts suspended by either can be resumed by
// the other.

/// Boost's public switch: fiber::resume.
inline void switch_fiber_boost(boost::context::fiber& target, boost::context::fiber* const& slot) {
  boost::context::fiber from = std::move(target).resume();
  *slot = std::move(from);
}

#if MARSOKHOD_HAVE_RETURNING_SWITCH
/// The returning switch (fiber_switch.cpp).
inline void switch_fiber_returning(boost::context::fiber& target,
                                   boost::context::fiber* const& slot) {
  // A fiber of the fcontext backend is its context pointer and nothing else; an empty one
  // holds nullptr, so the slot can be written without a move assignment's checks.
  using boost::context::fiber;
  using boost::context::detail::fcontext_t;
  static_assert(std::is_standard_layout_v<fiber> && sizeof(fiber) == sizeof(fcontext_t));
  fcontext_t& to = *reinterpret_cast<fcontext_t*>(&target);
  const fcontext_t from = marsokhod_jump_fcontext(std::exchange(to, nullptr), nullptr).fctx;
  *reinterpret_cast<fcontext_t*>(slot) = from;
}
#endif

/// The switch the kernel uses.
inline void switch_fiber(boost::context::fiber& target, boost::context::fiber* const& slot) {
#if MARSOKHOD_RETURNING_SWITCH
  switch_fiber_returning(target, slot);
#else
  switch_fiber_boost(target, slot);
#endif
}

} // namespace marsokhod::emulator::detail
