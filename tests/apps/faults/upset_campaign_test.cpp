// `marsokhod campaign` with upsets: the rate scales the unsafe share to a year of operations over
// every bit of the powered modules, the runs it skips have the records emulating them gives, and
// the outcomes come by memory region and buffer.

#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using marsokhod::testing::fresh_folder;
using marsokhod::testing::quoted;
using marsokhod::testing::run_marsokhod;
using marsokhod::testing::slurp;

/// An upset over every bit of memory at the cruise rate, on world seeds 2 and 3.
fs::path upset_campaign(const fs::path& dir, const std::string& protection) {
  const fs::path file = dir / "upsets.toml";
  std::ofstream(file) << "[campaign]\nname = \"upsets\"\nplatform = \"onboard\"\nseed = 5\n"
                         "[scenarios]\nworld_seeds = [2, 3]\n"
                         "[[fault]]\nkind = \"seu\"\nover = \"memory\"\n"
                      << protection << "[upsets]\npreset = \"cruise\"\n[stop]\nruns = 60\n";
  return file;
}

/// Two powered modules of 4 KB on chip and 256 KB external (platforms/onboard.toml).
constexpr double kModuleBytes = 4096.0 + 256.0 * 1024.0;
/// The cruise preset: Clementine's recorder, 71 upsets a day in 2.1 Gbit.
constexpr double kCruise = 3.4e-8;

TEST(UpsetCampaign, RateScalesTheUnsafeShareOverEveryBitOfThePoweredModules) {
  const fs::path dir = fresh_folder("upset-campaign", "rate");
  const auto result = run_marsokhod("campaign " + quoted(upset_campaign(dir, "")) +
                                    " --jobs 2 --json --out " + quoted(dir / "out"));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json s = nlohmann::json::parse(result.out);
  const double bits = 2 * 8 * kModuleBytes;
  EXPECT_EQ(s["memory_bits"].get<double>(), bits);
  EXPECT_NEAR(s["upsets_per_day"].get<double>(), kCruise * bits, 1e-12);
  const double share = s["outcomes"].value("unsafe", 0) / s["judged_runs"].get<double>();
  EXPECT_NEAR(s["expected_unsafe_per_year"].get<double>(), kCruise * bits * 365.25 * share, 1e-12);
  EXPECT_EQ(s["expected_unsafe_per_year_by_rate"].size(), 7U);
  EXPECT_TRUE(s.contains("by_region"));
  EXPECT_TRUE(s.contains("by_buffer"));
  for (const char* chart : {"regions.png", "buffers.png"})
    EXPECT_TRUE(fs::exists(dir / "out" / chart)) << chart;
}

TEST(UpsetCampaign, EdacAddsItsCheckBitsToWhatTheUpsetsStrike) {
  const fs::path dir = fresh_folder("upset-campaign", "edac");
  const auto result =
      run_marsokhod("campaign " + quoted(upset_campaign(dir, "[protection]\nedac = true\n")) +
                    " --jobs 2 --json --out " + quoted(dir / "out"));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json s = nlohmann::json::parse(result.out);
  // 7 check bits for each 32-bit word of external memory (SEC-DED).
  const double bits = 2 * (8 * kModuleBytes + 256.0 * 1024.0 / 4.0 * 7.0);
  EXPECT_EQ(s["memory_bits"].get<double>(), bits);
  EXPECT_EQ(s["memory_overhead_fraction"].get<double>(), 7.0 / 32.0);
  EXPECT_GT(s["cycle_s"]["mean"].get<double>(), s["cycle_s"]["mean_unprotected"].get<double>());
  EXPECT_EQ(s["outcomes"].value("unsafe", 0), 0);
}

TEST(UpsetCampaign, SkippedRunsHaveTheRecordsEmulatingThemGives) {
  const fs::path dir = fresh_folder("upset-campaign", "skip");
  const fs::path file = upset_campaign(dir, "[protection]\nedac = true\n");
  const auto skipping = run_marsokhod("campaign " + quoted(file) + " --jobs 2 --json --out " +
                                      quoted(dir / "skipping"));
  ASSERT_EQ(skipping.exit_code, 0) << skipping.err;
  const auto emulating = run_marsokhod("campaign " + quoted(file) + " --jobs 2 --no-skip --out " +
                                       quoted(dir / "emulating"));
  ASSERT_EQ(emulating.exit_code, 0) << emulating.err;
  // Most of external memory is free or corrected by the EDAC: most runs are skipped.
  EXPECT_GT(nlohmann::json::parse(skipping.out)["skipped_runs"].get<int>(), 30);
  EXPECT_EQ(slurp(dir / "skipping" / "runs.jsonl"), slurp(dir / "emulating" / "runs.jsonl"));
}

} // namespace
