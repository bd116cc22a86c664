// `marsokhod eval terrain`: its JSON keys, its pictures, and the exit codes of bad options.
#include "support/run_marsokhod.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

namespace marsokhod::apps {
namespace {

using marsokhod::testing::run_marsokhod;

TEST(EvalTerrainCommand, ReportsEveryKeyForTwoSmallSites) {
  const auto result = run_marsokhod("eval terrain --seeds 3..4 --size 64 --terrain-size 16 --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["seeds"], 2);
  for (const char* key :
       {"obstacle_recall", "false_prohibited", "false_prohibited_by_zone", "paths_found",
        "unsafe_paths", "ground_truth_paths", "bands", "hazard_bands", "per_seed"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_EQ(json["bands"].size(), 3U);
  EXPECT_EQ(json["bands"][0]["band_m"], "2-6");
  EXPECT_EQ(json["per_seed"].size(), 2U);
  EXPECT_NE(result.err.find("seed 2/2"), std::string::npos) << result.err;
}

TEST(EvalTerrainCommand, PicturesShowEachSiteInThreePanels) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "marsokhod-eval-terrain-tests" / "pictures";
  std::filesystem::remove_all(dir);
  const auto result = run_marsokhod("eval terrain --seeds 3 --size 64 --terrain-size 16 "
                                    "--pictures '" +
                                    dir.string() + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const imaging::AnyImage picture = imaging::read_image(dir / "seed-3.png");
  const auto* rgb = std::get_if<imaging::Image<std::uint8_t>>(&picture);
  ASSERT_NE(rgb, nullptr);
  EXPECT_EQ(rgb->width(), 3 * 64);
  EXPECT_EQ(rgb->height(), 64);
  EXPECT_EQ(rgb->channels(), 3);
}

TEST(EvalTerrainCommand, APicturesFolderThatCannotBeMadeIsARuntimeErrorNamingIt) {
  const std::filesystem::path base =
      std::filesystem::temp_directory_path() / "marsokhod-eval-terrain-tests" / "blocked";
  std::filesystem::create_directories(base);
  std::ofstream(base / "a-file") << "not a folder";
  const std::filesystem::path dir = base / "a-file" / "pictures";
  const auto result =
      run_marsokhod("eval terrain --seeds 3 --size 64 --pictures '" + dir.string() + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find(dir.string()), std::string::npos) << result.err;
}

TEST(EvalTerrainCommand, MalformedSeedRangesAreUsageErrors) {
  for (const std::string seeds : {"5..3", "abc", "1..", "-1..2"}) {
    const auto result = run_marsokhod("eval terrain --seeds " + seeds);
    EXPECT_EQ(result.exit_code, 2) << seeds;
    EXPECT_NE(result.err.find("--seeds"), std::string::npos) << result.err;
  }
}

} // namespace
} // namespace marsokhod::apps
