// `marsokhod emulate [LEFT RIGHT] --platform FILE`: one navigation cycle as OCCAM processes on
// the emulated transputer network (docs/emulated-navigation.md).

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/trace_file.hpp"
#include "emulation/cycle_pair.hpp"
#include "emulation/emulate_report.hpp"
#include "emulation/sweep_report.hpp"
#include "navigation/nav_outputs.hpp"

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/emulator/platform/platform_limits.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;
namespace emu = emulator;

/// A sweep runs one whole cycle per size.
constexpr std::size_t kMaxSweepSizes = 64;

struct EmulateCli {
  std::vector<fs::path> pair;
  std::optional<std::uint64_t> seed;
  std::optional<int> size;
  std::string platform;
  std::optional<fs::path> placement;
  std::optional<std::uint64_t> external_kb;
  std::string sweep_kb; ///< checked by whole_number_list
  double occam_style = nav_program::kOccamStyleFactor;
  fs::path out = "emulate-out";
  std::optional<std::string> trace;
  PairOptions given;
  bool json = false;
};

void print_summary(const nav_program::CycleEmulation& run, const EmulationSubject& subject,
                   double host_seconds) {
  fmt::print("marsokhod emulate: {} on {} ({}), placement {}\n", subject.pair, subject.platform,
             subject.platform_file, subject.placement_file);
  fmt::print("one cycle: {:.3f} s emulated, {:.3f} s of host time\n", emu::to_seconds(run.emulated),
             host_seconds);
  if (run.result)
    fmt::print("{}\n", run.result->found() ? "path found" : "no path: " + run.result->reason());
  fmt::print("{}", emulation_tables(run));
}

// The external memory of the platform's first powered node, KB, as shipped.
std::uint64_t shipped_external_kb(const emu::PlatformSpec& platform) {
  for (const emu::NodeSpec& node : platform.nodes)
    if (node.powered)
      return node.memory.external_bytes / 1024;
  return 0;
}

int run_sweep(const EmulateCli& cli, const emu::PlatformSpec& platform,
              const nav_program::CycleInput& input, nav_program::CycleSetup setup,
              const EmulationSubject& subject) {
  if (cli.external_kb || cli.trace)
    throw UsageError("--sweep-external-kb runs one cycle per memory size: it takes neither "
                     "--external-kb nor --trace");
  std::vector<eval::SweepPoint> points;
  const std::vector<std::uint64_t> sizes_kb = whole_numbers(cli.sweep_kb);
  const auto progress = [&cli, &sizes_kb](const eval::SweepPoint& point, std::size_t done) {
    if (!cli.json)
      fmt::print(stderr, "sweep {}/{}: {} KB: {}\n", done, sizes_kb.size(), point.external_kb,
                 point.memory_fault ? nav_program::describe(*point.memory_fault)
                                    : fmt::format("{:.3f} s", point.emulated_seconds));
  };
  try {
    points = eval::sweep_external_memory(input, setup, sizes_kb, progress);
  } catch (const std::invalid_argument& error) {
    throw CommandError(fmt::format("{}: {}", subject.pair, error.what()));
  }
  std::vector<imaging::LineChart::Mark> marks;
  if (const std::uint64_t kb = shipped_external_kb(platform); kb > 0)
    marks.push_back({static_cast<double>(kb), fmt::format("{} as shipped", subject.platform)});
  const auto written = write_sweep(cli.out, points, subject, marks);
  if (cli.json) {
    nlohmann::ordered_json json = sweep_json(points, subject);
    for (const auto& [key, path] : written)
      json["outputs"][key] = path.string();
    fmt::print("{}\n", json.dump(2));
    return kSuccess;
  }
  fmt::print("marsokhod emulate: {} on {} ({}), placement {}\n", subject.pair, subject.platform,
             subject.platform_file, subject.placement_file);
  fmt::print("{}wrote sweep.csv, sweep.json and sweep.png to {}\n", sweep_table(points),
             cli.out.string());
  return kSuccess;
}

