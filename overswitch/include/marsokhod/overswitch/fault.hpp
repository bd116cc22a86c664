// Faults injected into an emulated cycle, and the `--inject` specs that name them.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace marsokhod::overswitch {

/// One fault: what happens to which module, and when.
struct Fault {
  enum class Kind : std::uint8_t {
    hang,       ///< the CPU stops for good and the links stop acknowledging; still powered
    power_loss, ///< the module loses its power
    leak,       ///< memory exhaustion: a leak takes every free byte where the module's buffers go
  };
  Kind kind = Kind::hang;
  std::string module;
  /// Empty: `offset` is a simulated time from the cycle's start. Otherwise a process of the
  /// program: `offset` after its stage first starts.
  std::string stage;
  emulator::Tick offset = 0;
};

const char* to_string(Fault::Kind kind);

/// A bad `--inject` spec: what() names the spec and the problem.
class FaultSpecError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

/// Reads "KIND:MODULE@WHEN": KIND is hang, power or leak; WHEN is a time from the cycle's start
/// ("1.05s", "250ms", "900us") or a stage of the program and an offset after its start
/// ("matching+0.5s", "zones"). Checks the grammar and the ranges (0 to an hour), not that the
/// module and stage exist (the run does). Throws FaultSpecError.
Fault parse_fault(std::string_view spec);

/// The spec back as text, in parse_fault's grammar.
std::string describe(const Fault& fault);

} // namespace marsokhod::overswitch
