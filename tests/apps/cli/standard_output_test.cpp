// Tests: a command whose standard output cannot be written (a full disk, a closed pipe) fails
// with exit 1 and says so, instead of reporting success over lost results.
#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using marsokhod::testing::run_marsokhod;
using marsokhod::testing::run_marsokhod_into_closed_pipe;

std::string scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("marsokhod-stdout-" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  return dir.string();
}

// /dev/full takes the open and fails every write with ENOSPC.
void expect_full_disk_failure(const std::string& arguments) {
  const auto result = run_marsokhod(arguments, "/dev/full");
  EXPECT_EQ(result.exit_code, 1) << arguments << "\n" << result.err;
  EXPECT_NE(result.err.find("marsokhod: error: cannot write standard output: No space left on "
                            "device"),
            std::string::npos)
      << arguments << "\n"
      << result.err;
}

TEST(StandardOutput, AFullDiskIsExitOneWithTheReason) {
  // The example: `world ... > /dev/full` once exited 0.
  expect_full_disk_failure("world --size 16 --terrain-size 8 --out " + scratch("world"));
  expect_full_disk_failure("world --size 16 --terrain-size 8 --json --out " + scratch("json"));
  expect_full_disk_failure("rig");
  expect_full_disk_failure("rig --json");
  expect_full_disk_failure("commstime --loops 10 --json");
  expect_full_disk_failure("--help");
  expect_full_disk_failure("world --help");
}

TEST(StandardOutput, TheFailureIsReportedOnce) {
  const auto result = run_marsokhod("rig", "/dev/full");
  const std::string line = "cannot write standard output";
  const std::size_t first = result.err.find(line);
  ASSERT_NE(first, std::string::npos) << result.err;
  EXPECT_EQ(result.err.find(line, first + 1), std::string::npos) << result.err;
}

TEST(StandardOutput, AClosedPipeIsExitOneNotADeathBySignal) {
  for (const std::vector<std::string>& arguments : std::vector<std::vector<std::string>>{
           {"rig"},
           {"rig", "--json"},
           {"world", "--size", "16", "--terrain-size", "8", "--json", "--out", scratch("pipe")},
           {"linktest", "--bytes", "100", "--json"},
           {"--version"}}) {
    const auto result = run_marsokhod_into_closed_pipe(arguments);
    EXPECT_EQ(result.exit_code, 1) << arguments.front() << "\n" << result.err;
    EXPECT_NE(result.err.find("marsokhod: error: cannot write standard output: Broken pipe"),
              std::string::npos)
        << arguments.front() << "\n"
        << result.err;
  }
}

TEST(StandardOutput, ACommandThatFailsForItsOwnReasonKeepsItsCodeAndMessage) {
  // Nothing is printed on stdout before the usage error: exit 2 stays 2.
  const auto result = run_marsokhod("rig --size 100", "/dev/full");
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_NE(result.err.find("--size"), std::string::npos) << result.err;
}

} // namespace
