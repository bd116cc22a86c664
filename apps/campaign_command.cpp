// `marsokhod campaign FILE.toml`: fault-injection runs drawn from a campaign file, judged one by
// one and summed up (docs/faults.md, "Campaigns").

#include "campaign_jobs.hpp"
#include "campaign_runner.hpp"
#include "campaign_summary.hpp"
#include "command.hpp"
#include "option_checks.hpp"
#include "platform_choice.hpp"
#include "trace_file.hpp"

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/io/files/file_writer.hpp"
#include "marsokhod/occam_port/navigation/navigation_program.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <unistd.h>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

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

/// "A..B" (inclusive) as the list A, A+1, ..., B.
std::vector<std::uint64_t> seed_range(const std::string& text) {
  const std::size_t dots = text.find("..");
  const auto number = [&text](const std::string& part) {
    if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos ||
        part.size() > 18)
      throw UsageError(fmt::format("--seeds '{}': write A..B with whole numbers, e.g. 1..8", text));
    return std::stoull(part);
  };
  if (dots == std::string::npos)
    throw UsageError(fmt::format("--seeds '{}': write A..B with whole numbers, e.g. 1..8", text));
  const std::uint64_t first = number(text.substr(0, dots));
  const std::uint64_t last = number(text.substr(dots + 2));
  if (last < first || last - first >= 1000)
    throw UsageError(fmt::format("--seeds '{}': B must be at least A and at most A + 999", text));
  std::vector<std::uint64_t> seeds;
  for (std::uint64_t s = first; s <= last; ++s)
    seeds.push_back(s);
  return seeds;
}

// A platform named by a path is relative to the campaign file's folder.
emulator::PlatformSpec campaign_platform(const overswitch::CampaignSpec& spec) {
  const bool is_path =
      spec.platform.find('/') != std::string::npos || spec.platform.ends_with(".toml");
  const std::string name =
      is_path ? (fs::path(spec.source).parent_path() / spec.platform).string() : spec.platform;
  emulator::PlatformSpec platform = platform_for(name);
  require_overswitch(platform, spec.source);
  return platform;
}

/// Progress on a terminal: runs done, speed and time left, redrawn at most 5 times a second.
class ProgressBar {
public:
  ProgressBar(std::uint64_t total, bool shown)
      : total_(total), shown_(shown && ::isatty(STDERR_FILENO) != 0), start_(Clock::now()) {}

  void update(std::uint64_t done) {
    if (!shown_)
      return;
    const Clock::time_point now = Clock::now();
    if (done < total_ && now - last_ < std::chrono::milliseconds(200))
      return;
    last_ = now;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0.0;
    const double left = rate > 0 ? static_cast<double>(total_ - done) / rate : 0.0;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(kWidth * done / std::max<std::uint64_t>(total_, 1));
    fmt::print(stderr, "\r[{:<{}}] {}/{} runs, {:.0f} runs/min, ETA {}:{:02}   ",
               std::string(static_cast<std::size_t>(filled), '#'), kWidth, done, total_,
               rate * 60.0, static_cast<int>(left) / 60, static_cast<int>(left) % 60);
    if (done == total_)
      fmt::print(stderr, "\n");
  }

private:
  std::uint64_t total_;
  bool shown_;
  Clock::time_point start_;
  Clock::time_point last_{};
};

int replay(const CampaignCli& cli, const CampaignRunner& runner, std::uint64_t k) {
  imaging::prepare_output_folder(cli.out);
  const fs::path trace = cli.out / fmt::format("run-{}.trace.json", k);
  const nlohmann::ordered_json record = with_trace_file(
      trace.string(), [&](emulator::ChromeTraceWriter& w) { return runner.run(k, &w); });
  const fs::path file = cli.out / fmt::format("run-{}.json", k);
  io::write_file_atomically(file, record.dump() + "\n");
  fmt::print("{}\n", record.dump());
  if (!cli.json)
    fmt::print(stderr, "run {} replayed: its record in {}, its trace in {}\n", k, file.string(),
               trace.string());
  return kSuccess;
}

