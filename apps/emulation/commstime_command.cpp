// `marsokhod commstime`: the occam Commstime benchmark on one emulated T805.

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/trace_file.hpp"

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/emulator/trace/chrome_trace.hpp"
#include "marsokhod/occam_port/commstime.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <ctime>
#include <memory>
#include <optional>
#include <string>

namespace marsokhod::apps {
namespace {

namespace emu = marsokhod::emulator;

struct CommstimeCommandOptions {
  std::string platform;
  std::string node;
  std::int64_t loops = 10'000;
  std::string delta = "par";
  std::string trace_file;
  bool json = false;
};

struct Measurement {
  emu::NodeSpec node;
  occam_port::CommstimeResult result;
  double host_seconds = 0;
};

const emu::NodeSpec& choose_node(const emu::PlatformSpec& platform, const std::string& name) {
  if (name.empty()) {
    for (const emu::NodeSpec& node : platform.nodes)
      if (node.powered)
        return node;
    throw CommandError(fmt::format("{}: no powered node to run Commstime on", platform.source));
  }
  const emu::NodeSpec* node = platform.find_node(name);
  if (node == nullptr)
    throw UsageError(fmt::format("--node {}: {} has no such node", name, platform.source));
  return *node;
}

Measurement measure(const CommstimeCommandOptions& options, const emu::NodeSpec& spec,
                    emu::TraceSink* trace) {
  Measurement m{spec, {}, 0};
  emu::Kernel kernel;
  kernel.set_trace(trace);
  emu::NodeSpec powered = spec;
  powered.powered = true;
  emu::Node node(kernel, powered);
  occam_port::CommstimeOptions commstime;
  commstime.loops = options.loops;
  commstime.parallel_delta = options.delta == "par";
  occam_port::spawn_commstime(node, commstime, m.result);
  // Processor time, not wall time: on a shared machine the wall clock also counts the time
  // other programs held the processor.
  const std::clock_t start = std::clock();
  const emu::RunResult run = kernel.run();
  const std::clock_t stop = std::clock();
  if (run.reason != emu::StopReason::finished) {
    throw CommandError("Commstime did not finish: " +
                       (run.deadlock ? run.deadlock->text() : std::string(to_string(run.reason))));
  }
  m.host_seconds = static_cast<double>(stop - start) / CLOCKS_PER_SEC;
  return m;
}

Measurement run_traced(const CommstimeCommandOptions& options, const emu::NodeSpec& spec) {
  if (options.trace_file.empty())
    return measure(options, spec, nullptr);
  return with_trace_file(options.trace_file, [&](emu::ChromeTraceWriter& writer) {
    return measure(options, spec, &writer);
  });
}

// Exact: the measured time is a whole number of cycles.
double cycles_per_loop(const Measurement& m) {
  return static_cast<double>(m.result.measured_time) /
         (static_cast<double>(m.node.cpu.cycle) * static_cast<double>(m.result.loops));
}

double host_ns_per_communication(const Measurement& m) {
  return m.host_seconds * 1e9 / static_cast<double>(m.result.communications);
}

void print_json(const CommstimeCommandOptions& options, const emu::PlatformSpec& platform,
                const Measurement& m) {
  nlohmann::ordered_json json;
  json["platform"] = platform.name;
  json["node"] = m.node.name;
  json["speed_grade"] = m.node.speed_grade;
  json["cycle_ps"] = m.node.cpu.cycle;
  json["delta"] = options.delta;
  json["loops"] = m.result.loops;
  json["communications"] = m.result.communications;
  json["emulated_us_per_loop"] = m.result.emulated_us_per_loop();
  json["emulated_cycles_per_loop"] = cycles_per_loop(m);
  json["host_ns_per_communication"] = host_ns_per_communication(m);
  fmt::print("{}\n", json.dump(2));
}

void print_text(const CommstimeCommandOptions& options, const emu::PlatformSpec& platform,
                const Measurement& m) {
  const double cycles = cycles_per_loop(m);
  fmt::print("Commstime ({} delta) on {} node {} ({}, {:.1f} ns cycle), {} loops\n",
             options.delta == "par" ? "PAR" : "SEQ", platform.name, m.node.name, m.node.speed_grade,
             static_cast<double>(m.node.cpu.cycle) / 1000.0, m.result.loops);
  fmt::print("  emulated time per loop   {:.3f} us ({:.1f} cycles)\n",
             m.result.emulated_us_per_loop(), cycles);
  fmt::print("  per communication        {:.3f} us\n", m.result.emulated_us_per_loop() / 4.0);
  fmt::print("  host CPU time per comm.  {:.1f} ns ({} communications in {:.3f} s)\n",
             host_ns_per_communication(m), m.result.communications, m.host_seconds);
}

} // namespace

Command make_commstime_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "commstime", "Run the occam Commstime benchmark (prefix, delta, successor, consumer) on "
                   "one emulated T805 and report the loop time the data-book table implies.");
  auto options = std::make_shared<CommstimeCommandOptions>();
  app->add_option("--platform", options->platform, "platform TOML file (default: pc-card.toml)");
  app->add_option("--node", options->node, "node to run on (default: the first powered one)");
  app->add_option("--loops", options->loops, "loops measured (four communications each)")
      ->transform(integer_between(std::int64_t{1}, std::int64_t{1'000'000'000}))
      ->capture_default_str();
  app->add_option("--delta", options->delta, "delta outputs in PAR (the standard form) or in SEQ")
      ->check(CLI::IsMember({"par", "seq"}));
  app->add_option("--trace", options->trace_file, "write a Chrome Trace Event JSON file");
  app->add_flag("--json", options->json, "print one JSON object instead of text");
  return {app, [options] {
            const emu::PlatformSpec platform = emu::load_platform(
                options->platform.empty() ? emu::find_platform_file("pc-card.toml")
                                          : std::filesystem::path(options->platform));
            const Measurement m = run_traced(*options, choose_node(platform, options->node));
            if (options->json)
              print_json(*options, platform, m);
            else
              print_text(*options, platform, m);
            return kSuccess;
          }};
}

} // namespace marsokhod::apps
