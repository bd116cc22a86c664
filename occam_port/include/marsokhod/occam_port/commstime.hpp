// The Commstime benchmark network and what one run of it measures.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/node/node.hpp"

#include <cstdint>

namespace marsokhod::occam_port {

/// How to run Commstime.
struct CommstimeOptions {
  /// Loops measured (one loop = four channel communications).
  std::int64_t loops = 10'000;
  /// Loops run before the measurement starts and after it ends (so that neither the start-up
  /// nor the shutdown of the network falls inside the measurement).
  std::int64_t warmup_loops = 16;
  /// delta outputs to successor and consumer in PAR (the standard form) or in SEQ.
  bool parallel_delta = true;
};

/// What one run measured, all in simulated time.
struct CommstimeResult {
  std::int64_t loops = 0;
  /// Channel communications in the whole run (four per loop, warm-up and cool-down included).
  std::int64_t communications = 0;
  /// Simulated time of the measured loops.
  emulator::Tick measured_time = 0;
  double emulated_us_per_loop() const;
};

/// Spawns the standard occam Commstime network (prefix, delta, successor, consumer) on `node`;
/// the result is complete once the kernel has run until the network finished:
///
///   prefix (0) --a--> delta --b--> successor --c--> prefix
///                       `--d--> consumer
///
/// The processes loop a fixed number of times so that the network ends cleanly.
void spawn_commstime(emulator::Node& node, const CommstimeOptions& options,
                     CommstimeResult& result);

} // namespace marsokhod::occam_port
