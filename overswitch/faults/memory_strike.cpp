// Drawing the bit an upset or a stuck cell strikes, and striking it.

#include "marsokhod/overswitch/faults/memory_strike.hpp"

#include "marsokhod/overswitch/faults/split_mix.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <vector>

namespace marsokhod::overswitch {
namespace {

namespace emu = emulator;

/// A stretch of memory a bit may be drawn from, and whether the EDAC adds check bits to it.
struct Segment {
  emu::Address start = 0;
  std::size_t bytes = 0;
  bool edac = false;
};

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

bool names(const emu::BlockInfo& block, const std::string& wanted) {
  return lower(block.label).find(wanted) != std::string::npos ||
         lower(block.owner).find(wanted) != std::string::npos ||
         lower(emu::to_string(block.kind)) == wanted;
}

bool over_all_memory(const MemoryTarget& target) {
  return target.buffer.empty() && target.over == MemoryTarget::Over::memory;
}

std::vector<Segment> segments_of_memory(const emu::MemoryConfig& config, bool edac_external) {
  std::vector<Segment> segments;
  if (config.on_chip_bytes > 0)
    segments.push_back({emu::MemoryArena::kOnChipBase, config.on_chip_bytes, false});
  if (config.external_bytes > 0)
    segments.push_back({emu::MemoryArena::kExternalBase, config.external_bytes, edac_external});
  return segments;
}

std::vector<Segment> segments_of(emu::Node& module, const MemoryTarget& target) {
  const emu::MemoryArena& memory = module.memory();
  const emu::MemoryUpsets& upsets = module.upsets();
  if (over_all_memory(target))
    return segments_of_memory(memory.config(), upsets.edac_on_external());
  std::vector<Segment> segments;
  const std::string wanted = lower(target.buffer);
  for (const emu::BlockInfo& block : memory.blocks())
    if (wanted.empty() || names(block, wanted))
      segments.push_back({block.start, block.bytes, upsets.protects(block.start)});
  return segments;
}

std::uint64_t bits_of(const Segment& segment, bool with_check_bits) {
  const std::uint64_t data = std::uint64_t{segment.bytes} * 8;
  if (!with_check_bits || !segment.edac)
    return data;
  return data + segment.bytes / emu::MemoryArena::kWordBytes * emu::kEdacCheckBits;
}

/// A bit drawn uniformly over the segments' physical bits (check bits only for an upset: a
/// stuck cell is drawn among the data bits).
void draw_bit(MemoryHit& hit, const std::vector<Segment>& segments, const Fault& fault) {
  const bool check_bits = fault.kind == Fault::Kind::upset && !fault.memory.bit;
  std::uint64_t total = 0;
  for (const Segment& segment : segments)
    total += bits_of(segment, check_bits);
  SplitMix random(fault.draw, 0x5E0);
  std::uint64_t pick = random.below(total);
  for (const Segment& segment : segments) {
    const std::uint64_t bits = bits_of(segment, check_bits);
    if (pick >= bits) {
      pick -= bits;
      continue;
    }
    const std::uint64_t data_bits = std::uint64_t{segment.bytes} * 8;
    if (pick < data_bits) {
      hit.address = segment.start + static_cast<emu::Address>(pick / 8);
      hit.bit = fault.memory.bit.value_or(static_cast<unsigned>(pick % 8));
      return;
    }
    const std::uint64_t check = pick - data_bits;
    hit.address = segment.start + static_cast<emu::Address>(check / emu::kEdacCheckBits *
                                                            emu::MemoryArena::kWordBytes);
    hit.bit = static_cast<unsigned>(check % emu::kEdacCheckBits);
    hit.check_bit = true;
    return;
  }
}

void place(MemoryHit& hit, const emu::MemoryConfig& config) {
  hit.on_chip = hit.address - emu::MemoryArena::kOnChipBase < config.on_chip_bytes;
  hit.reserved =
      hit.on_chip && hit.address - emu::MemoryArena::kOnChipBase < config.reserved_on_chip_bytes;
}

void locate(MemoryHit& hit, emu::Node& module, const Fault& fault) {
  const MemoryTarget& target = fault.memory;
  if (target.address) {
    if (!module.memory().contains(*target.address))
      throw MemoryTargetError(fmt::format(
          "{}: #{:08X} is outside its memory (#{:08X}..#{:08X})", module.name(), *target.address,
          emu::MemoryArena::kOnChipBase, module.memory().end_address() - 1));
    hit.address = *target.address;
    hit.bit = target.bit.value_or(0);
    return;
  }
  const std::vector<Segment> segments = segments_of(module, target);
  if (segments.empty())
    throw MemoryTargetError(
        target.buffer.empty()
            ? fmt::format("{}: no memory is allocated to strike", module.name())
            : fmt::format("{}: no buffer matching '{}' is allocated at the strike", module.name(),
                          target.buffer));
  draw_bit(hit, segments, fault);
}

} // namespace

bool MemoryHit::corrupts_data() const {
  return effect != emu::UpsetEffect::corrected && block && block->kind == emu::BlockKind::data;
}

bool MemoryHit::corrupts_control() const {
  return effect != emu::UpsetEffect::corrected &&
         (reserved || (block && block->kind != emu::BlockKind::data));
}

std::string MemoryHit::region() const {
  if (reserved)
    return "on-chip reserved";
  return on_chip ? "on-chip" : "external";
}

std::string MemoryHit::buffer() const {
  if (reserved)
    return "processor's reserved words";
  if (!block)
    return "free";
  if (block->kind == emu::BlockKind::workspace)
    return "workspace of " + block->owner;
  if (block->kind == emu::BlockKind::code)
    return "code";
  return block->label.empty() ? block->owner + " data" : block->label;
}

std::optional<MemoryHit> locate_before_strike(const emu::MemoryConfig& config, bool edac_external,
                                              const Fault& fault) {
  if (!is_memory_fault(fault.kind) || !(fault.memory.address || over_all_memory(fault.memory)))
    return std::nullopt;
  MemoryHit hit;
  if (fault.memory.address) {
    hit.address = *fault.memory.address;
    hit.bit = fault.memory.bit.value_or(0);
  } else {
    draw_bit(hit, segments_of_memory(config, edac_external), fault);
  }
  place(hit, config);
  return hit;
}

MemoryHit strike_memory(emu::Node& module, const Fault& fault) {
  MemoryHit hit;
  locate(hit, module, fault);
  const emu::MemoryArena& memory = module.memory();
  place(hit, memory.config());
  hit.block = memory.block_at(hit.address);
  emu::MemoryUpsets& upsets = module.upsets();
  if (fault.kind == Fault::Kind::stuck)
    hit.effect = upsets.stick(hit.address, hit.bit, fault.memory.stuck_value);
  else if (hit.check_bit)
    hit.effect = upsets.upset_check_bit(hit.address, hit.bit);
  else
    hit.effect = upsets.upset(hit.address, hit.bit);
  return hit;
}

} // namespace marsokhod::overswitch
