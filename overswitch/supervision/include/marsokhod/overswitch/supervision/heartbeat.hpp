// The heartbeat: a high-priority process on each running module that kicks its watchdog.
#pragma once

#include "marsokhod/emulator/links/shared_output.hpp"
#include "marsokhod/emulator/node/node.hpp"

namespace marsokhod::overswitch {

/// Starts the heartbeat of `module`: at high priority, so that no low-priority work delays it,
/// it outputs the heartbeat byte (emulator::FrameStore::kHeartbeat) on the module's device
/// link at once and then every `period`; the overswitch on the device links kicks the module's
/// watchdog when the byte arrives. It shares the link's output with the program. It runs until
/// its module stops (power-off and hang kill it) or, at a beat, finds `stop` set.
emulator::Process& start_heartbeat(emulator::Node& module, emulator::SharedOutput& device_link,
                                   emulator::Tick period, const bool& stop);

} // namespace marsokhod::overswitch
