// The bare fiber switch the emulator benchmarks measure themselves against.
#pragma once

#include <cstdint>

namespace marsokhod::benches {

/// Host seconds (steady clock) that `switches` bare Boost.Context switches between two fibers
/// take: the floor any process switch sits on.
double time_bare_fiber_switches(std::int64_t switches);

} // namespace marsokhod::benches
