// `marsokhod eval traverse`: a sweep of courses over seeds and rock covers, its trials,
// figures and charts.
#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress_bar.hpp"
#include "navigation/seed_option.hpp"
#include "traverse/course_options.hpp"

#include "marsokhod/eval/terrain/terrain_evaluation.hpp"
#include "marsokhod/eval/traverse/traverse_sweep.hpp"
#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/imaging/pictures/bar_chart.hpp"
#include "marsokhod/io/files/file_writer.hpp"
#include "marsokhod/io/numbers/checked_number.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {
namespace {

struct SweepCli {
  std::string seeds = "1..10";
  std::string rocks = "0,0.05,0.10";
  std::string out = "out/eval-traverse";
  eval::TraverseSweep sweep;
  std::optional<std::uint64_t> replay;
  bool json = false;
};

constexpr std::size_t kMaxRockCovers = 32;

std::vector<double> rock_list(const std::string& text) {
  std::vector<double> list;
  for (const std::string& item : comma_items(text)) {
    const std::optional<double> k = io::parse_finite(item);
    if (!k || *k < 0.0 || *k > 0.5)
      throw UsageError(fmt::format("--rocks '{}': '{}' is not a rock cover from 0 to 0.5 (write a "
                                   "comma-separated list, e.g. 0,0.05,0.1)",
                                   text, item));
    list.push_back(*k);
    if (list.size() > kMaxRockCovers)
      throw UsageError(fmt::format("--rocks '{}': at most {} covers", text, kMaxRockCovers));
  }
  return list;
}

void write_chart(const std::filesystem::path& file, const std::vector<eval::RockFigures>& f) {
  imaging::BarChart chart;
  chart.title = "Traverses reaching the goal, by rock cover k";
  chart.y_label = "success %";
  chart.series = {"success", "95% low", "95% high"};
  for (const eval::RockFigures& r : f)
    chart.groups.push_back(
        {fmt::format("k={:g}", r.rocks),
         {100.0 * r.success_rate, 100.0 * r.success_ci95.low, 100.0 * r.success_ci95.high}});
  imaging::write_image(file, imaging::draw_bar_chart(chart).view());
}

void print_table(const std::vector<eval::RockFigures>& figures) {
  fmt::print("{:>6} {:>6} {:>8} {:>15} {:>6} {:>7} {:>9} {:>12} {:>10}\n", "k", "trials", "success",
             "95% interval", "SPL", "unsafe", "stops/100m", "hand-overs/100m", "m/h");
  for (const eval::RockFigures& f : figures)
    fmt::print("{:>6g} {:>6} {:>7.1f}% {:>6.1f}-{:>5.1f}% {:>6.3f} {:>7} {:>9.2f} {:>12.2f} "
               "{:>10.1f}\n",
               f.rocks, f.trials, 100.0 * f.success_rate, 100.0 * f.success_ci95.low,
               100.0 * f.success_ci95.high, f.spl, f.unsafe_trials, f.emergency_stops_per_100m,
               f.hand_overs_per_100m, f.metres_per_hour);
}

int run(SweepCli& cli) {
  const eval::SeedRange seeds = seed_range_option(cli.seeds);
  cli.sweep.first_seed = seeds.first;
  cli.sweep.last_seed = seeds.last;
  cli.sweep.rocks = rock_list(cli.rocks);
  check_course_faults(cli.sweep.course);
  if (cli.replay) {
    if (*cli.replay >= eval::sweep_trials(cli.sweep))
      throw UsageError(fmt::format("--replay {}: the sweep has trials 0..{}", *cli.replay,
                                   eval::sweep_trials(cli.sweep) - 1));
    fmt::print("{}\n", eval::sweep_trial_line(cli.sweep, *cli.replay));
    return kSuccess;
  }
  const std::filesystem::path out(cli.out);
  imaging::prepare_output_folder(out);
  imaging::prepare_output_folder(out / "failed");
  cli.sweep.failed_maps = out / "failed";
  ProgressBar bar(eval::sweep_trials(cli.sweep), !cli.json, "trials");
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::string> lines =
      eval::run_sweep(cli.sweep, [&bar](std::uint64_t done) { bar.update(done); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::string jsonl;
  for (const std::string& line : lines)
    jsonl += line + "\n";
  io::write_file_atomically(out / "trials.jsonl", jsonl);
  const std::vector<eval::RockFigures> figures = eval::sweep_figures(cli.sweep, lines);
  nlohmann::ordered_json summary = eval::sweep_json(figures);
  summary["trials_per_minute"] = seconds > 0.0 ? 60.0 * lines.size() / seconds : 0.0;
  io::write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  write_chart(out / "success.png", figures);
  if (cli.json) {
    fmt::print("{}\n", summary.dump(2));
    return kSuccess;
  }
  print_table(figures);
  fmt::print("{} trials, {:.1f} a minute; results in {}/ (trials.jsonl, summary.json, "
             "success.png, failed/)\n",
             lines.size(), summary["trials_per_minute"].get<double>(), cli.out);
  return kSuccess;
}

} // namespace

Command add_traverse_evaluation(CLI::App& parent) {
  auto cli = std::make_shared<SweepCli>();
  CLI::App* app = parent.add_subcommand(
      "traverse", "Drive many courses (every seed at every rock cover) and score how often the "
                  "rover reaches the goal.");
  app->footer(
      "Each trial is `marsokhod traverse` with that seed and rock cover (docs/traverse.md). "
      "Per rock cover: outcomes, success rate with its 95 % Wilson interval, SPL (success "
      "weighted by path efficiency), unsafe trials, emergency stops and hand-overs per "
      "100 m, metres per hour of mission and of driving. trials.jsonl is the same for any "
      "--jobs.");
  app->add_option("--seeds", cli->seeds, "Site seeds A..B (inclusive) or one seed")
      ->capture_default_str();
  app->add_option("--rocks", cli->rocks, "Rock covers k, comma-separated, each 0..0.5")
      ->capture_default_str();
  add_course_options(app, cli->sweep.course);
  app->add_option("--size", cli->sweep.course.image_px,
                  "Stereo image width and height, pixels (onboard: 128 unless given, the size "
                  "its two 256 KB modules hold)")
      ->transform(integer_between(64, 512))
      ->capture_default_str();
  app->add_option("--jobs", cli->sweep.jobs, "Worker processes")
      ->transform(integer_between(1, 64))
      ->capture_default_str();
  app->add_option("--out", cli->out, "Output folder (created if missing)")->capture_default_str();
  app->add_option("--replay", cli->replay,
                  "Run trial K alone and print its trials.jsonl line (nothing is written)")
      ->transform(integer_between<std::uint64_t>(0, 1000000));
  app->add_flag("--json", cli->json, "Print summary.json instead of the table");
  return {app, [cli, app] {
            if (cli->sweep.course.platform == "onboard" && app->count("--size") == 0)
              cli->sweep.course.image_px = kOnboardImagePx;
            return run(*cli);
          }};
}

} // namespace marsokhod::apps
