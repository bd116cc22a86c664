// Faults injected into an emulated cycle, and the `--inject` specs that name them.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/memory/memory_arena.hpp"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace marsokhod::overswitch {

/// Where a memory fault strikes: a given bit, a bit drawn in a named buffer, or a bit drawn
/// over the module's allocated memory or over all of it.
struct MemoryTarget {
  enum class Over : std::uint8_t {
    allocated, ///< every bit of the blocks allocated at the strike (data, workspaces, code)
    memory,    ///< every bit of the module's memory, free or not, check bits included
  };
  std::optional<emulator::Address> address;
  std::optional<unsigned> bit; ///< 0..7 within the byte; drawn when absent
  /// A bit drawn in the blocks whose label or owner contains this text (case ignored).
  std::string buffer;
  Over over = Over::allocated;
  bool stuck_value = true; ///< Kind::stuck: the value the cell keeps
};

/// Which way a link fault cuts: the wire the module's link drives (out), the one it listens to
/// (in), or both.
enum class LinkDirection : std::uint8_t { out, in, both };

/// One fault: what happens to which module, and when.
struct Fault {
  enum class Kind : std::uint8_t {
    hang,       ///< the CPU stops for good and the links stop acknowledging; still powered
    power_loss, ///< the module loses its power
    leak,       ///< memory exhaustion: a leak takes free bytes where the module's buffers go
    upset,      ///< a single-event upset: one bit of memory inverted
    stuck,      ///< a memory bit stuck at a value from then on
    link_down,  ///< a link's wire carries nothing (one or both ways), for good or for a while
    link_bit,   ///< one data bit inverted on a link's wire
    ack_lost,   ///< one acknowledge lost on a link's wire
  };
  Kind kind = Kind::hang;
  std::string module;
  /// Empty: `offset` is a simulated time from the cycle's start. Otherwise a process of the
  /// program: `offset` after its stage first starts.
  std::string stage;
  emulator::Tick offset = 0;

  /// Kind::upset and Kind::stuck.
  MemoryTarget memory;
  /// Kind::leak: bytes taken; nothing: the largest free block (the next buffer fails).
  std::optional<std::size_t> leak_bytes;
  /// Link faults: the module's link (0..3).
  int link = -1;
  LinkDirection direction = LinkDirection::both;
  /// Kind::link_down: mended after this long; nothing: for good.
  std::optional<emulator::Tick> duration;
  /// Kind::link_bit: the data byte hit, counted from the strike (0: the next), and its bit
  /// (drawn when absent).
  std::uint64_t byte = 0;
  std::optional<unsigned> data_bit;
  /// Seeds what the fault draws (address, bit) at its strike, so that a run is replayed exactly.
  std::uint64_t draw = 0;
};

const char* to_string(Fault::Kind kind);
/// A memory fault (upset or stuck bit).
bool is_memory_fault(Fault::Kind kind);
/// A fault of a link's wire.
bool is_link_fault(Fault::Kind kind);
/// A fault that stops a module outright (hang, power loss).
bool stops_module(Fault::Kind kind);

/// A bad `--inject` spec: what() names the spec and the problem.
class FaultSpecError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

/// Reads "KIND:MODULE@WHEN[,KEY=VALUE...]" (docs/faults.md, "Fault models"). KIND is hang,
/// power, leak, seu, stuck, link, linkbit or ackloss; a link fault names MODULE.linkN. WHEN is a
/// time from the cycle's start ("1.05s", "250ms", "900us") or a stage of the program and an
/// offset after its start ("matching+0.5s", "zones"). The keys: addr, bit, buffer, over (seu,
/// stuck), value (stuck), bytes (leak), dir, for (link), byte, bit (linkbit). Checks the grammar
/// and the ranges, not that the module, stage or buffer exists (the run does). Throws
/// FaultSpecError.
Fault parse_fault(std::string_view spec);

/// The spec back as text, in parse_fault's grammar.
std::string describe(const Fault& fault);

} // namespace marsokhod::overswitch
