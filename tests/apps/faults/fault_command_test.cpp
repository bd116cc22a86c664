// `marsokhod fault`: one run judged against the fault-free one; bad specs and platforms refused
// with the problem named.

#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace {

using marsokhod::testing::run_marsokhod;

TEST(FaultCommand, HangOfTheMapModuleIsRecoveredWithTheFaultFreePath) {
  const auto result =
      run_marsokhod("fault --platform onboard --seed 2 --inject hang:module1@1.05s --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json j = nlohmann::json::parse(result.out);
  EXPECT_EQ(j["outcome"], "recovered");
  EXPECT_TRUE(j["detected"].get<bool>());
  // Kicks every 100 ms: the last before 1.05 s at 1.0 s, the 200 ms timeout, the kick's own
  // latency (at most 4 us: interrupt latency, out, 1.1 us on the wire).
  EXPECT_GE(j["detection_latency_s"].get<double>(), 0.15);
  EXPECT_LE(j["detection_latency_s"].get<double>(), 0.150004);
  ASSERT_EQ(j["failovers"].size(), 1U);
  EXPECT_EQ(j["failovers"][0]["failed"], "module1");
  EXPECT_EQ(j["failovers"][0]["spare"], "module2");
  EXPECT_TRUE(j["path_equals_golden"].get<bool>());
  EXPECT_FALSE(j["telemetry_lost"].get<bool>());
  EXPECT_FALSE(j["wheels_commanded_while_failed"].get<bool>());
  for (const auto& upload : j["device_log"])
    EXPECT_NE(upload["from"], "module1");
}

TEST(FaultCommand, FaultsOnBothModulesAtOnceEndInASafeStop) {
  const auto result = run_marsokhod(
      "fault --platform onboard --seed 2 --inject hang:module0@1s --inject power:module1@1s "
      "--json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json j = nlohmann::json::parse(result.out);
  EXPECT_EQ(j["outcome"], "safe_stop");
  EXPECT_TRUE(j["telemetry_lost"].get<bool>());
  EXPECT_FALSE(j["path_equals_golden"].get<bool>());
}

TEST(FaultCommand, TraceShowsTheOverswitchAndTheSparesBoot) {
  const std::filesystem::path trace =
      marsokhod::testing::fresh_folder("fault", "trace") / "trace.json";
  const auto result = run_marsokhod("fault --platform onboard --seed 2 --inject hang:module1@1s "
                                    "--trace " +
                                    marsokhod::testing::quoted(trace));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json events = nlohmann::json::parse(marsokhod::testing::slurp(trace));
  bool expired = false;
  bool boot = false;
  for (const auto& e : events["traceEvents"]) {
    const std::string name = e.value("name", "");
    expired = expired || name == "watchdog expired: module1";
    boot = boot || name == "boot module2";
  }
  EXPECT_TRUE(expired) << "no watchdog expiry in the trace";
  EXPECT_TRUE(boot) << "no boot process in the trace";
}

TEST(FaultCommand, HangAfterTheCycleEndedIsMaskedAndStoppedNothing) {
  // Seed 2's onboard cycle ends near 22.5 s emulated: a hang at 100 s comes after it.
  const auto result =
      run_marsokhod("fault --platform onboard --seed 2 --inject hang:module1@100s --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json j = nlohmann::json::parse(result.out);
  EXPECT_EQ(j["outcome"], "masked");
  EXPECT_FALSE(j["activated"].get<bool>());
  EXPECT_FALSE(j["detected"].get<bool>());
  EXPECT_TRUE(j["path_equals_golden"].get<bool>());
  EXPECT_LT(j["emulated_s"].get<double>(), 100.0);
}

TEST(FaultCommand, BadSpecsAreRefusedNamingTheSpecAndTheProblem) {
  const struct {
    const char* spec;
    const char* problem;
  } cases[] = {
      {"melt:module1@1s", "unknown fault kind 'melt'"},
      {"hang:module9@1s", "no module module9"},
      {"hang:module1@zonez+1s", "'zonez' is no stage"},
      {"hang:module1@-3s", "cannot be negative"},
      {"hang:module1@4000s", "between 0 and 3600 s"},
      {"hang:module1@1 s", "is no time"},
      {"hang module1 1s", "KIND:MODULE@WHEN"},
      {"seu:module1@1s,bit=9", "between 0 and 7"},
      {"seu:module0@1s,colour=red", "takes no 'colour'"},
      {"link:module1@1s", "MODULE.linkN"},
      {"linkbit:module0.link0@1s,dir=both", "one wire"},
  };
  for (const auto& c : cases) {
    const auto result =
        run_marsokhod(std::string("fault --platform onboard --inject '") + c.spec + "'");
    EXPECT_EQ(result.exit_code, 2) << c.spec;
    EXPECT_NE(result.err.find(c.spec), std::string::npos) << result.err;
    EXPECT_NE(result.err.find(c.problem), std::string::npos) << result.err;
  }
}

TEST(FaultCommand, ScrubWithoutEdacIsAUsageError) {
  const auto result = run_marsokhod("fault --platform onboard --scrub 5 --inject seu:module0@1s");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--scrub needs --edac"), std::string::npos) << result.err;
}

// An upset in zones' copy of the terrain just after zones took it: zones reads every row after
// it, so the checked terrain halts module1 and the spare's cycle gives the fault-free path.
TEST(FaultCommand, TerrainCheckHaltsTheModuleWhoseKeptTerrainWasStruck) {
  const auto result = run_marsokhod("fault --platform onboard --seed 2 --terrain-check --inject "
                                    "'seu:module1@zones+1us,buffer=seeable disparity' --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json j = nlohmann::json::parse(result.out);
  EXPECT_EQ(j["outcome"], "recovered");
  ASSERT_EQ(j["halts"].size(), 1U);
  EXPECT_EQ(j["halts"][0]["module"], "module1");
  EXPECT_NE(j["halts"][0]["cause"].get<std::string>().find("no longer checks"), std::string::npos);
  EXPECT_TRUE(j["path_equals_golden"].get<bool>());
}

TEST(FaultCommand, UpsetRecordNamesTheBitItsRegionAndBuffer) {
  const auto result = run_marsokhod("fault --platform onboard --seed 2 --edac --inject "
                                    "'seu:module0@1s,addr=0x80001010,bit=4' --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json j = nlohmann::json::parse(result.out);
  const nlohmann::json& fault = j["faults"][0];
  EXPECT_EQ(fault["address"], "#80001010");
  EXPECT_EQ(fault["bit"], 4);
  EXPECT_EQ(fault["region"], "external");
  EXPECT_EQ(fault["edac"], "corrected");
  EXPECT_EQ(j["outcome"], "masked");
  EXPECT_TRUE(j["detected"].get<bool>());
}

TEST(FaultCommand, DeadLinkRecordShowsItsTroublesAndRestarts) {
  const auto result =
      run_marsokhod("fault --platform onboard --seed 2 --inject link:module0.link0@2s --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json j = nlohmann::json::parse(result.out);
  EXPECT_EQ(j["outcome"], "recovered");
  EXPECT_EQ(j["restarts"], 2);
  ASSERT_EQ(j["link_troubles"].size(), 2U);
  EXPECT_EQ(j["link_troubles"][0]["module"], "module0");
  EXPECT_EQ(j["link_troubles"][0]["peer"], "module1");
  EXPECT_EQ(j["failovers"][0]["failed"], "module1");
}

TEST(FaultCommand, PlatformWithoutAnOverswitchIsRefused) {
  const auto result = run_marsokhod("fault --platform pc-card --inject hang:card@1s");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("no [overswitch] table"), std::string::npos) << result.err;
}

} // namespace
