// Example: the occam multiplexer with a timeout (docs/emulator.md) on one emulated T805.
//
// Two producers feed the multiplexer's inputs at set clock values, the multiplexer passes on
// what arrives (in.0 first when both are ready) or -1 after 100 quiet ticks, and a consumer
// prints each value with the simulated time at which it received it. Every process runs at
// high priority, so the timer ticks every 1 us and no process is preempted or timesliced: the
// CPU runs the ready processes one after another in the order they became ready, each until
// it blocks. Only the occam primitives cost simulated time (channel in/out, ldtimer, tin, the
// ALT's enables and disables); the C++ loop control around them is free. How each printed time
// follows from the platform file's data-book costs: examples/expected/occam_multiplexer.txt.
//
// Usage: example_occam_multiplexer [PLATFORM.toml]   (default: the shipped pc-card.toml)

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/occam_port/occam.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <utility>

namespace {

namespace emu = marsokhod::emulator;
using namespace marsokhod::occam_port;

// PROC mux (CHAN OF INT in.0, in.1, out): whatever arrives on in.0 or in.1 goes to out, in.0
// first when both are ready; -1 when nothing came for 100 ticks of the timer.
void mux(ChanIn<int> in0, ChanIn<int> in1, ChanOut<int> out) {
  Timer tim;
  const auto pass = [out](int x) { out << x; };
  for (;;) {
    const std::int32_t t = tim.read();
    pri_alt(on_input(in0, pass), on_input(in1, pass), on_after(tim, t + 100, [out] { out << -1; }));
  }
}

// SEQ  tim ? AFTER after  ;  out ! value
void send_after(ChanOut<int> out, std::int32_t after, int value) {
  Timer tim;
  tim.wait_after(after);
  out << value;
}

// Inputs `count` values, printing each with the simulated time it arrived, then ends the run
// (the multiplexer itself never stops).
void print_received(ChanIn<int> in, int count, emu::Kernel& kernel) {
  for (int i = 0; i < count; ++i) {
    int x = 0;
    in >> x;
    fmt::print("received {:3} at {}\n", x, emu::format_time(kernel.now()));
  }
  kernel.stop();
}

int run(const std::filesystem::path& platform_file) {
  const emu::PlatformSpec platform = emu::load_platform(platform_file);
  const emu::NodeSpec& spec = platform.nodes.front();
  fmt::print("occam multiplexer on {} node {} ({}, {} ps cycle), every process at high "
             "priority\n",
             platform.name, spec.name, spec.speed_grade, spec.cpu.cycle);

  Chan<int> in0("in.0"), in1("in.1"), out("out");
  emu::Kernel kernel;
  emu::Node node(kernel, spec);
  const auto spawn_high = [&node](const char* name, std::function<void()> body) {
    node.spawn(name, std::move(body), emu::NodeSpawnOptions{emu::Priority::high});
  };
  constexpr int kMessages = 7;
  // Spawned in this order, so they first run in this order at time 0.
  spawn_high(
      "mux", [&] { mux(in0, in1, out); });
  spawn_high("consumer", [&] { print_received(out, kMessages, kernel); });
  spawn_high("producer.0", [&] {
    send_after(in0, 50, 10);
    send_after(in0, 400, 11);
  });
  spawn_high("producer.1", [&] {
    send_after(in1, 20, 20);
    send_after(in1, 400, 21);
  });

  const emu::RunResult result = kernel.run();
  fmt::print("run {} at {} after {} messages\n", emu::to_string(result.reason),
             emu::format_time(result.time), kMessages);
  return result.reason == emu::StopReason::stopped ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
  try {
    return run(argc > 1 ? std::filesystem::path(argv[1]) : emu::find_platform_file("pc-card.toml"));
  } catch (const std::exception& error) {
    fmt::print(stderr, "example_occam_multiplexer: {}\n", error.what());
    return 1;
  }
}
