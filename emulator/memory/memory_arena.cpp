// A node's memory: on-chip and external regions, allocation and the address map.

#include "marsokhod/emulator/memory/memory_arena.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <stdexcept>
#include <sys/mman.h>
#include <system_error>

namespace marsokhod::emulator {
namespace {

constexpr std::size_t kExternalOffset = MemoryArena::kExternalBase - MemoryArena::kOnChipBase;
constexpr const char* kNoProcess = "(no process)";

std::size_t round_up(std::size_t value, std::size_t alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

bool is_power_of_two(std::size_t value) {
  return value != 0 && (value & (value - 1)) == 0;
}

// The node's bytes, mapped rather than allocated: the kernel hands out zeroed pages as they are
// first touched, so a node with 2 GB of external RAM costs the host only what its programs
// use. MAP_NORESERVE: no swap is set aside for the untouched rest. Page-aligned, which covers
// kMaxAlignment.
std::byte* map_host_bytes(std::size_t size) {
  void* bytes = ::mmap(nullptr, size, PROT_READ | PROT_WRITE,
                       MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (bytes == MAP_FAILED) {
    const int error = errno;
    throw HostMemoryError(
        fmt::format("cannot map {} bytes of host memory for a node's emulated memory: {}", size,
                    std::generic_category().message(error)));
  }
  return static_cast<std::byte*>(bytes);
}

MemoryConfig checked(const MemoryConfig& config) {
  if (config.on_chip_bytes > kExternalOffset)
    throw std::invalid_argument(
        fmt::format("on-chip memory of {} bytes exceeds the T805's {} bytes", config.on_chip_bytes,
                    kExternalOffset));
  if (config.reserved_on_chip_bytes > config.on_chip_bytes)
    throw std::invalid_argument("reserved on-chip bytes exceed the on-chip memory");
  if (config.external_bytes > 0x7FFFF000U)
    throw std::invalid_argument("external memory exceeds the T805 address space");
  return config;
}

const char* region_name(Placement placement) {
  switch (placement) {
  case Placement::on_chip:
    return "on-chip";
  case Placement::external:
    return "external";
  case Placement::on_chip_then_external:
    return "on-chip or external";
  }
  return "unknown";
}

} // namespace

MemoryArena::MemoryArena(const MemoryConfig& config)
    : config_(checked(config)), bytes_(map_host_bytes(kExternalOffset + config_.external_bytes),
                                       HostBytesDeleter{kExternalOffset + config_.external_bytes}) {
  const std::size_t usable_on_chip = config_.on_chip_bytes - config_.reserved_on_chip_bytes;
  if (usable_on_chip > 0)
    on_chip_free_.emplace(config_.reserved_on_chip_bytes, usable_on_chip);
  if (config_.external_bytes > 0)
    external_free_.emplace(kExternalOffset, config_.external_bytes);
}

MemoryArena::~MemoryArena() = default;

void MemoryArena::HostBytesDeleter::operator()(std::byte* bytes) const {
  ::munmap(bytes, size);
}

Address MemoryArena::allocate_block(std::size_t bytes, std::size_t alignment, Placement placement,
                                    std::string_view owner, BlockKind kind) {
  if (!is_power_of_two(alignment) || alignment > kMaxAlignment)
    throw std::invalid_argument(
        fmt::format("alignment {} is not a power of two up to {}", alignment, kMaxAlignment));
  const std::size_t size = round_up(std::max<std::size_t>(bytes, 1), kWordBytes);
  const std::size_t align = std::max(alignment, kWordBytes);

  std::optional<std::size_t> offset;
  bool on_chip = placement != Placement::external;
  if (on_chip)
    offset = take_first_fit(on_chip_free_, size, align);
  if (!offset && placement != Placement::on_chip) {
    on_chip = false;
    offset = take_first_fit(external_free_, size, align);
  }
  if (!offset)
    fault(bytes, alignment, placement, owner);

  const std::size_t owner_id = owner_index(owner);
  const std::size_t label = kind == BlockKind::data ? owner_labels_[owner_id] : 0;
  const Block block{size, owner_id, kind, on_chip, label};
  blocks_.emplace(*offset, block);
  account_allocation(block);
  const Address start = kOnChipBase + static_cast<Address>(*offset);
  if (block_listener_)
    block_listener_(start, size, true);
  return start;
}

void MemoryArena::free_block(Address address) {
  const std::size_t offset = address - kOnChipBase;
  const auto found = blocks_.find(offset);
  if (address < kOnChipBase || found == blocks_.end())
    throw std::invalid_argument(
        fmt::format("#{:08X} is not the start of an allocated block", address));
  const Block block = found->second;
  blocks_.erase(found);
  give_back(block.on_chip ? on_chip_free_ : external_free_, offset, block.size);
  account_free(block);
  if (block_listener_)
    block_listener_(address, block.size, false);
}

Address MemoryArena::reserve_workspace(std::string_view process, std::size_t bytes) {
  return allocate_block(bytes, kWordBytes, Placement::on_chip_then_external, process,
                        BlockKind::workspace);
}

std::optional<std::size_t> MemoryArena::take_first_fit(FreeList& list, std::size_t bytes,
                                                       std::size_t alignment) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const auto [start, size] = *it;
    const std::size_t aligned = round_up(start, alignment);
    if (aligned + bytes > start + size)
      continue;
    list.erase(it);
    if (aligned > start)
      list.emplace(start, aligned - start);
    if (aligned + bytes < start + size)
      list.emplace(aligned + bytes, start + size - aligned - bytes);
    return aligned;
  }
  return std::nullopt;
}

void MemoryArena::give_back(FreeList& list, std::size_t offset, std::size_t size) {
  auto next = list.lower_bound(offset);
  if (next != list.end() && offset + size == next->first) {
    size += next->second;
    next = list.erase(next);
  }
  if (next != list.begin()) {
    const auto previous = std::prev(next);
    if (previous->first + previous->second == offset) {
      previous->second += size;
      return;
    }
  }
  list.emplace_hint(next, offset, size);
}

std::size_t MemoryArena::owner_index(std::string_view owner) {
  const std::string name(owner.empty() ? kNoProcess : owner);
  const auto [it, inserted] = owner_ids_.try_emplace(name, owner_usage_.size());
  if (inserted) {
    owner_usage_.push_back(OwnerUsage{name, 0, 0, 0, 0, 0});
    owner_labels_.push_back(0);
  }
  return it->second;
}

void MemoryArena::account_allocation(const Block& block) {
  OwnerUsage& owner = owner_usage_[block.owner];
  (block.kind == BlockKind::workspace ? owner.workspace_bytes : owner.data_bytes) += block.size;
  owner.peak_bytes = std::max(owner.peak_bytes, owner.data_bytes + owner.workspace_bytes);
  ++owner.allocations;

  usage_.in_use_bytes += block.size;
  usage_.peak_bytes = std::max(usage_.peak_bytes, usage_.in_use_bytes);
  if (block.on_chip) {
    usage_.on_chip_in_use_bytes += block.size;
    usage_.on_chip_peak_bytes = std::max(usage_.on_chip_peak_bytes, usage_.on_chip_in_use_bytes);
  } else {
    usage_.external_in_use_bytes += block.size;
    usage_.external_peak_bytes = std::max(usage_.external_peak_bytes, usage_.external_in_use_bytes);
  }
  if (block.kind == BlockKind::workspace)
    usage_.workspace_bytes += block.size;
  ++usage_.allocations;
  if (usage_listener_)
    usage_listener_(usage_);
}

void MemoryArena::account_free(const Block& block) {
  OwnerUsage& owner = owner_usage_[block.owner];
  (block.kind == BlockKind::workspace ? owner.workspace_bytes : owner.data_bytes) -= block.size;
  ++owner.frees;

  usage_.in_use_bytes -= block.size;
  (block.on_chip ? usage_.on_chip_in_use_bytes : usage_.external_in_use_bytes) -= block.size;
  if (block.kind == BlockKind::workspace)
    usage_.workspace_bytes -= block.size;
  ++usage_.frees;
  if (usage_listener_)
    usage_listener_(usage_);
}

void MemoryArena::fault(std::size_t bytes, std::size_t alignment, Placement placement,
                        std::string_view owner) const {
  MemoryFault error(std::string(owner.empty() ? kNoProcess : owner), bytes, alignment,
                    region_name(placement), free_bytes(placement), largest_free_block(placement));
  if (fault_listener_)
    fault_listener_(error);
  throw error;
}

std::string MemoryArena::current_owner() const {
  if (!owner_scopes_.empty())
    return owner_scopes_.back();
  if (owner_provider_)
    return owner_provider_();
  return kNoProcess;
}

void MemoryArena::set_owner_provider(std::function<std::string()> provider) {
  owner_provider_ = std::move(provider);
}

MemoryArena::OwnerScope::OwnerScope(MemoryArena& arena, std::string owner)
    : arena_(arena), depth_(arena.owner_scopes_.size()) {
  arena_.owner_scopes_.push_back(std::move(owner));
}

MemoryArena::OwnerScope::~OwnerScope() {
  arena_.owner_scopes_.resize(depth_);
}

bool MemoryArena::contains(Address address) const {
  if (address < kOnChipBase)
    return false;
  const std::size_t offset = address - kOnChipBase;
  if (offset < kExternalOffset)
    return offset < config_.on_chip_bytes;
  return offset - kExternalOffset < config_.external_bytes;
}

bool MemoryArena::is_on_chip(Address address) const {
  return address >= kOnChipBase && address < kOnChipBase + config_.on_chip_bytes;
}

std::byte* MemoryArena::pointer(Address address) {
  if (!contains(address))
    throw std::out_of_range(fmt::format("address #{:08X} is outside populated memory", address));
  return bytes_.get() + (address - kOnChipBase);
}

const std::byte* MemoryArena::pointer(Address address) const {
  return const_cast<MemoryArena*>(this)->pointer(address);
}

Address MemoryArena::address_of(const void* pointer) const {
  const auto* byte = static_cast<const std::byte*>(pointer);
  const std::byte* begin = bytes_.get();
  const std::size_t span = kExternalOffset + config_.external_bytes;
  if (std::less<>{}(byte, begin) || !std::less<>{}(byte, begin + span))
    throw std::out_of_range("pointer is not inside this node's memory");
  const auto address = kOnChipBase + static_cast<Address>(byte - begin);
  if (!contains(address))
    throw std::out_of_range(fmt::format("pointer maps to unpopulated address #{:08X}", address));
  return address;
}

Address MemoryArena::end_address() const {
  return kExternalBase + static_cast<Address>(config_.external_bytes);
}

void MemoryArena::flip_bit(Address address, unsigned bit) {
  if (bit > 7)
    throw std::out_of_range(fmt::format("bit {} does not exist in a byte", bit));
  std::byte* byte = pointer(address);
  *byte ^= std::byte{static_cast<unsigned char>(1U << bit)};
}

std::vector<OwnerUsage> MemoryArena::owners() const {
  return owner_usage_;
}

std::size_t MemoryArena::free_bytes(Placement placement) const {
  std::size_t total = 0;
  if (placement != Placement::external)
    for (const auto& [start, size] : on_chip_free_)
      total += size;
  if (placement != Placement::on_chip)
    for (const auto& [start, size] : external_free_)
      total += size;
  return total;
}

std::size_t MemoryArena::largest_free_block(Placement placement) const {
  std::size_t largest = 0;
  if (placement != Placement::external)
    for (const auto& [start, size] : on_chip_free_)
      largest = std::max(largest, size);
  if (placement != Placement::on_chip)
    for (const auto& [start, size] : external_free_)
      largest = std::max(largest, size);
  return largest;
}

void MemoryArena::set_usage_listener(std::function<void(const ArenaUsage&)> listener) {
  usage_listener_ = std::move(listener);
}

void MemoryArena::set_block_listener(
    std::function<void(Address start, std::size_t bytes, bool allocated)> listener) {
  block_listener_ = std::move(listener);
}

void MemoryArena::set_fault_listener(std::function<void(const MemoryFault&)> listener) {
  fault_listener_ = std::move(listener);
}

void* MemoryArena::do_allocate(std::size_t bytes, std::size_t alignment) {
  return pointer(allocate_block(bytes, alignment, default_placement_, current_owner()));
}

void MemoryArena::do_deallocate(void* pointer, std::size_t /*bytes*/, std::size_t /*alignment*/) {
  free_block(address_of(pointer));
}

bool MemoryArena::do_is_equal(const std::pmr::memory_resource& other) const noexcept {
  return this == &other;
}

} // namespace marsokhod::emulator
