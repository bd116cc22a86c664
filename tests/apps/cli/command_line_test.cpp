// Tests: the command line's help, unknown subcommands and exit codes.

#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>

using marsokhod::testing::run_marsokhod;

TEST(CommandLine, HelpListsSubcommandsAndExitsZero) {
  const auto result = run_marsokhod("--help");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("Usage: marsokhod"), std::string::npos);
  EXPECT_NE(result.out.find("world"), std::string::npos) << result.out;
}

TEST(CommandLine, NoSubcommandIsAUsageError) {
  const auto result = run_marsokhod("");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("subcommand"), std::string::npos) << result.err;
}

TEST(CommandLine, UnknownSubcommandIsAUsageError) {
  const auto result = run_marsokhod("fly-to-mars");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("fly-to-mars"), std::string::npos) << result.err;
}

TEST(CommandLine, UnknownOptionIsAUsageError) {
  const auto result = run_marsokhod("world --out /tmp/marsokhod-unused --no-such-option");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--no-such-option"), std::string::npos) << result.err;
}

TEST(CommandLine, VersionPrintsTheVersion) {
  const auto result = run_marsokhod("--version");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("marsokhod 0.1.0"), std::string::npos) << result.out;
}
