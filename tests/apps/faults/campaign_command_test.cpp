// `marsokhod campaign`: hang and power faults over 1,000 runs all recovered to the fault-free
// path, records independent of the number of jobs, a replay byte-identical to its record, and
// bad campaign files refused naming file, line and key.

#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using marsokhod::testing::fresh_folder;
using marsokhod::testing::quoted;
using marsokhod::testing::run_marsokhod;
using marsokhod::testing::slurp;

const fs::path kCampaigns = fs::path(MARSOKHOD_SOURCE_DIR) / "campaigns";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

TEST(CampaignCommand, ThousandHangsAndPowerLossesAreAllDetectedAndRecovered) {
  const fs::path out = fresh_folder("campaign", "thousand");
  const auto result = run_marsokhod("campaign " + quoted(kCampaigns / "hang-power.toml") +
                                    " --runs 1000 --jobs 2 --json --out " + quoted(out));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json summary = nlohmann::json::parse(result.out);
  EXPECT_EQ(summary["runs"], 1000);
  EXPECT_EQ(summary["outcomes"].size(), 1U) << summary["outcomes"].dump();
  EXPECT_EQ(summary["outcomes"]["recovered"], 1000);
  EXPECT_EQ(summary["detected_fraction"], 1.0);
  EXPECT_EQ(summary["path_equals_golden_runs"], 1000);
  EXPECT_EQ(summary["telemetry_lost_runs"], 0);
  EXPECT_EQ(summary["wheels_commanded_while_failed_runs"], 0);
  EXPECT_EQ(summary["unsafe_rate"], 0.0);
  // Detection by the watchdog: after the last kick (at most a period, 100 ms, before the
  // fault) the timeout, 200 ms: between 100 and 200 ms after the fault, plus the kick's few
  // microseconds. The partner's link timeout (100 ms from the start of an output the stopped
  // module never takes) may come first, never later, and fails the module without a restart.
  EXPECT_LE(summary["detection_latency_s"]["max"].get<double>(), 0.200004);
  const std::vector<std::string> records = lines_of(slurp(out / "runs.jsonl"));
  ASSERT_EQ(records.size(), 1000U);
  for (const std::string& line : records) {
    const nlohmann::json record = nlohmann::json::parse(line);
    const double latency = record["detection_latency_s"].get<double>();
    // The failover's restart only (none after a fault past the cycle's end), none on the pair.
    EXPECT_LE(record["restarts"].get<std::size_t>(), record["failovers"].size()) << line;
    if (record.contains("link_troubles")) {
      EXPECT_GT(latency, 0.0) << line;
      continue;
    }
    EXPECT_GE(latency, 0.1) << line;
  }
  for (const char* file : {"summary.json", "summary.md", "outcomes.png", "latency.png"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
}

TEST(CampaignCommand, RecordsDoNotDependOnTheJobsAndReplayRepeatsOneExactly) {
  const fs::path one = fresh_folder("campaign", "one-job");
  const fs::path two = fresh_folder("campaign", "two-jobs");
  // Two of the file's eight scenes: every record still comes from a scene's golden run and a
  // drawn fault, at a quarter of the golden runs' cost.
  const std::string file = quoted(kCampaigns / "hang-power.toml") + " --seeds 2..3";
  ASSERT_EQ(
      run_marsokhod("campaign " + file + " --runs 40 --jobs 1 --out " + quoted(one)).exit_code, 0);
  ASSERT_EQ(
      run_marsokhod("campaign " + file + " --runs 40 --jobs 2 --out " + quoted(two)).exit_code, 0);
  const std::string records = slurp(one / "runs.jsonl");
  EXPECT_EQ(records, slurp(two / "runs.jsonl"));
  const fs::path replayed = fresh_folder("campaign", "replay");
  const auto result =
      run_marsokhod("campaign " + file + " --replay 17 --json --out " + quoted(replayed));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out, lines_of(records).at(17) + "\n");
  EXPECT_EQ(slurp(replayed / "run-17.json"), lines_of(records).at(17) + "\n");
  const fs::path again = fresh_folder("campaign", "replay-again");
  ASSERT_EQ(run_marsokhod("campaign " + file + " --replay 17 --out " + quoted(again)).exit_code, 0);
  const std::string trace = slurp(replayed / "run-17.trace.json");
  EXPECT_GT(trace.size(), 1000U);
  EXPECT_EQ(trace, slurp(again / "run-17.trace.json"));
}

TEST(CampaignCommand, SeedsOptionReplacesTheFilesWorldSeeds) {
  const fs::path out = fresh_folder("campaign", "seeds");
  const auto result = run_marsokhod("campaign " + quoted(kCampaigns / "hang-power.toml") +
                                    " --runs 20 --seeds 3..4 --out " + quoted(out));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const std::string& line : lines_of(slurp(out / "runs.jsonl"))) {
    const auto seed = nlohmann::json::parse(line)["world_seed"].get<int>();
    EXPECT_TRUE(seed == 3 || seed == 4) << line;
  }
  EXPECT_EQ(run_marsokhod("campaign " + quoted(kCampaigns / "hang-power.toml") +
                          " --seeds 4..3 --out " + quoted(out))
                .exit_code,
            2);
}

TEST(CampaignCommand, ConfidenceWidthStopsAtTheFirstBatchThatReachesIt) {
  const fs::path dir = fresh_folder("campaign", "ci-width");
  const fs::path file = dir / "narrow.toml";
  std::ofstream(file) << "[campaign]\nname = \"narrow\"\nplatform = \"onboard\"\n"
                         "[scenarios]\nworld_seeds = [2, 3]\n"
                         "[[fault]]\nkind = \"power\"\n"
                         "[stop]\nruns = 900\nci_width = 0.05\n";
  const auto result =
      run_marsokhod("campaign " + quoted(file) + " --jobs 2 --json --out " + quoted(dir / "out"));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // Batches of 500: after the first, 0 unsafe in 500 judged runs (the fault-free paths of
  // seeds 2 and 3 are safe) gives a Wilson interval 0..0.0076.
  EXPECT_EQ(nlohmann::json::parse(result.out)["runs"], 500);
}

