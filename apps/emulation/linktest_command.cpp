// `marsokhod linktest`: streams bytes over an emulated link and reports its throughput.

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/trace_file.hpp"

#include "marsokhod/emulator/links/link_stream.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/emulator/trace/chrome_trace.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>

namespace marsokhod::apps {
namespace {

namespace emu = marsokhod::emulator;

struct LinktestOptions {
  std::string platform;
  std::uint64_t bytes = 100'000;
  std::string mode = "oneway";
  std::optional<int> mbps;
  std::size_t message_bytes = 4096;
  std::string trace_file;
  bool json = false;
};

emu::PlatformSpec load(const LinktestOptions& options) {
  if (!options.platform.empty())
    return emu::load_platform(options.platform);
  return emu::load_platform(emu::find_platform_file("onboard.toml"));
}

void check_speed(const emu::PlatformSpec& platform, const std::optional<int>& mbps) {
  if (!mbps)
    return;
  const auto& speeds = platform.link_speeds_mbps;
  if (std::find(speeds.begin(), speeds.end(), *mbps) == speeds.end())
    throw UsageError(fmt::format("--mbps {}: the {} links run at {} Mbit/s", *mbps,
                                 platform.processor_type, fmt::join(speeds, ", ")));
}

emu::LinkStreamResult stream(const LinktestOptions& options, const emu::PlatformSpec& platform) {
  emu::LinkStreamOptions stream_options;
  stream_options.bytes = options.bytes;
  stream_options.both_ways = options.mode == "both";
  stream_options.mbps = options.mbps;
  stream_options.message_bytes = options.message_bytes;
  if (options.trace_file.empty())
    return emu::run_link_stream(platform, stream_options);
  return with_trace_file(options.trace_file, [&](emu::ChromeTraceWriter& writer) {
    stream_options.trace = &writer;
    return emu::run_link_stream(platform, stream_options);
  });
}

nlohmann::ordered_json result_json(const LinktestOptions& options,
                                   const emu::PlatformSpec& platform,
                                   const emu::LinkStreamResult& result) {
  nlohmann::ordered_json json;
  json["platform"] = platform.source;
  json["from"] = result.from;
  json["to"] = result.to;
  json["mode"] = options.mode;
  json["mbps"] = result.mbps;
  json["bytes"] = options.bytes;
  json["message_bytes"] = options.message_bytes;
  json["bytes_moved"] = result.bytes_moved;
  json["emulated_seconds"] = emu::to_seconds(result.elapsed);
  json["bytes_per_second"] = result.bytes_per_second;
  json["intact"] = result.intact;
  return json;
}

int run(const LinktestOptions& options) {
  const emu::PlatformSpec platform = load(options);
  check_speed(platform, options.mbps);
  const emu::LinkStreamResult result = stream(options, platform);
  if (!result.intact)
    throw CommandError("the stream did not arrive intact: the emulated link lost, duplicated or "
                       "reordered bytes, or a process blocked forever");
  if (options.json) {
    fmt::print("{}\n", result_json(options, platform, result).dump(2));
    return kSuccess;
  }
  fmt::print("linktest: {} bytes {} over {} {} {} at {} Mbit/s\n", options.bytes,
             options.mode == "both" ? "each way" : "one way", result.from,
             options.mode == "both" ? "<->" : "->", result.to, result.mbps);
  fmt::print("  emulated time  {}\n", emu::format_time(result.elapsed));
  fmt::print("  throughput     {:.1f} KB/s{}\n", result.bytes_per_second / 1000.0,
             options.mode == "both" ? " (both directions together)" : "");
  return kSuccess;
}

} // namespace

Command make_linktest_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "linktest", "Stream bytes over an emulated INMOS link between two T805 nodes and report "
                  "the throughput that emerges from the link framing (emulated time).");
  auto options = std::make_shared<LinktestOptions>();
  app->add_option("--platform", options->platform,
                  "platform TOML file (default: onboard.toml); the first wire joining two "
                  "powered nodes is used");
  app->add_option("--bytes", options->bytes, "bytes to send in each direction that carries traffic")
      ->transform(integer_between(std::uint64_t{1}, std::uint64_t{1'000'000'000}))
      ->capture_default_str();
  app->add_option("--mode", options->mode,
                  "oneway: one direction; both: both directions at once (bytes_per_second is "
                  "then the sum)")
      ->check(CLI::IsMember({"oneway", "both"}))
      ->capture_default_str();
  app->add_option("--mbps", options->mbps,
                  "link speed in Mbit/s, one the platform's links support (default: the wire's "
                  "speed)")
      ->transform(integer_between(1, 1000));
  app->add_option("--message-bytes", options->message_bytes, "bytes per output/input message")
      ->transform(integer_between(std::size_t{1}, std::size_t{1} << 24))
      ->capture_default_str();
  app->add_option("--trace", options->trace_file, "write a Chrome Trace Event JSON file");
  app->add_flag("--json", options->json, "print one JSON object instead of text");
  return {app, [options] { return run(*options); }};
}

} // namespace marsokhod::apps
