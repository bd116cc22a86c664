// The platform's [overswitch] table: the onboard timings as shipped, and every wrong key,
// type or value refused naming the file, the line and the key.

#include "support/test_files.hpp"

#include "marsokhod/emulator/platform/platform.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace marsokhod::emulator {
namespace {

using test_support::kPlatforms;

/// onboard.toml up to its [overswitch] table, naming the shipped processor file by its path.
std::string onboard_without_overswitch() {
  std::ifstream in(kPlatforms / "onboard.toml");
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  text = text.substr(0, text.find("[overswitch]"));
  const std::string relative = "\"processors/t805.toml\"";
  std::string absolute = "\"";
  absolute += (kPlatforms / "processors" / "t805.toml").string();
  absolute += '"';
  text.replace(text.find(relative), relative.size(), absolute);
  return text;
}

std::filesystem::path write_platform(const std::string& overswitch) {
  const std::string test = testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::filesystem::path path =
      std::filesystem::path(testing::TempDir()) /
      (test + "-" + std::to_string(std::hash<std::string>{}(overswitch)) + ".toml");
  std::ofstream(path) << onboard_without_overswitch() << overswitch;
  return path;
}

int lines_in(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(PlatformOverswitch, OnboardShipsTheWatchdogAtTwiceTheHeartbeat) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  ASSERT_TRUE(onboard.overswitch);
  const OverswitchSpec& o = *onboard.overswitch;
  EXPECT_EQ(o.modules, (std::vector<std::string>{"module0", "module1", "module2", "module3"}));
  EXPECT_EQ(o.powered_at_once, 2);
  EXPECT_EQ(o.heartbeat_period, 100 * kMillisecond);
  EXPECT_EQ(o.watchdog_timeout, 2 * o.heartbeat_period);
  EXPECT_EQ(o.boot_allowance, kSecond);
  EXPECT_FALSE(load_platform(kPlatforms / "pc-card.toml").overswitch);
}

TEST(PlatformOverswitch, WrongTablesNameFileLineAndKey) {
  const std::string good_timings =
      "heartbeat_period_us = 100000\nwatchdog_timeout_us = 200000\nboot_allowance_us = 1000000\n";
  const struct {
    std::string table;
    int line; ///< within the table, from 1 at [overswitch]
    std::string key;
    std::string problem;
  } cases[] = {
      {"[overswitch]\nmodules = [\"module0\", \"module9\"]\npowered_at_once = 1\n" + good_timings,
       2, "modules", "'module9' is no node"},
      {"[overswitch]\nmodules = [\"module0\", \"module0\"]\npowered_at_once = 1\n" + good_timings,
       2, "modules", "listed twice"},
      {"[overswitch]\nmodules = [\"module0\", \"module1\", \"module2\"]\npowered_at_once = 3\n" +
           good_timings,
       3, "powered_at_once", "2 of its modules are powered"},
      {"[overswitch]\nmodules = [\"module0\", \"module1\"]\npowered_at_once = 2\n"
       "heartbeat_period_us = 100000\nwatchdog_timeout_us = 100000\nboot_allowance_us = 1\n",
       5, "watchdog_timeout_us", "longer than heartbeat_period_us"},
      {"[overswitch]\nmodules = [\"module0\", \"module1\"]\npowered_at_once = 2\n"
       "heartbeat_period_us = 0\nwatchdog_timeout_us = 100000\nboot_allowance_us = 1\n",
       4, "heartbeat_period_us", ""},
      {"[overswitch]\nmodules = [\"module0\", \"module1\"]\npowered_at_once = 2\n" + good_timings +
           "policy = \"random\"\n",
       7, "policy", ""},
      {"[overswitch]\nmodules = []\npowered_at_once = 2\n" + good_timings, 2, "modules",
       "must list the modules"},
  };
  const int offset = lines_in(onboard_without_overswitch());
  for (const auto& c : cases) {
    const std::filesystem::path file = write_platform(c.table);
    try {
      load_platform(file);
      ADD_FAILURE() << "accepted:\n" << c.table;
    } catch (const PlatformError& error) {
      const std::string place =
          file.string() + ":" + std::to_string(offset + c.line) + ": '" + c.key + "'";
      EXPECT_NE(std::string(error.what()).find(place), std::string::npos)
          << error.what() << "\nwanted " << place;
      EXPECT_NE(std::string(error.what()).find(c.problem), std::string::npos) << error.what();
    }
  }
}

} // namespace
} // namespace marsokhod::emulator
