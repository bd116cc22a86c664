// `marsokhod fault --platform FILE --inject SPEC ...`: one onboard cycle with injected faults,
// judged against the fault-free run and the world's ground truth (docs/faults.md).

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/trace_file.hpp"
#include "faults/fault_report.hpp"

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/eval/campaign/campaign_scene.hpp"
#include "marsokhod/eval/faults/fault_record.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/io/files/file_writer.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/overswitch/faults/split_mix.hpp"
#include "marsokhod/overswitch/protection/protection.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {
namespace {

namespace emu = emulator;

struct FaultCli {
  std::string platform;
  std::uint64_t seed = 1;
  std::vector<std::string> inject;
  bool edac = false;
  std::optional<double> scrub_s;
  bool link_checksums = false;
  bool terrain_check = false;
  std::optional<std::string> trace;
  std::optional<std::filesystem::path> out;
  bool json = false;
};

overswitch::Protection protection_of(const FaultCli& cli) {
  overswitch::Protection protection;
  protection.edac = cli.edac;
  if (cli.scrub_s)
    protection.scrub_period = static_cast<emu::Tick>(*cli.scrub_s * emu::kSecond);
  protection.link_checksums = cli.link_checksums;
  protection.terrain_check = cli.terrain_check;
  return protection;
}

std::vector<overswitch::Fault> parse_faults(const FaultCli& cli,
                                            const emu::PlatformSpec& platform) {
  std::vector<overswitch::Fault> faults;
  for (const std::string& spec : cli.inject) {
    overswitch::Fault fault = overswitch::parse_fault(spec);
    if (platform.find_node(fault.module) == nullptr)
      throw UsageError(fmt::format("--inject '{}': platform {} has no module {}", spec,
                                   platform.name, fault.module));
    const auto& processes = nav_program::navigation_program_shape().processes;
    if (!fault.stage.empty() &&
        std::find(processes.begin(), processes.end(), fault.stage) == processes.end())
      throw UsageError(fmt::format("--inject '{}': '{}' is no stage of the program (stages: {})",
                                   spec, fault.stage, fmt::join(processes, ", ")));
    // Each fault draws its address and bit from the seed and its place in the list alone.
    fault.draw = overswitch::SplitMix(cli.seed, faults.size()).next();
    faults.push_back(std::move(fault));
  }
  return faults;
}

int run_fault(const FaultCli& cli) {
  if (cli.scrub_s && !cli.edac)
    throw UsageError("--scrub needs --edac: scrubbing rewrites memory through the EDAC");
  const overswitch::Protection protection = protection_of(cli);
  const emu::PlatformSpec platform =
      overswitch::protected_platform(emu::load_named_platform(cli.platform), protection);
  overswitch::require_overswitch(platform, platform.source);
  const std::vector<overswitch::Fault> faults = parse_faults(cli, platform);
  const nav_program::Placement placement = nav_program::load_program_placement(platform);
  if (cli.out)
    imaging::prepare_output_folder(*cli.out);
  // A folder holds the run's trace too, so that `report` draws its timeline.
  const std::optional<std::string> trace =
      cli.trace ? cli.trace
                : (cli.out ? std::optional<std::string>((*cli.out / "trace.json").string())
                           : std::nullopt);
  if (!cli.json)
    fmt::print(stderr, "rendering world seed {} at 128x128...\n", cli.seed);
  const std::unique_ptr<eval::CampaignScene> scene =
      eval::supervised_scene(cli.seed, {}, platform, placement, protection);

  overswitch::FailoverSupervisor supervisor(platform, faults, protection);
  const auto faulty = [&](emu::TraceSink* sink) {
    return eval::emulate_supervised(*scene, platform, placement, supervisor, sink);
  };
  const nav_program::CycleEmulation run =
      trace ? with_trace_file(*trace, [&](emu::ChromeTraceWriter& w) { return faulty(&w); })
            : faulty(nullptr);
  const eval::FaultVerdict verdict = eval::judge_scene_run(*scene, run, supervisor);
  const auto json = fault_run_json(platform.name, cli.seed, verdict, supervisor, run);
  if (cli.out)
    io::write_file_atomically(*cli.out / "fault.json", json.dump(2) + "\n");
  if (!cli.json) {
    print_verdict(verdict, supervisor);
    if (cli.out)
      fmt::print("wrote fault.json and trace.json to {}\n", cli.out->string());
    return kSuccess;
  }
  fmt::print("{}\n", json.dump(2));
  return kSuccess;
}

} // namespace

Command make_fault_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "fault", "Run one onboard navigation cycle with injected faults under the overswitch's "
               "watchdogs and failover, and judge it against the fault-free run and the world's "
               "ground truth (docs/faults.md).");
  auto cli = std::make_shared<FaultCli>();
  app->add_option(
         "--platform", cli->platform,
         "Platform file with an [overswitch] table, or a shipped platform's name (onboard)")
      ->required();
  app->add_option("--seed", cli->seed, "World seed of the rendered scene")
      ->capture_default_str()
      ->transform(integer_between<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()));
  app->add_option("--inject", cli->inject,
                  "A fault, KIND:MODULE@WHEN[,KEY=VALUE...], repeatable. KIND: hang, power, leak "
                  "(memory exhaustion; bytes=N), seu (an upset; addr=#ADDR,bit=B or buffer=NAME "
                  "or over=allocated|memory), stuck (as seu, value=0|1), link, linkbit, ackloss "
                  "(on MODULE.linkN; dir=out|in|both, for=DURATION, byte=K, bit=B). WHEN: a time "
                  "from the cycle's start (1.05s, 250ms) or a stage and an offset "
                  "(matching+0.5s). Drawn addresses and bits come from --seed. See "
                  "docs/faults.md")
      ->required();
  app->add_flag("--edac", cli->edac,
                "SEC-DED EDAC on the modules' external memory (adds its wait states)");
  app->add_option("--scrub", cli->scrub_s,
                  "With --edac: scrub each module's external memory once per this many seconds")
      ->check(real_between(0.01, 86400.0));
  app->add_flag(
      "--link-checksums", cli->link_checksums,
      "A checksum after each link message; a bad one is reported and the cycle restarted");
  app->add_flag("--terrain-check", cli->terrain_check,
                "Word sums of the kept terrain's rows, checked each time zones and path rebuild "
                "one; a struck row halts its module");
  app->add_option("--trace", cli->trace, "Write a Chrome trace (Perfetto) of the faulty run here");
  app->add_option("--out", cli->out,
                  "Also write the verdict (fault.json) and, without --trace, the trace "
                  "(trace.json) into this folder, created if missing");
  app->add_flag("--json", cli->json, "Print a machine-readable verdict on stdout");
  return {app, [cli] {
            try {
              return run_fault(*cli);
            } catch (const overswitch::FaultSpecError& error) {
              throw UsageError(error.what());
            }
          }};
}

} // namespace marsokhod::apps
