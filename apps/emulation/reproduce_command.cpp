// `marsokhod reproduce`: the paper's timings (8 s stereo on one T805, 10 s on the PC card, 1.3 min
// onboard) as predictions of the model, its one fitted constant, the sensitivity to the
// parameters the paper does not give, and the onboard cycle against memory (docs/timing.md).

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "emulation/reproduce_report.hpp"
#include "emulation/sweep_report.hpp"

#include "marsokhod/emulator/platform/platform_limits.hpp"
#include "marsokhod/eval/common/errors.hpp"
#include "marsokhod/eval/terrain/terrain_evaluation.hpp"
#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/io/files/file_writer.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <map>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;

/// The sweep runs the onboard cycle once per size.
constexpr std::size_t kMaxReproduceSweepSizes = 64;

struct ReproduceCli {
  std::string seeds = "1..8";
  /// Checked by whole_number_list.
  std::string sweep_kb =
      "32,64,96,128,160,192,224,256,320,384,512,640,768,1024,1536,2048,3072,4096";
  fs::path out = "reproduce-out";
  bool json = false;
};

std::vector<std::uint64_t> seed_list(const std::string& text) {
  eval::SeedRange range;
  try {
    range = eval::parse_seed_range(text);
  } catch (const eval::OptionError& error) {
    throw UsageError(fmt::format("--seeds {}", error.what()));
  }
  if (range.last - range.first >= 64)
    throw UsageError(fmt::format("--seeds {}: at most 64 scenes", text));
  std::vector<std::uint64_t> seeds;
  for (std::uint64_t s = range.first; s <= range.last; ++s)
    seeds.push_back(s);
  return seeds;
}

// Where the rover and the PC card sit on the sweep's picture.
std::vector<imaging::LineChart::Mark> sweep_marks(const eval::Reproduction& r) {
  return {{static_cast<double>(r.onboard_external_kb),
           fmt::format("rover {} KB", r.onboard_external_kb)},
          {static_cast<double>(r.card_external_kb),
           fmt::format("PC card {} KB: {:.1f} s", r.card_external_kb, r.figures[1].model.mean)}};
}

std::map<std::string, fs::path> write_outputs(const ReproduceCli& cli,
                                              const eval::Reproduction& r) {
  std::map<std::string, fs::path> written{{"json", cli.out / "reproduce.json"},
                                          {"markdown", cli.out / "reproduce.md"},
                                          {"chart", cli.out / "reproduce.png"}};
  try {
    io::write_file_atomically(written["json"], nlohmann::ordered_json(r).dump(2) + '\n');
    io::write_file_atomically(written["markdown"], reproduction_markdown(r));
    imaging::write_image(written["chart"], reproduction_chart(r));
  } catch (const std::exception& error) {
    throw CommandError(error.what());
  }
  const EmulationSubject subject{
      "onboard", "onboard.toml", "placements/onboard.toml",
      fmt::format("world seeds {}..{} at 128x128, mean", r.seeds.front(), r.seeds.back())};
  written.merge(write_sweep(cli.out, r.sweep, subject, sweep_marks(r)));
  return written;
}

int run_reproduce(const ReproduceCli& cli) {
  imaging::prepare_output_folder(cli.out);
  const eval::Reproduction r = eval::reproduce(seed_list(cli.seeds), whole_numbers(cli.sweep_kb),
                                               [&cli](const std::string& text) {
                                                 if (!cli.json)
                                                   fmt::print(stderr, "{}\n", text);
                                               });
  const auto written = write_outputs(cli, r);
  if (cli.json) {
    nlohmann::ordered_json json = r;
    for (const auto& [key, path] : written)
      json["outputs"][key] = path.string();
    fmt::print("{}\n", json.dump(2));
    return kSuccess;
  }
  fmt::print("{}\nwrote reproduce.md, reproduce.json, reproduce.png and the sweep (csv, json, png) "
             "to {}\n",
             reproduction_markdown(r), cli.out.string());
  return kSuccess;
}

} // namespace

Command make_reproduce_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "reproduce", "The paper's timings from the model: 128x128 stereo on one T805 (8 s), the "
                   "cycle on the PC card (10 s) and onboard (1.3 min), with the model's fitted "
                   "constant, the sensitivity to what the paper does not give, and the onboard "
                   "cycle against memory.");
  auto cli = std::make_shared<ReproduceCli>();
  app->add_option("--seeds", cli->seeds, "World seeds A..B of the scenes the figures average")
      ->capture_default_str();
  app->add_option("--sweep-external-kb", cli->sweep_kb,
                  fmt::format("External memory sizes of the onboard sweep, KB, comma-separated "
                              "(default {})",
                              cli->sweep_kb))
      ->check(
          whole_number_list(1, emulator::platform_limits::kMaxExternalKb, kMaxReproduceSweepSizes));
  app->add_option("--out", cli->out, "Output folder (created if missing)")->capture_default_str();
  app->add_flag("--json", cli->json, "Print the reproduction as JSON on stdout");
  return {app, [cli] { return run_reproduce(*cli); }};
}

} // namespace marsokhod::apps
