// A node's memory as reports of upsets see it: which block holds an address, and what for.

#include "marsokhod/emulator/memory/memory_arena.hpp"

#include <iterator>

namespace marsokhod::emulator {

const char* to_string(BlockKind kind) {
  switch (kind) {
  case BlockKind::data:
    return "data";
  case BlockKind::workspace:
    return "workspace";
  case BlockKind::code:
    return "code";
  }
  return "?";
}

std::size_t MemoryArena::label_index(std::string_view label) {
  if (label.empty())
    return 0;
  const auto [it, inserted] = label_ids_.try_emplace(std::string(label), labels_.size());
  if (inserted)
    labels_.emplace_back(label);
  return it->second;
}

void MemoryArena::set_label(std::string_view owner, std::string_view label) {
  const std::size_t id = owner_index(owner);
  owner_labels_[id] = label_index(label);
}

BlockInfo MemoryArena::info(std::size_t offset, const Block& block) const {
  return BlockInfo{kOnChipBase + static_cast<Address>(offset),
                   block.size,
                   owner_usage_[block.owner].owner,
                   labels_[block.label],
                   block.kind,
                   block.on_chip};
}

std::optional<BlockInfo> MemoryArena::block_at(Address address) const {
  if (!contains(address))
    return std::nullopt;
  const std::size_t offset = address - kOnChipBase;
  auto after = blocks_.upper_bound(offset);
  if (after == blocks_.begin())
    return std::nullopt;
  const auto& [start, block] = *std::prev(after);
  if (offset >= start + block.size)
    return std::nullopt;
  return info(start, block);
}

std::vector<BlockInfo> MemoryArena::blocks() const {
  std::vector<BlockInfo> all;
  all.reserve(blocks_.size());
  for (const auto& [offset, block] : blocks_)
    all.push_back(info(offset, block));
  return all;
}

} // namespace marsokhod::emulator
