// `marsokhod reproduce`: the paper's three figures beside the model's, its one fitted constant
// fitted on exactly one of them, a sweep that falls as memory grows and meets the PC card at
// the card's size, byte-identical JSON twice, and clear refusals.
#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <string>
#include <sys/file.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using marsokhod::testing::quoted;
using marsokhod::testing::run_marsokhod;
using marsokhod::testing::slurp;

fs::path reproduce_folder(const std::string& name) {
  return marsokhod::testing::fresh_folder("marsokhod-reproduce-tests", name);
}

// The default run (about 7 s), made once for the tests that read it: ctest runs each test in a
// process of its own, so the first to take the lock runs it into a folder named for the binary's
// build time, beside the binary, and the others wait and read it.
fs::path default_run() {
  const fs::path binary = MARSOKHOD_BINARY;
  const auto built = fs::last_write_time(binary).time_since_epoch().count();
  const fs::path out = binary.parent_path() / ("reproduce-test-" + std::to_string(built));
  const int lock = ::open((out.string() + ".lock").c_str(), O_CREAT | O_RDWR, 0644);
  EXPECT_GE(lock, 0) << out;
  ::flock(lock, LOCK_EX);
  if (!fs::exists(out / "reproduce.json")) {
    const fs::path made = out.string() + ".making";
    fs::remove_all(made);
    const auto result = run_marsokhod("reproduce --json --out " + quoted(made));
    EXPECT_EQ(result.exit_code, 0) << result.err;
    if (result.exit_code == 0)
      fs::rename(made, out);
  }
  ::flock(lock, LOCK_UN);
  ::close(lock);
  return out;
}

const nlohmann::json& reproduction() {
  static const nlohmann::json json = nlohmann::json::parse(slurp(default_run() / "reproduce.json"));
  return json;
}

const nlohmann::json& figure(const std::string& name) {
  for (const nlohmann::json& f : reproduction()["figures"])
    if (f["name"] == name)
      return f;
  throw std::runtime_error("no figure " + name);
}

// The paper's figures, as its Conclusions give them: 8 s, 10 s and 1.3 min.
TEST(ReproduceCommand, GivesThePapersThreeFiguresBesideTheModelsWithTheirErrors) {
  ASSERT_EQ(reproduction()["figures"].size(), 3U);
  EXPECT_EQ(figure("stereo 128x128 on one T805")["paper_seconds"], 8.0);
  EXPECT_EQ(figure("whole cycle on the PC card")["paper_seconds"], 10.0);
  EXPECT_EQ(figure("whole cycle onboard")["paper_seconds"], 78.0);
  for (const nlohmann::json& f : reproduction()["figures"]) {
    const double paper = f["paper_seconds"];
    const double model = f["model_seconds"];
    EXPECT_GT(model, 0.0) << f["name"];
    EXPECT_NEAR(f["error_percent"].get<double>(), (model - paper) / paper * 100.0, 1e-9);
    EXPECT_LE(f["over_scenes"]["least"].get<double>(), model);
    EXPECT_GE(f["over_scenes"]["greatest"].get<double>(), model);
  }
}

TEST(ReproduceCommand, FitsOneConstantOnOneFigureAndTheShippedValueIsTheFit) {
  ASSERT_EQ(reproduction()["fitted_constants"].size(), 1U);
  const nlohmann::json& c = reproduction()["fitted_constants"][0];
  EXPECT_EQ(c["name"], "occam_style_factor");
  EXPECT_NE(c["fitted_on"].get<std::string>().find("stereo"), std::string::npos);
  EXPECT_NEAR(c["value"].get<double>(), c["refit"].get<double>(), 0.0015);
  int fitted = 0;
  for (const nlohmann::json& f : reproduction()["figures"])
    fitted += f["fitted"].get<bool>() ? 1 : 0;
  EXPECT_EQ(fitted, 1);
  EXPECT_TRUE(figure("stereo 128x128 on one T805")["fitted"].get<bool>());
  EXPECT_NEAR(figure("stereo 128x128 on one T805")["error_percent"].get<double>(), 0.0, 0.5);
}

