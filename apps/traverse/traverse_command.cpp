// `marsokhod traverse`: one course driven cycle after cycle, its map and records.
#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "navigation/nav_outputs.hpp"
#include "traverse/course_options.hpp"

#include "marsokhod/eval/traverse/traverse.hpp"
#include "marsokhod/eval/traverse/traverse_json.hpp"
#include "marsokhod/eval/traverse/traverse_map.hpp"
#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/io/files/file_writer.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace marsokhod::apps {
namespace {

struct TraverseCli {
  eval::TraverseSettings settings;
  std::string out;
  bool json = false;
};

std::string cycle_line(const eval::TraverseCycle& c, const eval::TraverseResult& r) {
  const Eigen::Vector2d at =
      c.track.empty() ? Eigen::Vector2d(c.start.x, c.start.y) : c.track.back();
  std::string line = fmt::format(
      "cycle {:3}  {:16} {:>9}  drove {:5.2f} m  at ({:6.2f}, {:6.2f})  goal {:5.1f} m away",
      c.index, nav::to_string(c.state), c.found ? "path" : "no path", c.driven_m, at.x(), at.y(),
      (at - r.goal).norm());
  for (const std::string& event : c.events)
    line += "  [" + event + "]";
  return line;
}

void write_outputs(const std::filesystem::path& folder, const world::Terrain& terrain,
                   const eval::TraverseResult& result) {
  std::string lines;
  for (const eval::TraverseCycle& cycle : result.cycles)
    lines += eval::cycle_json(cycle).dump() + "\n";
  io::write_file_atomically(folder / "cycles.jsonl", lines);
  io::write_file_atomically(folder / "traverse.json", eval::traverse_json(result).dump(2) + "\n");
  imaging::write_image(folder / "map.png", eval::traverse_map(terrain, result).view());
}

void print_summary(const eval::TraverseResult& r, const std::string& out) {
  fmt::print("outcome {}: {:.1f} m driven in {} cycles, {:.1f} m from the goal; path efficiency "
             "{:.2f}; {} emergency stops, {} hand-overs, {} unsafe events; mission {:.0f} s "
             "(driving {:.0f} s, navigating {:.0f} s on {})\n",
             eval::to_string(r.outcome), r.distance_m, r.cycles.size(), r.goal_left_m,
             r.path_efficiency(), r.emergency_stops, r.hand_overs, r.unsafe_events.size(),
             r.mission_seconds(), r.driving_seconds, r.compute_seconds, r.settings.platform);
  for (const eval::UnsafeEvent& e : r.unsafe_events)
    fmt::print("unsafe at ({:.2f}, {:.2f}): {}\n", e.x_m, e.y_m, e.why);
  for (const eval::TraverseFault& f : r.faults)
    fmt::print("fault in cycle {}: {}: {}, {} failover{}, {:.1f} s lost\n", f.cycle, f.fault,
               f.outcome, f.failovers, f.failovers == 1 ? "" : "s", f.time_lost_s);
  if (!out.empty())
    fmt::print("results in {}/ (map.png, traverse.json, cycles.jsonl, views/cycle-NNN.png)\n", out);
}

void add_options(CLI::App* app, TraverseCli& cli) {
  eval::TraverseSettings& s = cli.settings;
  app->add_option("--seed", s.seed, "Seed of the site and the sensor noise")
      ->transform(integer_between<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()))
      ->capture_default_str();
  app->add_option("--rocks", s.rocks, "Rock cover k (Golombek-Rapp cumulative fractional area)")
      ->check(real_between(0.0, 0.5))
      ->capture_default_str();
  add_course_options(app, s);
  app->add_option("--size", s.image_px,
                  "Stereo image width and height, pixels (onboard: 128 unless given, the size "
                  "its two 256 KB modules hold)")
      ->transform(integer_between(64, 512))
      ->capture_default_str();
  app->add_option("--max-cycles", s.max_cycles,
                  "Cycles before the traverse times out (0: four per 10 m of course, plus 20)")
      ->transform(integer_between(0, 10000))
      ->capture_default_str();
  app->add_option("--out", cli.out,
                  "Output folder (created if missing): map.png, traverse.json, cycles.jsonl, and "
                  "views/cycle-NNN.png (each cycle's left image with its path)");
  app->add_flag("--json", cli.json, "Print traverse.json on stdout instead of the summary");
}

} // namespace

Command make_traverse_command(CLI::App& parent) {
  auto cli = std::make_shared<TraverseCli>();
  CLI::App* app = parent.add_subcommand(
      "traverse", "Drive the rover across a synthetic site toward a goal, cycle after cycle, with "
                  "the paper's motion scheme, judged on the true ground.");
  app->footer("The site is a strip goal-m + 20 m long and 30 m wide; the rover starts at its west "
              "end facing east, "
              "the goal lies goal-m east. Each cycle renders the pair from the rover's pose, "
              "navigates natively toward the goal, and drives the commands on the true ground "
              "with the inclinometer read every 0.25 m (emergency stop over 20 deg). Outcomes: "
              "success (within 1.5 m of the goal), hand_over (a full turn found no path), unsafe "
              "(the footprint on a true obstacle, or a tilt over 25 deg), timeout. See "
              "docs/traverse.md.");
  add_options(app, *cli);
  return {app, [cli, app] {
            if (cli->settings.platform == "onboard" && app->count("--size") == 0)
              cli->settings.image_px = kOnboardImagePx;
            check_course_faults(cli->settings);
            const bool live = !cli->json && ::isatty(STDERR_FILENO) != 0;
            // A folder that cannot be made is refused before the drive, not after it.
            if (!cli->out.empty())
              imaging::prepare_output_folder(cli->out);
            const world::Terrain terrain =
                world::Terrain::generate(eval::traverse_site(cli->settings));
            // Each cycle's view beside the records, when there is a folder for them.
            eval::CycleView view;
            if (!cli->out.empty()) {
              const std::filesystem::path views = std::filesystem::path(cli->out) / "views";
              imaging::prepare_output_folder(views);
              view = [views](int cycle, const imaging::Image<std::uint8_t>& left,
                             const nav::NavigationResult& navigation) {
                imaging::write_image(views / fmt::format("cycle-{:03}.png", cycle),
                                     path_overlay(left, navigation).view());
              };
            }
            const eval::TraverseResult result = eval::run_traverse(
                terrain, cli->settings,
                [live](const eval::TraverseCycle& cycle, const eval::TraverseResult& partial) {
                  if (live)
                    fmt::print(stderr, "{}\n", cycle_line(cycle, partial));
                },
                view);
            if (!cli->out.empty())
              write_outputs(cli->out, terrain, result);
            if (cli->json)
              fmt::print("{}\n", eval::traverse_json(result).dump(2));
            else
              print_summary(result, cli->out);
            return static_cast<int>(kSuccess);
          }};
}

} // namespace marsokhod::apps
