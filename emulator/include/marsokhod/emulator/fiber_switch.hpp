// Which fiber switch this build of the emulator uses (see emulator/fiber.hpp).
#pragma once

#include <string_view>

namespace marsokhod::emulator {

/// "returning" (the copy of Boost's x86-64 jump_fcontext that ends in a return,
/// fiber_switch.cpp) or "boost" (Boost's public fiber::resume).
std::string_view fiber_switch_name();

} // namespace marsokhod::emulator
