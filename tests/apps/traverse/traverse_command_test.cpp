// `marsokhod traverse`: its files and keys, and the exit codes of bad options and folders.
#include "support/run_marsokhod.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <variant>

namespace marsokhod::apps {
namespace {

using marsokhod::testing::run_marsokhod;

std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "marsokhod-traverse-tests" / name;
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(TraverseCommand, WritesTheMapTheCyclesAndTheSummary) {
  const std::filesystem::path dir = scratch("short");
  const auto result = run_marsokhod("traverse --seed 4 --rocks 0 --slope 0 --goal-m 20 --out '" +
                                    dir.string() + "' --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  for (const char* key :
       {"outcome", "distance_m", "path_efficiency", "cycles", "emergency_stops", "hand_overs",
        "unsafe_events", "mission_seconds", "driving_seconds", "compute_seconds"})
    EXPECT_TRUE(json.contains(key)) << key;
  std::ifstream file(dir / "traverse.json");
  EXPECT_EQ(nlohmann::json::parse(file), json);
  std::ifstream cycles(dir / "cycles.jsonl");
  std::string line;
  int lines = 0;
  while (std::getline(cycles, line)) {
    const auto cycle = nlohmann::json::parse(line);
    EXPECT_EQ(cycle["cycle"], lines);
    ++lines;
  }
  EXPECT_EQ(lines, json["cycles"]);
  const imaging::AnyImage map = imaging::read_image(dir / "map.png");
  const auto* rgb = std::get_if<imaging::Image<std::uint8_t>>(&map);
  ASSERT_NE(rgb, nullptr);
  // From 5 m west of the start to 5 m east of the goal, 20 m apart, at 0.1 m a pixel.
  EXPECT_EQ(rgb->width(), 300);
  EXPECT_EQ(rgb->channels(), 3);
  for (int cycle = 0; cycle < json["cycles"]; ++cycle)
    EXPECT_TRUE(std::filesystem::exists(dir / "views" / fmt::format("cycle-{:03}.png", cycle)))
        << cycle;
}

TEST(TraverseCommand, AnOutputFolderThatCannotBeMadeIsARuntimeErrorNamingIt) {
  const std::filesystem::path base = scratch("blocked");
  std::filesystem::create_directories(base);
  std::ofstream(base / "a-file") << "not a folder";
  const std::filesystem::path dir = base / "a-file" / "out";
  const auto result = run_marsokhod("traverse --goal-m 20 --out '" + dir.string() + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find(dir.string()), std::string::npos) << result.err;
}

TEST(TraverseCommand, OptionsOutOfRangeAreUsageErrorsNamingTheOption) {
  for (const std::string option :
       {"--rocks 0.6", "--slope 20", "--goal-m 2", "--light dusk", "--size 16", "--max-cycles -1",
        "--seed x", "--platform cray", "--slip 0.6", "--drive-m 21", "--hazard-memory 11"}) {
    const auto result = run_marsokhod("traverse " + option);
    EXPECT_EQ(result.exit_code, 2) << option;
    const std::string name = option.substr(0, option.find(' '));
    EXPECT_NE(result.err.find(name), std::string::npos) << option << ": " << result.err;
  }
}

// --faults strike the emulated computer: on the native one they are a usage error, as a
// campaign file of another platform is; a campaign file that is not there is named.
TEST(TraverseCommand, FaultsNeedTheCampaignsPlatformAndAFileThatReads) {
  const std::string campaign =
      (std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "campaigns" / "hang-power.toml").string();
  for (const std::string& command :
       {"traverse --faults '" + campaign + "'",
        "traverse --platform pc-card --faults '" + campaign + "'",
        "eval traverse --seeds 1 --rocks 0 --faults '" + campaign + "'"}) {
    const auto result = run_marsokhod(command);
    EXPECT_EQ(result.exit_code, 2) << command;
    EXPECT_NE(result.err.find("--faults"), std::string::npos) << command << ": " << result.err;
  }
  const std::filesystem::path missing = scratch("faults") / "no-such-campaign.toml";
  const auto result =
      run_marsokhod("traverse --platform onboard --faults '" + missing.string() + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("no-such-campaign.toml"), std::string::npos) << result.err;
}

std::string read_all(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(EvalTraverseCommand, TrialsAreTheSameForOneAndTwoJobs) {
  std::string trials[2];
  for (const int jobs : {1, 2}) {
    const std::filesystem::path dir = scratch(fmt::format("sweep-{}", jobs));
    const auto result = run_marsokhod(fmt::format(
        "eval traverse --seeds 1..2 --rocks 0,0.1 --goal-m 10 --jobs {} --out '{}' --json", jobs,
        dir.string()));
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const auto summary = nlohmann::json::parse(result.out);
    EXPECT_EQ(summary["trials"], 4);
    ASSERT_EQ(summary["by_rocks"].size(), 2u);
    for (const char* key : {"rocks", "trials", "outcomes", "success_rate", "success_ci95", "spl",
                            "unsafe_trials", "emergency_stops_per_100m", "hand_overs_per_100m",
                            "metres_per_hour", "metres_per_hour_driving"})
      EXPECT_TRUE(summary["by_rocks"][0].contains(key)) << key;
    EXPECT_TRUE(std::filesystem::exists(dir / "success.png"));
    trials[jobs - 1] = read_all(dir / "trials.jsonl");
  }
  EXPECT_FALSE(trials[0].empty());
  EXPECT_EQ(trials[0], trials[1]);

  // Trial 2 (rocks 0.1, seed 1) run alone gives its line byte for byte.
  const auto replay =
      run_marsokhod("eval traverse --seeds 1..2 --rocks 0,0.1 --goal-m 10 --replay 2");
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  std::istringstream lines(trials[0]);
  std::string line;
  for (int k = 0; k <= 2; ++k)
    std::getline(lines, line);
  EXPECT_EQ(replay.out, line + "\n");
}

TEST(EvalTraverseCommand, MalformedRockListsAndSeedsAreUsageErrors) {
  for (const std::string option : {"--rocks 0,,0.1", "--rocks 0.7", "--rocks x", "--rocks ''",
                                   "--seeds 5..3", "--jobs 0", "--replay 99"}) {
    const auto result = run_marsokhod("eval traverse " + option);
    EXPECT_EQ(result.exit_code, 2) << option;
    const std::string name = option.substr(0, option.find(' '));
    EXPECT_NE(result.err.find(name), std::string::npos) << option << ": " << result.err;
  }
}

} // namespace
} // namespace marsokhod::apps
