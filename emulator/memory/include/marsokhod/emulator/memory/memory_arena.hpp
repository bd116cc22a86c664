// A node's memory: the T805 address map, on-chip and external regions, allocation.
#pragma once

#include "marsokhod/emulator/memory/memory_arena_fault.hpp"
#include "marsokhod/emulator/memory/memory_arena_usage.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <memory_resource>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace marsokhod::emulator {

/// A T805 byte address (the address space is signed, on-chip RAM sits at the most negative end).
using Address = std::uint32_t;

/// Sizes of a node's memory; the address map itself is fixed by the T805 (T805.md, "Clock and
/// memory": on-chip RAM at #80000000, MemStart #80000070, external memory from #80001000).
struct MemoryConfig {
  std::size_t on_chip_bytes = 4096;
  std::size_t external_bytes = 256 * 1024;
  /// Bytes at the bottom of on-chip RAM the processor reserves (link and event channel words,
  /// saved registers): MemStart - #80000000 = #70.
  std::size_t reserved_on_chip_bytes = 0x70;
};

/// The host could not provide the bytes behind a node's memory (address space exhausted, as
/// under a `ulimit -v`); the message says how many bytes were asked for.
class HostMemoryError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Where a block may be placed.
enum class Placement : std::uint8_t {
  on_chip,              ///< only on-chip RAM (1-cycle access)
  external,             ///< only external RAM
  on_chip_then_external ///< on-chip first, as a linker filling memory from MemStart would
};

/// What a block is for; workspaces are the processes' stacks in occam terms.
enum class BlockKind : std::uint8_t { data, workspace, code };

const char* to_string(BlockKind kind);

/// One allocated block as reports of upsets name it: where it is, whose, and what for.
struct BlockInfo {
  Address start = 0;
  std::size_t bytes = 0;
  std::string owner;
  /// What the block holds ("left image, 128 x 128 x 1 B"); empty when its owner never said.
  std::string label;
  BlockKind kind = BlockKind::data;
  bool on_chip = false;
};

/// A node's memory: real bytes for on-chip RAM and for the external arena (mapped zeroed, backed
/// by host memory only where touched, so that its size costs nothing up front), handed out by a
/// deterministic first-fit allocator with coalescing, so that addresses depend only on the
/// sequence of requests. Every block is charged to an owner (a process name); running out
/// raises MemoryFault naming the owner and the request. Usable as a std::pmr::memory_resource
/// (placement `default_placement()`, external memory unless changed).
class MemoryArena : public std::pmr::memory_resource {
public:
  static constexpr Address kOnChipBase = 0x80000000U;
  static constexpr Address kExternalBase = 0x80001000U;
  /// Host alignment of the byte buffer; larger alignment requests are refused.
  static constexpr std::size_t kMaxAlignment = 4096;
  /// Allocation granularity: the T805 word.
  static constexpr std::size_t kWordBytes = 4;

  /// std::invalid_argument for a config beyond the T805 address map, HostMemoryError when the
  /// host cannot map the bytes.
  explicit MemoryArena(const MemoryConfig& config);
  ~MemoryArena() override;
  MemoryArena(const MemoryArena&) = delete;
  MemoryArena& operator=(const MemoryArena&) = delete;

  const MemoryConfig& config() const { return config_; }

  /// Allocates `bytes` (rounded up to whole words) for `owner`; throws MemoryFault when no free
  /// block of the placement fits, std::invalid_argument for an alignment above kMaxAlignment.
  Address allocate_block(std::size_t bytes, std::size_t alignment, Placement placement,
                         std::string_view owner, BlockKind kind = BlockKind::data);
  /// Frees a block returned by allocate_block; an address that is no block's start is a logic
  /// error (std::invalid_argument).
  void free_block(Address address);

  /// Reserves a process workspace of `bytes`, on-chip when it fits (as occam places the
  /// workspaces of the first processes), external otherwise.
  Address reserve_workspace(std::string_view process, std::size_t bytes);

  /// Placement used by the std::pmr interface.
  Placement default_placement() const { return default_placement_; }
  void set_default_placement(Placement placement) { default_placement_ = placement; }

  /// Who the std::pmr interface charges: an explicit OwnerScope if one is active, otherwise the
  /// provider (the kernel's "current process"), otherwise "(no process)".
  std::string current_owner() const;
  void set_owner_provider(std::function<std::string()> provider);

