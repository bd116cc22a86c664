// Example: a producer on one T805 module sends messages over a link to a consumer on another.
//
// module0 and module1 of the onboard computer are joined by their link 0 (10 Mbit/s in the
// shipped onboard.toml). The channel between them is an external channel: each side pays only
// the operand loads and the base of out/in on its CPU, and the link engines move the bytes,
// eleven bits per data byte, each acknowledged by a two-bit packet. The producer prints when
// each output completed (its last byte acknowledged), the consumer when each message arrived
// (its last byte in). How each printed time follows from the platform file's data-book costs
// and link timing: examples/expected/two_node_link.txt.
//
// Usage: example_two_node_link [PLATFORM.toml]   (default: the shipped onboard.toml)

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/links/link_network.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/occam_port/occam.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <exception>
#include <filesystem>

namespace {

namespace emu = marsokhod::emulator;
using namespace marsokhod::occam_port;

constexpr int kMessages = 4;

// SEQ i = 0 FOR n  out ! 1000 + i
void producer(ChanOut<std::int32_t> out, emu::Kernel& kernel) {
  for (std::int32_t i = 0; i < kMessages; ++i) {
    out << 1000 + i;
    fmt::print("module0: output {} done at {}\n", 1000 + i, emu::format_time(kernel.now()));
  }
}

// SEQ i = 0 FOR n  in ? x
void consumer(ChanIn<std::int32_t> in, emu::Kernel& kernel, emu::Tick& last_arrival) {
  for (int i = 0; i < kMessages; ++i) {
    std::int32_t x = 0;
    in >> x;
    last_arrival = kernel.now();
    fmt::print("module1: received {} at {}\n", x, emu::format_time(last_arrival));
  }
}

int run(const std::filesystem::path& platform_file) {
  const emu::PlatformSpec platform = emu::load_platform(platform_file);
  emu::Kernel kernel;
  emu::LinkNetwork network(kernel, platform);
  emu::Node m0(kernel, *platform.find_node("module0"));
  emu::Node m1(kernel, *platform.find_node("module1"));
  network.attach(m0);
  network.attach(m1);
  fmt::print("{} messages of {} bytes from module0 to module1 over link 0 ({}, {} ps cycle)\n",
             kMessages, sizeof(std::int32_t), m0.spec().speed_grade, m0.cpu_spec().cycle);

  Chan<std::int32_t> channel("module0->module1");
  channel.place_on_link(*m0.link(0), *m1.link(0));
  emu::Tick last_arrival = 0;
  m0.spawn(
      "producer", [&] { producer(channel, kernel); });
  m1.spawn("consumer", [&] { consumer(channel, kernel, last_arrival); });

  const emu::RunResult result = kernel.run();
  fmt::print("run {}: {} bytes crossed the link in {} (from the start of the first output to "
             "the last byte's arrival)\n",
             emu::to_string(result.reason), kMessages * sizeof(std::int32_t),
             emu::format_time(last_arrival));
  return result.reason == emu::StopReason::finished ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
  try {
    return run(argc > 1 ? std::filesystem::path(argv[1]) : emu::find_platform_file("onboard.toml"));
  } catch (const std::exception& error) {
    fmt::print(stderr, "example_two_node_link: {}\n", error.what());
    return 1;
  }
}
