// Booting a spare module over a link from a running one, as a T805 boots.
#pragma once

#include "marsokhod/emulator/links/link_network.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <cstddef>
#include <functional>

namespace marsokhod::overswitch {

/// The boot stream of `code_bytes` of program: a T805 with BootFromROM low boots from the first
/// link that receives a byte, which is the length of the block that follows (T805 datasheet,
/// "Bootstrapping"); a program longer than a block goes as a chain of blocks of at most 255
/// bytes, each behind its length byte.
std::size_t boot_stream_bytes(std::size_t code_bytes);

/// Boots `spare` from `from` over the wire joining them: a process on `from` outputs the boot
/// stream on its link, the spare's boot hardware (a process on the spare standing for it)
/// inputs it block by block and places the program in the spare's memory; `done` is called
/// when the last block is in. std::invalid_argument if no sound wire joins the two.
void boot_over_link(const emulator::PlatformSpec& platform, emulator::LinkNetwork& links,
                    emulator::Node& spare, emulator::Node& from, std::size_t code_bytes,
                    std::function<void()> done);

} // namespace marsokhod::overswitch
