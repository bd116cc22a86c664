// Faults of a link's wires: a dead wire, a flipped data bit, a lost acknowledge.

#include "marsokhod/emulator/links/link.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace marsokhod::emulator {

void Link::check_end(int end) {
  if (end != 0 && end != 1)
    throw std::out_of_range(fmt::format("a link has ends 0 and 1, not {}", end));
}

void Link::set_wire_dead(int from_end, bool dead) {
  check_end(from_end);
  framing_.set_wire_dead(from_end, dead);
  const LinkPort& port = ports_[from_end];
  if (TraceSink* sink = trace())
    sink->instant(port.out_track_, kernel_->now(), dead ? "wire dead" : "wire mended",
                  port.name_ + " -> " + ports_[1 - from_end].name_);
  reschedule();
}

void Link::flip_data_bit(int from_end, std::uint64_t nth_byte, unsigned bit) {
  check_end(from_end);
  if (bit > 7)
    throw std::invalid_argument(fmt::format("a data byte has bits 0 to 7, not {}", bit));
  flips_[from_end].push_back(BitFlip{data_started_[from_end] + nth_byte,
                                     std::byte{static_cast<unsigned char>(1U << bit)}});
}

void Link::lose_acknowledge(int from_end) {
  check_end(from_end);
  framing_.lose_acknowledge(from_end);
}

void Link::apply_flips(int sender, std::uint64_t byte) {
  std::vector<BitFlip>& flips = flips_[sender];
  const std::byte before = on_wire_[sender];
  for (const BitFlip& flip : flips)
    if (flip.byte == byte)
      on_wire_[sender] ^= flip.mask;
  std::erase_if(flips, [byte](const BitFlip& flip) { return flip.byte == byte; });
  if (on_wire_[sender] == before)
    return; // nothing due for this byte, or two flips of the same bit
  if (TraceSink* sink = trace())
    sink->instant(ports_[sender].out_track_, kernel_->now(), "bit flipped",
                  fmt::format("byte {}: {:#04x} sent as {:#04x}", byte,
                              std::to_integer<unsigned>(before),
                              std::to_integer<unsigned>(on_wire_[sender])));
}

std::uint64_t Link::bytes_before_flip(int sender) const {
  std::uint64_t next = std::numeric_limits<std::uint64_t>::max();
  for (const BitFlip& flip : flips_[sender])
    next = std::min(next, flip.byte);
  return next - data_started_[sender];
}

void Link::note_lost_acknowledge(int end) {
  if (TraceSink* sink = trace())
    sink->instant(ports_[end].out_track_, kernel_->now(), "acknowledge lost",
                  ports_[end].name_ + " -> " + ports_[1 - end].name_);
}

} // namespace marsokhod::emulator
