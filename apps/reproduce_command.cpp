// `marsokhod reproduce`: the paper's timings (8 s stereo on one T805, 10 s on the PC card, 1.3 min
// onboard) as predictions of the model, its one fitted constant, the sensitivity to the
// parameters the paper does not give, and the onboard cycle against memory (docs/timing.md).

#include "command.hpp"
#include "option_checks.hpp"
#include "reproduce_report.hpp"

#include "marsokhod/eval/common/errors.hpp"
#include "marsokhod/eval/terrain/terrain_evaluation.hpp"
#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/io/files/file_writer.hpp"
#include "marsokhod/occam_port/navigation/work_costs.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <map>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;

struct ReproduceCli {
  std::string seeds = "1..8";
  std::vector<std::uint64_t> sweep_kb{32,  64,  96,  128, 160,  192,  224,  256,  320,
                                      384, 512, 640, 768, 1024, 1536, 2048, 3072, 4096};
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

void note(const ReproduceCli& cli, const std::string& text) {
  if (!cli.json)
    fmt::print(stderr, "{}\n", text);
}

Reproduction reproduce(const ReproduceCli& cli) {
  Reproduction r;
  r.seeds = seed_list(cli.seeds);
  note(cli, fmt::format("rendering {} world scenes at 128x128...", r.seeds.size()));
  const TimingModel model(r.seeds);
  r.card_external_kb = model.card().nodes.front().memory.external_bytes / 1024;
  r.onboard_external_kb = model.onboard().nodes.front().memory.external_bytes / 1024;
  const double style = occam_port::kOccamStyleFactor;
  note(cli, "fitting the occam style factor on the stereo figure...");
  const std::string fitted_on = "stereo 128x128 on one T805 (the PC card), 8 s";
  r.fitted.push_back(
      {"occam_style_factor", style, fit_occam_style(model, kPaperStereoSeconds), fitted_on});
  note(cli, "the three figures...");
  const ModelFigures f = model.figures(model.card(), model.onboard(), style);
  r.figures = {{"stereo 128x128 on one T805", "the stereo reconstruction algorithm takes 8 sec",
                kPaperStereoSeconds, f.stereo, true},
               {"whole cycle on the PC card",
                "the overall processing time on such card equals 10 sec", kPaperCardCycleSeconds,
                f.card_cycle, false},
               {"whole cycle onboard", "versus 1.3 min in onboard processing",
                kPaperOnboardCycleSeconds, f.onboard_cycle, false}};
  note(cli, "sensitivity to the parameters the paper does not give...");
  r.sensitivity = sensitivity(model, style, f);
  r.sweep = model.onboard_sweep(cli.sweep_kb, style, [&](std::size_t done) {
    note(cli, fmt::format("sweep {}/{}: {} KB", done, cli.sweep_kb.size(), cli.sweep_kb[done - 1]));
  });
  return r;
}

// Where the rover and the PC card sit on the sweep's picture.
std::vector<imaging::LineChart::Mark> sweep_marks(const Reproduction& r) {
  return {{static_cast<double>(r.onboard_external_kb),
           fmt::format("rover {} KB", r.onboard_external_kb)},
          {static_cast<double>(r.card_external_kb),
           fmt::format("PC card {} KB: {:.1f} s", r.card_external_kb, r.figures[1].model.mean)}};
}

std::map<std::string, fs::path> write_outputs(const ReproduceCli& cli, const Reproduction& r) {
  std::map<std::string, fs::path> written{{"json", cli.out / "reproduce.json"},
                                          {"markdown", cli.out / "reproduce.md"},
                                          {"chart", cli.out / "reproduce.png"}};
  try {
    io::write_file_atomically(written["json"], reproduction_json(r).dump(2) + '\n');
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
  const Reproduction r = reproduce(cli);
  const auto written = write_outputs(cli, r);
  if (cli.json) {
    nlohmann::ordered_json json = reproduction_json(r);
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
                              fmt::join(cli->sweep_kb, ",")))
      ->delimiter(',')
      ->transform(integer_between<std::uint64_t>(1, 4194300));
  app->add_option("--out", cli->out, "Output folder (created if missing)")->capture_default_str();
  app->add_flag("--json", cli->json, "Print the reproduction as JSON on stdout");
  return {app, [cli] { return run_reproduce(*cli); }};
}

} // namespace marsokhod::apps
