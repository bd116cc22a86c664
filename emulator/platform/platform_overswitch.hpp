// Reading a platform file's [overswitch] table.
#pragma once

#include "platform/platform_table_reader.hpp"

#include "marsokhod/emulator/platform/platform.hpp"

namespace marsokhod::emulator::detail {

/// The overswitch of `platform`, whose nodes are read: its modules are nodes, named once each,
/// as many powered as it powers at once; its watchdog outlasts the heartbeat.
OverswitchSpec read_overswitch(TableReader& table, const PlatformSpec& platform);

} // namespace marsokhod::emulator::detail