// The sweep from 32 KB to 4 MB: the small sizes cannot run, and from the first size that runs
// the cycle never takes longer as memory grows.
TEST(ReproduceCommand, TheOnboardSweepFallsAsMemoryGrowsAndMeetsTheCardAtItsSize) {
  const nlohmann::json& sweep = reproduction()["sweep"];
  ASSERT_GE(sweep.size(), 10U);
  EXPECT_EQ(sweep.front()["external_kb"], 32);
  EXPECT_EQ(sweep.back()["external_kb"], 4096);
  EXPECT_FALSE(sweep.front()["memory_fault"].is_null());
  double last = INFINITY;
  bool ran = false;
  std::map<int, double> seconds_at;
  for (const nlohmann::json& p : sweep) {
    if (!p["memory_fault"].is_null()) {
      EXPECT_FALSE(ran) << p["external_kb"] << " KB faults above a size that ran";
      continue;
    }
    ran = true;
    const double seconds = p["emulated_seconds"];
    EXPECT_LE(seconds, last * 1.0001) << p["external_kb"];
    last = seconds;
    seconds_at[p["external_kb"].get<int>()] = seconds;
  }
  ASSERT_TRUE(seconds_at.contains(2048));
  ASSERT_TRUE(seconds_at.contains(256));
  const double card = figure("whole cycle on the PC card")["model_seconds"];
  EXPECT_NEAR(seconds_at[2048], card, 0.03 * card);
  EXPECT_NEAR(seconds_at[256], figure("whole cycle onboard")["model_seconds"].get<double>(), 1e-9);
}

// The sensitivity table holds the parameters the paper does not give; a slower card is slower.
TEST(ReproduceCommand, SensitivityMovesEachFigureWithTheParametersThePaperDoesNotGive) {
  const nlohmann::json& rows = reproduction()["sensitivity"];
  double t805_30 = 0.0;
  double t805_20 = 0.0;
  for (const nlohmann::json& row : rows) {
    if (row["parameter"] == "PC card speed grade" && row["value"] == "T805-30")
      t805_30 = row["card_cycle_seconds"];
    if (row["parameter"] == "PC card speed grade" && row["value"] == "T805-20")
      t805_20 = row["card_cycle_seconds"];
  }
  ASSERT_GT(t805_30, 0.0);
  // Almost all of the card's cycle is CPU time: 50 ns cycles against 33.3 ns.
  EXPECT_NEAR(t805_20 / t805_30, 50000.0 / 33333.0, 0.03);
}

TEST(ReproduceCommand, WritesItsTablesAndPicturesAndRepeatsItsJsonByteForByte) {
  const fs::path a = reproduce_folder("a");
  const fs::path b = reproduce_folder("b");
  const std::string args = " --seeds 2..3 --sweep-external-kb 128,256,2048";
  ASSERT_EQ(run_marsokhod("reproduce --out " + quoted(a) + args).exit_code, 0);
  ASSERT_EQ(run_marsokhod("reproduce --out " + quoted(b) + args).exit_code, 0);
  for (const char* file : {"reproduce.json", "reproduce.md", "reproduce.png", "sweep.csv",
                           "sweep.json", "sweep.png"}) {
    EXPECT_TRUE(fs::exists(a / file)) << file;
    EXPECT_EQ(slurp(a / file), slurp(b / file)) << file;
  }
  EXPECT_NE(slurp(a / "reproduce.md").find("| whole cycle onboard |"), std::string::npos);
}

TEST(ReproduceCommand, RefusesABackwardSeedRangeNamingTheOption) {
  const auto result =
      run_marsokhod("reproduce --seeds 5..2 --out " + quoted(reproduce_folder("bad")));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--seeds"), std::string::npos) << result.err;
}

} // namespace
