// The heartbeat process.

#include "marsokhod/overswitch/supervision/heartbeat.hpp"

#include "marsokhod/emulator/links/link_frame_store.hpp"

namespace marsokhod::overswitch {

emulator::Process& start_heartbeat(emulator::Node& module, emulator::SharedOutput& device_link,
                                   emulator::Tick period, const bool& stop) {
  return module.spawn(
      "heartbeat",
      [&module, &device_link, period, &stop] {
        emulator::Kernel& kernel = module.kernel();
        const std::byte beat = emulator::FrameStore::kHeartbeat;
        for (emulator::Tick next = kernel.now(); !stop; next += period) {
          module.execute(emulator::Instruction::out);
          device_link.output(std::span(&beat, 1));
          kernel.block_until(next + period, emulator::WaitInfo{emulator::WaitKind::timer, nullptr});
        }
      },
      emulator::NodeSpawnOptions{emulator::Priority::high, 0, 0, nullptr});
}

} // namespace marsokhod::overswitch
