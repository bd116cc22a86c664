// `marsokhod campaign FILE.toml`: fault-injection runs drawn from a campaign file, judged one by
// one and summed up (docs/faults.md, "Campaigns").

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress_bar.hpp"
#include "cli/trace_file.hpp"
#include "faults/campaign_report.hpp"
#include "navigation/seed_option.hpp"

#include "marsokhod/eval/campaign/campaign_platform.hpp"
#include "marsokhod/eval/campaign/campaign_runs.hpp"
#include "marsokhod/eval/campaign/campaign_summary.hpp"
#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/io/files/file_writer.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;

struct CampaignCli {
  fs::path file;
  std::optional<std::uint64_t> runs;
  std::optional<std::string> seeds;
  int jobs = 1;
  fs::path out = "campaign-out";
  std::optional<std::uint64_t> replay;
  bool no_skip = false;
  bool json = false;
};

/// A campaign's runs each render their world seeds' scenes: a thousand is plenty.
constexpr std::uint64_t kMaxCampaignSeeds = 1000;

/// "A..B" (inclusive) or "A" as the list A, A+1, ..., B, read as every evaluation reads --seeds.
std::vector<std::uint64_t> seed_range(const std::string& text) {
  const eval::SeedRange range = seed_range_option(text, kMaxCampaignSeeds);
  std::vector<std::uint64_t> seeds;
  for (std::uint64_t offset = 0; offset <= range.last - range.first; ++offset)
    seeds.push_back(range.first + offset);
  return seeds;
}

int replay(const CampaignCli& cli, const eval::CampaignRunner& runner, std::uint64_t k) {
  imaging::prepare_output_folder(cli.out);
  const fs::path trace = cli.out / fmt::format("run-{}.trace.json", k);
  const std::string record = with_trace_file(trace.string(), [&](emulator::ChromeTraceWriter& w) {
    return eval::run_record_line(runner.run(k, &w));
  });
  const fs::path file = cli.out / fmt::format("run-{}.json", k);
  io::write_file_atomically(file, record + "\n");
  fmt::print("{}\n", record);
  if (!cli.json)
    fmt::print(stderr, "run {} replayed: its record in {}, its trace in {}\n", k, file.string(),
               trace.string());
  return kSuccess;
}

/// summary.json and .md, the charts; returns the summary and the charts' names.
std::pair<nlohmann::ordered_json, std::string>
write_summary(const CampaignCli& cli, const overswitch::CampaignSpec& spec,
              const eval::CampaignFacts& facts, const eval::CampaignTally& t, double per_minute) {
  const nlohmann::ordered_json summary = eval::summary_json(spec, facts, t, per_minute);
  io::write_file_atomically(cli.out / "summary.json", summary.dump(2) + "\n");
  io::write_file_atomically(cli.out / "summary.md", summary_markdown(spec, facts, t, per_minute));
  imaging::write_image(cli.out / "outcomes.png", outcomes_chart(t));
  imaging::write_image(cli.out / "latency.png", latency_chart(t));
  if (t.by_region.empty())
    return {summary, "outcomes.png and latency.png"};
  imaging::write_image(cli.out / "regions.png",
                       memory_chart(t.by_region, "Outcomes of memory faults by region"));
  imaging::write_image(cli.out / "buffers.png",
                       memory_chart(t.by_buffer, "Outcomes of memory faults by buffer"));
  return {summary, "outcomes.png, regions.png, buffers.png and latency.png"};
}

int run(const CampaignCli& cli) {
  overswitch::CampaignSpec spec = overswitch::load_campaign(cli.file);
  if (cli.seeds)
    spec.world_seeds = seed_range(*cli.seeds);
  const emulator::PlatformSpec platform = eval::campaign_platform(spec);
  const nav_program::Placement placement = nav_program::load_program_placement(platform);
  if (!cli.json)
    fmt::print(stderr, "campaign {}: rendering {} scenes and their fault-free runs...\n", spec.name,
               spec.world_seeds.size());
  const eval::CampaignRunner runner(spec, platform, placement, {});
  if (cli.replay)
    return replay(cli, runner, *cli.replay);
  imaging::prepare_output_folder(cli.out);
  const eval::RunPlan plan{cli.runs.value_or(spec.runs), cli.jobs, !cli.no_skip, spec.ci_width};
  ProgressBar bar(plan.runs, !cli.json);
  const auto start = std::chrono::steady_clock::now();
  const eval::CampaignRuns runs =
      eval::make_runs(runner, plan, [&bar](std::uint64_t done) { bar.update(done); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double per_minute =
      seconds > 0 ? static_cast<double>(runs.lines.size()) * 60.0 / seconds : 0;

  std::string jsonl;
  for (const std::string& line : runs.lines)
    jsonl += line + "\n";
  io::write_file_atomically(cli.out / "runs.jsonl", jsonl);
  eval::CampaignFacts facts = runner.facts();
  if (plan.skip)
    for (std::uint64_t k = 0; k < runs.lines.size(); ++k)
      facts.skipped_runs += runner.skippable(k) ? 1 : 0;
  const eval::CampaignTally t = eval::tally(runs.records);
  const auto [summary, charts] = write_summary(cli, spec, facts, t, per_minute);
  if (cli.json) {
    fmt::print("{}\n", summary.dump(2));
    return kSuccess;
  }
  fmt::print("{}", summary_markdown(spec, facts, t, per_minute));
  fmt::print("\nwrote runs.jsonl, summary.json, summary.md, {} to {}\n", charts, cli.out.string());
  return kSuccess;
}

} // namespace

Command make_campaign_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "campaign", "Run a fault-injection campaign: many onboard cycles, each with one fault drawn "
                  "from the campaign file, judged against the fault-free run and the ground "
                  "truth, and summed up (docs/faults.md).");
  auto cli = std::make_shared<CampaignCli>();
  app->add_option("FILE", cli->file, "Campaign file (campaigns/*.toml)")->required();
  app->add_option("--runs", cli->runs, "Runs to make (default: the file's [stop] runs)")
      ->transform(integer_between<std::uint64_t>(1, overswitch::kMaxCampaignRuns));
  app->add_option("--seeds", cli->seeds,
                  "World seeds A..B to draw the scenarios over, instead of the file's");
  app->add_option("--jobs", cli->jobs, "Worker processes")
      ->capture_default_str()
      ->transform(integer_between<int>(1, 256));
  app->add_option("--out", cli->out, "Output folder (created if missing)")->capture_default_str();
  app->add_option("--replay", cli->replay,
                  "Repeat run K alone: its record (as in runs.jsonl) and its trace into the output "
                  "folder")
      ->transform(integer_between<std::uint64_t>(0, overswitch::kMaxCampaignRuns - 1));
  app->add_flag("--no-skip", cli->no_skip,
                "Emulate every run, also those whose fault cannot change them (an upset in free "
                "memory or corrected by the EDAC), which are otherwise judged from the fault-free "
                "run with the same record");
  app->add_flag("--json", cli->json, "Print the summary (or the replayed record) as JSON");
  return {app, [cli] { return run(*cli); }};
}

} // namespace marsokhod::apps
