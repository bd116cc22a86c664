// Tests: `marsokhod commstime`, its JSON and trace, and its errors for bad platforms and options.

#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

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

TEST(CommstimeCommand, TraceIsByteIdenticalJsonWithProcessSlicesAndMemoryCounters) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "marsokhod-commstime-trace";
  fs::create_directories(dir);
  std::vector<std::string> texts;
  for (const char* name : {"first.json", "second.json"}) {
    const fs::path file = dir / name;
    const auto result =
        run_marsokhod("commstime --loops 4 --delta seq --trace '" + file.string() + "'");
    ASSERT_EQ(result.exit_code, 0) << result.err;
    std::ifstream in(file, std::ios::binary);
    texts.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  EXPECT_EQ(texts[0], texts[1]);
  const auto trace = nlohmann::json::parse(texts[0]);
  std::set<std::string> slices;
  int counters = 0;
  for (const auto& event : trace.at("traceEvents")) {
    if (event.at("ph") == "B")
      slices.insert(event.at("name").get<std::string>());
    counters += event.at("ph") == "C";
  }
  // The parent that runs the PAR's last branch, and the three branches it starts.
  EXPECT_EQ(slices.size(), 4U);
  EXPECT_GE(counters, 2); // the memory track's starting point: in use and high water
}
