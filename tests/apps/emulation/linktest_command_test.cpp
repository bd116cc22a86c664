// Tests: `marsokhod linktest` against the data book, its traces, and its errors.

#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

// `marsokhod linktest` against the INMOS data book (T805.md, "Links"): at 10 Mbit/s about
// 910 KB/s one way and 1250 KB/s both ways together; at 20 Mbit/s about 1740 KB/s one way and
// 2350-2400 KB/s both ways. 1 KB = 1000 bytes, as the data book's 910 = 10^7 / 11 bits shows.

namespace marsokhod {
namespace {

namespace fs = std::filesystem;
using testing::run_marsokhod;
using testing::slurp;

nlohmann::json linktest(const std::string& arguments) {
  const auto result = run_marsokhod("linktest --json --bytes 20000 " + arguments);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return nlohmann::json::parse(result.out);
}

TEST(LinktestCommand, TenMegabitOneWayMatchesTheDataBook) {
  const nlohmann::json json = linktest("--mode oneway --mbps 10");
  EXPECT_EQ(json.at("mbps"), 10);
  EXPECT_TRUE(json.at("intact").get<bool>());
  EXPECT_NEAR(json.at("bytes_per_second").get<double>(), 910e3, 0.05 * 910e3);
}

TEST(LinktestCommand, TenMegabitBothWaysMatchesTheDataBook) {
  const nlohmann::json json = linktest("--mode both --mbps 10");
  EXPECT_EQ(json.at("bytes_moved"), 40000);
  EXPECT_NEAR(json.at("bytes_per_second").get<double>(), 1250e3, 0.05 * 1250e3);
}

TEST(LinktestCommand, TwentyMegabitMatchesTheDataBook) {
  EXPECT_NEAR(linktest("--mode oneway --mbps 20").at("bytes_per_second").get<double>(), 1740e3,
              0.05 * 1740e3);
  EXPECT_NEAR(linktest("--mode both --mbps 20").at("bytes_per_second").get<double>(), 2375e3,
              0.05 * 2350e3);
}

TEST(LinktestCommand, DefaultSpeedIsTheOnboardWiresTenMegabit) {
  const nlohmann::json json = linktest("");
  EXPECT_EQ(json.at("mbps"), 10); // onboard.toml: 4 links at 10 Mbit/s (paper)
  EXPECT_EQ(json.at("from"), "module0.link0");
  EXPECT_EQ(json.at("to"), "module1.link0");
}

TEST(LinktestCommand, SpeedTheT805DoesNotOfferIsAUsageError) {
  const auto result = run_marsokhod("linktest --mbps 15");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("15"), std::string::npos) << result.err;
}

TEST(LinktestCommand, MissingPlatformFileIsNamed) {
  const auto result = run_marsokhod("linktest --platform /no/such/platform.toml");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("/no/such/platform.toml"), std::string::npos) << result.err;
}

TEST(LinktestCommand, UnwritableTraceFileIsNamed) {
  const auto result = run_marsokhod("linktest --bytes 10 --trace /no/such/folder/trace.json");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("/no/such/folder/trace.json"), std::string::npos) << result.err;
}

TEST(LinktestCommand, TracesOfIdenticalRunsAreByteIdenticalJson) {
  const fs::path dir = fs::temp_directory_path() / "marsokhod-linktest-trace";
  fs::create_directories(dir);
  const fs::path first = dir / "first.json";
  const fs::path second = dir / "second.json";
  for (const fs::path& file : {first, second}) {
    const auto result = run_marsokhod(
        "linktest --bytes 3000 --message-bytes 1000 --mode both --trace '" + file.string() + "'");
    ASSERT_EQ(result.exit_code, 0) << result.err;
  }
  const std::string text = slurp(first);
  EXPECT_EQ(text, slurp(second));
  const nlohmann::json trace = nlohmann::json::parse(text);
  int link_slices = 0;
  for (const auto& event : trace.at("traceEvents"))
    link_slices += event.at("ph") == "B" && event.at("name").get<std::string>().starts_with("out ");
  EXPECT_EQ(link_slices, 6); // three 1000-byte messages each way
}

TEST(LinktestCommand, TraceHasCpuLinkAndMemoryTracksAndMarksTheColdSpares) {
  const fs::path file = fs::temp_directory_path() / "marsokhod-linktest-tracks.json";
  const auto result =
      run_marsokhod("linktest --bytes 2000 --message-bytes 1000 --trace '" + file.string() + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json trace = nlohmann::json::parse(slurp(file));
  std::map<int, std::string> node_of_pid;
  std::set<std::string> tracks; // "node/track"
  for (const auto& event : trace.at("traceEvents"))
    if (event.at("ph") == "M" && event.at("name") == "process_name")
      node_of_pid[event.at("pid").get<int>()] = event.at("args").at("name").get<std::string>();
  std::set<std::string> powered_off;
  std::map<std::string, int> memory_samples;
  for (const auto& event : trace.at("traceEvents")) {
    const std::string node = node_of_pid[event.at("pid").get<int>()];
    if (event.at("ph") == "M" && event.at("name") == "thread_name")
      tracks.insert(node + "/" + event.at("args").at("name").get<std::string>());
    if (event.at("ph") == "i" && event.at("name") == "power off")
      powered_off.insert(node);
    if (event.at("ph") == "C")
      ++memory_samples[node];
  }
  // onboard.toml: module0 and module1 powered, 2 and 3 cold spares; the stream uses the
  // module0-module1 wire, and each side holds a 1000-byte message buffer in its memory.
  for (const char* track : {"module0/cpu", "module1/cpu", "module0/memory", "module0/link0 out",
                            "module0/link0 in", "module1/link0 out", "module1/link0 in"})
    EXPECT_TRUE(tracks.contains(track)) << track;
  EXPECT_EQ(powered_off, (std::set<std::string>{"module2", "module3"}));
  EXPECT_GT(memory_samples["module0"], 2); // the starting point plus the buffer coming and going
  EXPECT_GT(memory_samples["module1"], 2);
}

TEST(LinktestCommand, MessageLargerThanTheNodeMemoryIsAMemoryFaultNamingTheProcess) {
  // onboard.toml modules have 256 KB of external memory: a 300,000-byte buffer cannot exist.
  const auto result = run_marsokhod("linktest --bytes 300000 --message-bytes 300000");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("memory fault"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("stream_out"), std::string::npos) << result.err;
}

} // namespace
} // namespace marsokhod