/// Runs in batches until the stopping rule holds; the batches' size is fixed, so the runs made
/// do not depend on the number of jobs.
std::vector<std::string> run_campaign(const CampaignCli& cli, const overswitch::CampaignSpec& spec,
                                      const CampaignRunner& runner, std::uint64_t runs) {
  constexpr std::uint64_t kBatch = 500;
  ProgressBar bar(runs, !cli.json);
  std::vector<std::string> records;
  std::uint64_t unsafe = 0;
  std::uint64_t judged = 0;
  while (records.size() < runs) {
    const std::uint64_t first = records.size();
    const std::uint64_t last = spec.ci_width ? std::min(runs, first + kBatch) : runs;
    const std::vector<std::string> batch = run_in_jobs(
        first, last, cli.jobs,
        [&runner, &cli](std::uint64_t k) { return runner.run(k, nullptr, !cli.no_skip).dump(); },
        [&bar, first](std::uint64_t done) { bar.update(first + done); });
    for (const std::string& line : batch) {
      const nlohmann::json record = nlohmann::json::parse(line);
      unsafe += record.at("outcome") == "unsafe" ? 1 : 0;
      judged += record.at("golden_unsafe").get<bool>() ? 0 : 1;
      records.push_back(line);
    }
    const Interval ci = wilson_95(unsafe, judged);
    if (spec.ci_width && ci.high - ci.low <= *spec.ci_width)
      break;
  }
  return records;
}

int run(const CampaignCli& cli) {
  overswitch::CampaignSpec spec = overswitch::load_campaign(cli.file);
  if (cli.seeds)
    spec.world_seeds = seed_range(*cli.seeds);
  const std::uint64_t runs = cli.runs.value_or(spec.runs);
  const emulator::PlatformSpec platform = campaign_platform(spec);
  const occam_port::Placement placement =
      occam_port::load_placement(occam_port::default_placement_file(platform), platform,
                                 occam_port::navigation_program_shape());
  if (!cli.json)
    fmt::print(stderr, "campaign {}: rendering {} scenes and their fault-free runs...\n", spec.name,
               spec.world_seeds.size());
  const CampaignRunner runner(spec, platform, placement, {});
  if (cli.replay)
    return replay(cli, runner, *cli.replay);
  imaging::prepare_output_folder(cli.out);
  const Clock::time_point start = Clock::now();
  const std::vector<std::string> lines = run_campaign(cli, spec, runner, runs);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const double per_minute = seconds > 0 ? static_cast<double>(lines.size()) * 60.0 / seconds : 0;

  std::string jsonl;
  std::vector<nlohmann::json> records;
  for (const std::string& line : lines) {
    jsonl += line + "\n";
    records.push_back(nlohmann::json::parse(line));
  }
  const CampaignTally t = tally(records);
  io::write_file_atomically(cli.out / "runs.jsonl", jsonl);
  CampaignFacts facts = runner.facts();
  if (!cli.no_skip)
    for (std::uint64_t k = 0; k < lines.size(); ++k)
      facts.skipped_runs += runner.skippable(k) ? 1 : 0;
  const nlohmann::ordered_json summary = summary_json(spec, facts, t, per_minute);
  const std::string markdown = summary_markdown(spec, facts, t, per_minute);
  io::write_file_atomically(cli.out / "summary.json", summary.dump(2) + "\n");
  io::write_file_atomically(cli.out / "summary.md", markdown);
  imaging::write_image(cli.out / "outcomes.png", outcomes_chart(t));
  imaging::write_image(cli.out / "latency.png", latency_chart(t));
  std::string charts = "outcomes.png and latency.png";
  if (!t.by_region.empty()) {
    imaging::write_image(cli.out / "regions.png",
                         memory_chart(t.by_region, "Outcomes of memory faults by region"));
    imaging::write_image(cli.out / "buffers.png",
                         memory_chart(t.by_buffer, "Outcomes of memory faults by buffer"));
    charts = "outcomes.png, regions.png, buffers.png and latency.png";
  }
  if (cli.json) {
    fmt::print("{}\n", summary.dump(2));
    return kSuccess;
  }
  fmt::print("{}", markdown);
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