  /// Names what `owner`'s next blocks hold (a buffer's name), until it names something else;
  /// reports of upsets say which buffer they struck.
  void set_label(std::string_view owner, std::string_view label);

  /// Sets the owner the std::pmr interface charges for as long as it lives.
  class OwnerScope {
  public:
    OwnerScope(MemoryArena& arena, std::string owner);
    ~OwnerScope();
    OwnerScope(const OwnerScope&) = delete;
    OwnerScope& operator=(const OwnerScope&) = delete;

  private:
    MemoryArena& arena_;
    std::vector<std::string>::size_type depth_;
  };

  // Address map.
  bool contains(Address address) const;
  bool is_on_chip(Address address) const;
  std::byte* pointer(Address address);
  const std::byte* pointer(Address address) const;
  /// The T805 address of a host pointer into this arena; std::out_of_range when it is not.
  Address address_of(const void* pointer) const;
  /// One past the last populated address.
  Address end_address() const;

  /// Inverts bit `bit` (0 = least significant) of the byte at `address`, as a particle hit
  /// would; std::out_of_range for an address outside populated memory or a bit above 7.
  void flip_bit(Address address, unsigned bit);

  /// The block holding `address`; nothing when the address is free, reserved or outside.
  std::optional<BlockInfo> block_at(Address address) const;
  /// Every allocated block, in address order.
  std::vector<BlockInfo> blocks() const;

  // Accounting.
  const ArenaUsage& usage() const { return usage_; }
  /// Per-owner figures, in order of each owner's first allocation.
  std::vector<OwnerUsage> owners() const;
  std::size_t free_bytes(Placement placement) const;
  std::size_t largest_free_block(Placement placement) const;

  /// Called after every change of the bytes in use (allocation or free).
  void set_usage_listener(std::function<void(const ArenaUsage&)> listener);
  /// Called after each block is allocated (true) or freed (false), with its start and bytes.
  void set_block_listener(
      std::function<void(Address start, std::size_t bytes, bool allocated)> listener);
  /// Called with each memory fault just before it is thrown.
  void set_fault_listener(std::function<void(const MemoryFault&)> listener);

protected:
  void* do_allocate(std::size_t bytes, std::size_t alignment) override;
  void do_deallocate(void* pointer, std::size_t bytes, std::size_t alignment) override;
  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override;

private:
  struct Block {
    std::size_t size;
    std::size_t owner;
    BlockKind kind;
    bool on_chip;
    std::size_t label;
  };
  /// Free blocks of one region, start offset -> size; address order makes the scan first-fit.
  using FreeList = std::map<std::size_t, std::size_t>;

  std::optional<std::size_t> take_first_fit(FreeList& list, std::size_t bytes,
                                            std::size_t alignment);
  static void give_back(FreeList& list, std::size_t offset, std::size_t size);
  std::size_t owner_index(std::string_view owner);
  std::size_t label_index(std::string_view label);
  BlockInfo info(std::size_t offset, const Block& block) const;
  void account_allocation(const Block& block);
  void account_free(const Block& block);
  [[noreturn]] void fault(std::size_t bytes, std::size_t alignment, Placement placement,
                          std::string_view owner) const;

  MemoryConfig config_;
  struct HostBytesDeleter {
    std::size_t size;
    void operator()(std::byte* bytes) const;
  };

  std::unique_ptr<std::byte, HostBytesDeleter> bytes_;
  FreeList on_chip_free_;
  FreeList external_free_;
  std::map<std::size_t, Block> blocks_;
  std::vector<OwnerUsage> owner_usage_;
  std::unordered_map<std::string, std::size_t> owner_ids_;
  /// Labels, interned (index 0: none); each owner's current one, by owner index.
  std::vector<std::string> labels_{std::string()};
  std::unordered_map<std::string, std::size_t> label_ids_;
  std::vector<std::size_t> owner_labels_;
  std::vector<std::string> owner_scopes_;
  std::function<std::string()> owner_provider_;
  std::function<void(const ArenaUsage&)> usage_listener_;
  std::function<void(const MemoryFault&)> fault_listener_;
  std::function<void(Address, std::size_t, bool)> block_listener_;
  Placement default_placement_ = Placement::external;
  ArenaUsage usage_;
};

} // namespace marsokhod::emulator
