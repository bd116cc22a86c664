// The ucontext backend of Boost.Context (used in AddressSanitizer builds, see fiber.hpp)
// needs a per-thread "current context" record that the prebuilt Boost library does not
// provide, since it was compiled for fcontext. This is Boost's own definition.

#include "fibers/fiber.hpp"

#if defined(BOOST_USE_UCONTEXT)

namespace boost::context::detail {

namespace {
thread_local fiber_activation_record* current_record = nullptr;
thread_local std::size_t initializer_count = 0;
} // namespace

fiber_activation_record_initializer::fiber_activation_record_initializer() noexcept {
  if (initializer_count++ == 0)
    current_record = new fiber_activation_record();
}

fiber_activation_record_initializer::~fiber_activation_record_initializer() {
  if (--initializer_count == 0)
    delete current_record;
}

fiber_activation_record*& fiber_activation_record::current() noexcept {
  thread_local static fiber_activation_record_initializer initializer;
  return current_record;
}

} // namespace boost::context::detail

#endif
