// `marsokhod emulate [LEFT RIGHT] --platform FILE`: one navigation cycle as OCCAM processes on
// the emulated transputer network (docs/emulated-navigation.md).

#include "command.hpp"
#include "emulate_report.hpp"
#include "emulate_sweep.hpp"
#include "nav_outputs.hpp"
#include "option_checks.hpp"
#include "pair_inputs.hpp"
#include "platform_choice.hpp"
#include "trace_file.hpp"

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/occam_port/navigation/navigation_program.hpp"
#include "marsokhod/world/scene/rendered_site.hpp"

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

struct EmulateCli {
  std::vector<fs::path> pair;
  std::optional<std::uint64_t> seed;
  std::optional<int> size;
  std::string platform;
  std::optional<fs::path> placement;
  std::optional<std::uint64_t> external_kb;
  std::vector<std::uint64_t> sweep_kb;
  double occam_style = occam_port::kOccamStyleFactor;
  fs::path out = "emulate-out";
  std::optional<std::string> trace;
  PairOptions given;
  bool json = false;
};

/// The cycle's pair, rig and attitude, from files or rendered.
struct Pair {
  imaging::Image<std::uint8_t> left;
  imaging::Image<std::uint8_t> right;
  std::unique_ptr<imaging::StereoRig> rig;
  imaging::Attitude attitude;
  std::string description;
};

Pair files_pair(const EmulateCli& cli) {
  Pair pair;
  pair.left = read_grey(cli.pair[0]);
  imaging::Image<std::uint8_t> right = read_grey(cli.pair[1]);
  if (pair.left.width() != right.width() || pair.left.height() != right.height())
    throw CommandError(fmt::format("{} is {}x{} but {} is {}x{}; a stereo pair has one size",
                                   cli.pair[0].string(), pair.left.width(), pair.left.height(),
                                   cli.pair[1].string(), right.width(), right.height()));
  pair.rig = std::make_unique<imaging::StereoRig>(
      rig_for(cli.given.rig_file, cli.pair[0], pair.left.width(), pair.left.height()));
  pair.right = aligned_right(cli.given.calibration_file, std::move(right));
  pair.attitude = pair_attitude(cli.given);
  pair.description = cli.pair[0].string();
  return pair;
}

Pair rendered_pair(const EmulateCli& cli) {
  if (cli.given.rig_file || cli.given.scene_file || cli.given.calibration_file)
    throw UsageError("--rig, --scene and --calibration describe a given pair: name LEFT and RIGHT, "
                     "or leave them out to emulate a rendered scene");
  const std::uint64_t seed = cli.seed.value_or(1);
  world::SceneDescription scene = world::default_scene(seed, cli.size.value_or(128));
  if (!cli.json)
    fmt::print(stderr, "rendering world seed {} at {}x{}...\n", seed, scene.rig.width_px,
               scene.rig.height_px);
  world::RenderedFrame frame = world::render_site(scene);
  Pair pair{std::move(frame.images.left), std::move(frame.images.right),
            std::make_unique<imaging::StereoRig>(scene.rig), scene.placement.attitude,
            fmt::format("world seed {} at {}x{}", seed, scene.rig.width_px, scene.rig.height_px)};
  return pair;
}

Pair pair_for(const EmulateCli& cli) {
  if (cli.pair.empty())
    return rendered_pair(cli);
  if (cli.pair.size() != 2)
    throw UsageError("give both LEFT and RIGHT, or neither to emulate a rendered scene");
  if (cli.seed || cli.size)
    throw UsageError(
        "--seed and --size choose a rendered scene; they do not apply to a given pair");
  return files_pair(cli);
}

void print_summary(const occam_port::CycleEmulation& run, const EmulationSubject& subject,
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
              const occam_port::CycleInput& input, occam_port::CycleSetup setup,
              const EmulationSubject& subject) {
  if (cli.external_kb || cli.trace)
    throw UsageError("--sweep-external-kb runs one cycle per memory size: it takes neither "
                     "--external-kb nor --trace");
  std::vector<SweepPoint> points;
  try {
    points = sweep_external_memory(input, setup, cli.sweep_kb, cli.json);
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
  const emu::PlatformSpec platform = platform_for(cli.platform);
  const fs::path placement_file =
      cli.placement ? *cli.placement : occam_port::default_placement_file(platform);
  const occam_port::Placement placement =
      occam_port::load_placement(placement_file, platform, occam_port::navigation_program_shape());
  const Pair pair = pair_for(cli);
  imaging::prepare_output_folder(cli.out);

  occam_port::CycleInput input{pair.left, pair.right, pair.rig.get(), {}, {}};
  input.options.attitude = pair.attitude;
  occam_port::CycleSetup setup{&platform,       &placement, std::nullopt, nullptr,
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
      return occam_port::emulate_navigation_cycle(input, setup);
    } catch (const std::invalid_argument& error) {
      throw CommandError(fmt::format("{}: {}", pair.description, error.what()));
    }
  };
  const occam_port::CycleEmulation run =
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
    throw CommandError(memory_fault_message(*run.memory_fault));
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
      ->transform(integer_between<std::uint64_t>(0, 4194300));
  app->add_option("--sweep-external-kb", cli->sweep_kb,
                  "Run the cycle once for each of these external memory sizes, KB, comma-separated "
                  "(e.g. 64,128,256,512,1024,2048,4096), and write sweep.csv, sweep.json and "
                  "sweep.png")
      ->delimiter(',')
      ->transform(integer_between<std::uint64_t>(1, 4194300));
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
