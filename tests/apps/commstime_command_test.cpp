#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using marsokhod::testing::run_marsokhod;

TEST(CommstimeCommand, JsonReportsTheLoopTimeAndHostCost) {
  const auto result = run_marsokhod("commstime --loops 2000 --delta seq --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  // 223 data-book cycles per loop (docs/emulator.md) at the T805-30's 33,333 ps cycle.
  EXPECT_NEAR(json.at("emulated_us_per_loop").get<double>(), 223 * 0.033333, 1e-9);
  EXPECT_DOUBLE_EQ(json.at("emulated_cycles_per_loop").get<double>(), 223.0);
  EXPECT_GT(json.at("host_ns_per_communication").get<double>(), 0.0);
  EXPECT_EQ(json.at("communications").get<int>(), 4 * (2000 + 2 * 16));
}

TEST(CommstimeCommand, MissingPlatformFileIsAnErrorNamingIt) {
  const auto result = run_marsokhod("commstime --platform /no/such/platform.toml");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("/no/such/platform.toml"), std::string::npos) << result.err;
}

TEST(CommstimeCommand, UnknownNodeIsAUsageError) {
  const auto result = run_marsokhod("commstime --node module9");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("module9"), std::string::npos) << result.err;
}

TEST(CommstimeCommand, ZeroLoopsIsAUsageError) {
  const auto result = run_marsokhod("commstime --loops 0");
  EXPECT_EQ(result.exit_code, 2);
}
