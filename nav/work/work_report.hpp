// How nav kernels report their work counts to a meter (private to the nav layer).
#pragma once

// How nav kernels hand their work counts to a meter. Defining MARSOKHOD_NAV_UNMETERED removes
// every report from the kernels; it exists only to show that a NullMeter build is the same
// machine code as a build without metering (docs/navigation.md, "Work metering").

#include "marsokhod/nav/work/work.hpp"

#include <cstdint>

namespace marsokhod::nav::detail {

template <class Meter>
inline void report(Meter& meter, Work kind, std::uint64_t count) {
#ifdef MARSOKHOD_NAV_UNMETERED
  static_cast<void>(meter);
  static_cast<void>(kind);
  static_cast<void>(count);
#else
  meter(kind, count);
#endif
}

} // namespace marsokhod::nav::detail

// Lists the meters every nav kernel is explicitly instantiated for.
#define MARSOKHOD_NAV_FOR_EACH_METER(X)                                                            \
  X(::marsokhod::nav::NullMeter)                                                                   \
  X(::marsokhod::nav::CountingMeter)                                                               \
  X(::marsokhod::nav::DynamicMeter)
