// Faults injected into an emulated cycle, and the `--inject` specs that name them.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/memory/memory_arena.hpp"

#include <cstdint>
#include <optional>
#include <span>
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
  /// What happens to the module (fault_kinds.def gives each kind's meaning and name).
  enum class Kind : std::uint8_t {
#define MARSOKHOD_FAULT_KIND(enumerator, name, fault_class) enumerator,
#include "marsokhod/overswitch/faults/fault_kinds.def"
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

/// What a kind of fault strikes.
enum class FaultClass : std::uint8_t {
  module,     ///< the whole module: it stops outright (hang, power loss)
  exhaustion, ///< the free space of its memory (a leak)
  memory,     ///< a bit of its memory (upset, stuck bit)
  link,       ///< a wire of one of its links
};

/// Every kind, in fault_kinds.def's order.
std::span<const Fault::Kind> fault_kinds();
/// The kind's name ("hang", "power", "seu", ...).
const char* to_string(Fault::Kind kind);
/// The kind named `name`; nothing when no kind has that name.
std::optional<Fault::Kind> parse_fault_kind(std::string_view name);
/// "hang, power, leak, ...": every kind's name, for messages.
std::string fault_kind_names();
FaultClass fault_class(Fault::Kind kind);
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