struct BadFile {
  std::string name;
  std::string text;
  int line; ///< 0: a problem of the whole file, said without a line
  std::string key;
  std::string problem;
};

TEST(CampaignCommand, BadCampaignFilesNameFileLineAndKey) {
  const std::string head = "[campaign]\nname = \"x\"\nplatform = \"onboard\"\n"
                           "[scenarios]\nworld_seeds = [2]\n";
  const std::string fault = "[[fault]]\nkind = \"hang\"\n";
  const std::vector<BadFile> cases = {
      {"no-platform", "[campaign]\nname = \"x\"\n[scenarios]\nworld_seeds = [2]\n", 1, "platform",
       "name the platform"},
      {"unknown-key", "[campaign]\nname = \"x\"\nplatform = \"onboard\"\nspeed = 3\n", 4, "speed",
       "is not a key of [campaign]"},
      {"bad-kind", head + "[[fault]]\nkind = \"melt\"\n", 7, "kind", "no fault kind"},
      {"bad-weight", head + fault + "weight = -1\n", 8, "weight", "is not between"},
      {"bad-module", head + fault + "modules = [\"module7\"]\n", 6, "modules",
       "no module of onboard"},
      {"bad-runs", head + fault + "[stop]\nruns = 0\n", 9, "runs", "is not between"},
      {"bad-light",
       "[campaign]\nplatform = \"onboard\"\n[scenarios]\nworld_seeds = [2]\n"
       "light = \"disco\"\n",
       5, "light", "no light"},
      {"bad-share", head + fault + "from_share = 0.5\nto_share = 0.2\n", 9, "to_share",
       "more than from_share"},
      {"no-fault", head, 0, "fault", "at least one [[fault]]"},
      {"bad-over", head + "[[fault]]\nkind = \"seu\"\nover = \"sky\"\n", 8, "over",
       "neither \"allocated\" nor \"memory\""},
      {"bad-stuck-value", head + "[[fault]]\nkind = \"stuck\"\nvalue = 2\n", 8, "value",
       "is not between 0 and 1"},
      {"scrub-without-edac", head + fault + "[protection]\nscrub_period_s = 5\n", 9,
       "scrub_period_s", "set edac"},
      {"bad-protection-key", head + fault + "[protection]\nparity = true\n", 9, "parity",
       "is not a key of [protection]"},
      {"terrain-check-not-a-boolean", head + fault + "[protection]\nterrain_check = \"yes\"\n", 9,
       "terrain_check", "boolean"},
      {"bad-preset",
       head + "[[fault]]\nkind = \"seu\"\nover = \"memory\"\n[upsets]\npreset = \"venus\"\n", 10,
       "preset", "no preset (cruise, mars-surface, leo)"},
      {"rate-and-preset",
       head + "[[fault]]\nkind = \"seu\"\nover = \"memory\"\n[upsets]\npreset = \"leo\"\n"
              "rate_per_bit_day = 1e-8\n",
       11, "rate_per_bit_day", "not both"},
      {"rate-with-a-hang", head + fault + "[upsets]\npreset = \"cruise\"\n", 6, "kind",
       "every [[fault]] is an upset"},
      {"rate-over-allocated", head + "[[fault]]\nkind = \"seu\"\n[upsets]\npreset = \"cruise\"\n",
       6, "over", "over every bit of memory"},
  };
  const fs::path dir = fresh_folder("campaign", "bad");
  for (const BadFile& c : cases) {
    const fs::path file = dir / (c.name + ".toml");
    std::ofstream(file) << c.text;
    const auto result =
        run_marsokhod("campaign " + quoted(file) + " --runs 1 --out " + quoted(dir / "out"));
    EXPECT_EQ(result.exit_code, 1) << c.name << ": " << result.err;
    const std::string place =
        c.line > 0 ? file.string() + ":" + std::to_string(c.line) + ": '" + c.key + "'"
                   : "'" + c.key + "'";
    EXPECT_NE(result.err.find(place), std::string::npos) << c.name << ": " << result.err;
    EXPECT_NE(result.err.find(c.problem), std::string::npos) << c.name << ": " << result.err;
  }
}

// A platform found nowhere is the campaign file's error: both commands that read the file name
// it, with its key, rather than a platform file that does not exist.
TEST(CampaignCommand, APlatformFoundNowhereIsNamedAsTheCampaignFilesError) {
  const fs::path dir = fresh_folder("campaign", "nowhere");
  std::ifstream shipped(kCampaigns / "hang-power.toml");
  std::ofstream file(dir / "nowhere.toml");
  for (std::string line; std::getline(shipped, line);)
    file << (line.rfind("platform = ", 0) == 0 ? "platform = \"-inf\"" : line) << "\n";
  file.close();
  const std::string campaign = quoted(dir / "nowhere.toml");
  for (const std::string& command :
       {"campaign " + campaign + " --runs 1 --out " + quoted(dir / "out"),
        "traverse --platform onboard --max-cycles 1 --faults " + campaign + " --out " +
            quoted(dir / "traverse")}) {
    const auto result = run_marsokhod(command);
    EXPECT_EQ(result.exit_code, 1) << command << "\n" << result.err;
    EXPECT_NE(result.err.find((dir / "nowhere.toml").string() +
                              ": 'platform': '-inf': no such platform file"),
              std::string::npos)
        << result.err;
  }
}

} // namespace
