// Reading a platform file's [overswitch] table.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/io/formats/toml_table.hpp"

namespace marsokhod::emulator::detail {

/// The overswitch of `platform`, whose nodes are read: its modules are nodes, named once each,
/// as many powered as it powers at once; its watchdog outlasts the heartbeat.
OverswitchSpec read_overswitch(io::TomlTable& table, const PlatformSpec& platform);

} // namespace marsokhod::emulator::detail