int run_emulate(const EmulateCli& cli) {
  const emu::PlatformSpec platform = emu::load_named_platform(cli.platform);
  const fs::path placement_file =
      cli.placement ? *cli.placement : nav_program::default_placement_file(platform);
  const nav_program::Placement placement = nav_program::load_placement(
      placement_file, platform, nav_program::navigation_program_shape());
  const CyclePair pair = cycle_pair({cli.pair, cli.seed, cli.size, cli.given}, cli.json);
  imaging::prepare_output_folder(cli.out);

  nav_program::CycleInput input{pair.left, pair.right, pair.rig.get(), {}, {}};
  input.options.attitude = pair.attitude;
  nav_program::CycleSetup setup{&platform,       &placement, std::nullopt, nullptr,
                                cli.occam_style, nullptr,    std::nullopt};
  if (!cli.sweep_kb.empty())
    return run_sweep(cli, platform, input, setup,
                     EmulationSubject{platform.name, platform.source, placement_file.string(),
                                      pair.description});
  if (cli.external_kb)
    setup.external_bytes = static_cast<std::size_t>(*cli.external_kb) * 1024;
  const auto start = std::chrono::steady_clock::now();
  const auto emulate = [&](emu::TraceSink* sink) {
    setup.trace = sink;
    try {
      return nav_program::emulate_navigation_cycle(input, setup);
    } catch (const std::invalid_argument& error) {
      throw CommandError(fmt::format("{}: {}", pair.description, error.what()));
    }
  };
  const nav_program::CycleEmulation run =
      cli.trace
          ? with_trace_file(*cli.trace, [&](emu::ChromeTraceWriter& w) { return emulate(&w); })
          : emulate(nullptr);
  const double host_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::map<std::string, fs::path> outputs;
  if (run.result)
    outputs =
        write_navigation_outputs(cli.out, pair.left, run.result->stereo.disparity, *run.result);
  const EmulationSubject subject{platform.name, platform.source, placement_file.string(),
                                 pair.description};
  if (cli.json)
    fmt::print("{}\n", emulation_json(run, subject, host_seconds, outputs).dump(2));
  else
    print_summary(run, subject, host_seconds);
  if (run.memory_fault)
    throw CommandError(nav_program::describe(*run.memory_fault));
  if (!cli.json)
    fmt::print("wrote disparity, range, elevation, zones, path overlay and path.json to {}\n",
               cli.out.string());
  return kSuccess;
}

} // namespace

Command make_emulate_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "emulate", "Run one navigation cycle as OCCAM processes on an emulated T805 network: image "
                 "acquisition to drive commands, with per-stage timing, memory and link figures.");
  auto cli = std::make_shared<EmulateCli>();
  app->add_option("LEFT RIGHT", cli->pair,
                  "A stereo pair (left is the reference); without one, a rendered world scene")
      ->expected(0, 2);
  app->add_option("--seed", cli->seed, "World seed of the rendered scene (default 1)")
      ->transform(integer_between<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()));
  app->add_option("--size", cli->size, "Side of the rendered scene's images (default 128)")
      ->transform(integer_one_of({128, 256}));
  app->add_option("--platform", cli->platform,
                  "Platform file, or a shipped platform's name (onboard, pc-card)")
      ->required();
  app->add_option("--placement", cli->placement,
                  "Placement file (default: placements/<platform>.toml beside the platform file)");
  app->add_option("--external-kb", cli->external_kb,
                  "Replace every node's external memory by this many KB (what-if)")
      ->transform(integer_between<std::uint64_t>(0, emu::platform_limits::kMaxExternalKb));
  app->add_option("--sweep-external-kb", cli->sweep_kb,
                  "Run the cycle once for each of these external memory sizes, KB, comma-separated "
                  "(e.g. 64,128,256,512,1024,2048,4096), and write sweep.csv, sweep.json and "
                  "sweep.png")
      ->check(whole_number_list(1, emu::platform_limits::kMaxExternalKb, kMaxSweepSizes));
  app->add_option("--occam-style", cli->occam_style,
                  "Cycles of the program's occam per unit of work over the cost table's (the "
                  "model's fitted constant, docs/timing.md; 1 is the table's careful style)")
      ->capture_default_str()
      ->check(real_between(0.01, 100.0));
  app->add_option("--out", cli->out, "Output folder (created if missing)")->capture_default_str();
  app->add_option("--trace", cli->trace, "Write a Chrome trace (Perfetto) of the cycle here");
  add_pair_options(*app, cli->given);
  app->add_flag("--json", cli->json, "Print a machine-readable summary on stdout");
  return {app, [cli] { return run_emulate(*cli); }};
}

} // namespace marsokhod::apps
