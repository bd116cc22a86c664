// Bare fiber switches, the floor any process switch sits on: both of the emulator's switches,
// timed in the benchmark binary that times the emulator itself (bare_fiber_switch.cpp).
#pragma once

#include <cstdint>

namespace marsokhod::benches {

/// Host seconds (steady clock) that `switches` bare switches between two fibers take with
/// Boost's public fiber::resume: the floor any process switch sits on.
double time_bare_fiber_switches(std::int64_t switches);

/// The same with the emulator's returning switch (emulator/fiber_switch.cpp); a negative value
/// when this build has none (another Boost version, target or backend).
double time_returning_fiber_switches(std::int64_t switches);

} // namespace marsokhod::benches
