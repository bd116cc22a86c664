// The boot stream: length-prefixed blocks from the running module to the spare's boot hardware.

#include "marsokhod/overswitch/supervision/link_boot.hpp"

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/memory/memory_arena.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <vector>

namespace marsokhod::overswitch {
namespace {

constexpr std::size_t kBlockBytes = 255; // a length byte counts at most 255

std::vector<std::size_t> block_sizes(std::size_t code_bytes) {
  std::vector<std::size_t> blocks;
  for (std::size_t left = code_bytes; left > 0; left -= std::min(left, kBlockBytes))
    blocks.push_back(std::min(left, kBlockBytes));
  return blocks;
}

} // namespace

std::size_t boot_stream_bytes(std::size_t code_bytes) {
  return code_bytes + block_sizes(code_bytes).size();
}

void boot_over_link(const emulator::PlatformSpec& platform, emulator::LinkNetwork& links,
                    emulator::Node& spare, emulator::Node& from, std::size_t code_bytes,
                    std::function<void()> done) {
  const emulator::WireSpec* wire = platform.wire_between(from.name(), spare.name());
  if (wire == nullptr || wire->broken)
    throw std::invalid_argument(
        fmt::format("no sound wire joins {} and {} to boot over", from.name(), spare.name()));
  const bool from_is_a = wire->a.owner == from.name();
  emulator::LinkPort& out =
      links.require_port(from.name(), from_is_a ? wire->a.link : wire->b.link);
  emulator::LinkPort& in =
      links.require_port(spare.name(), from_is_a ? wire->b.link : wire->a.link);
  const std::vector<std::size_t> blocks = block_sizes(code_bytes);
  from.spawn(
      "boot " + spare.name(),
      [&from, &out, blocks] {
        std::vector<std::byte> message(kBlockBytes + 1);
        for (const std::size_t size : blocks) {
          message[0] = std::byte(static_cast<unsigned char>(size));
          from.execute(emulator::Instruction::out);
          out.output(std::span(message.data(), size + 1));
        }
      },
      emulator::NodeSpawnOptions{emulator::Priority::high, 0, 0, nullptr});
  // The spare's boot hardware: it takes the length byte, then the block, into memory.
  spare.spawn(
      "boot loader",
      [&spare, &in, count = blocks.size(), code_bytes, done = std::move(done)] {
        std::vector<std::byte> block(kBlockBytes);
        for (std::size_t b = 0; b < count; ++b) {
          std::byte length{};
          in.input(std::span(&length, 1));
          in.input(std::span(block.data(), static_cast<std::size_t>(length)));
        }
        spare.memory().allocate_block(code_bytes, emulator::MemoryArena::kWordBytes,
                                      emulator::Placement::on_chip_then_external, "code",
                                      emulator::BlockKind::code);
        done();
      },
      emulator::NodeSpawnOptions{emulator::Priority::high, 0, 0, nullptr});
}

} // namespace marsokhod::overswitch
