// Tests: through the binary, each command's numeric options refuse NaN, infinities, overflow,
// wrapped integers and junk with exit 2 naming the option, and legal edge values run.
#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace {

namespace fs = std::filesystem;
using marsokhod::testing::run_marsokhod;

// A command with its required arguments (which are never read: parsing fails first) and its
// numeric options.
struct CommandOptions {
  std::string command;
  std::vector<std::string> options;
};

const std::vector<CommandOptions> kCommands = {
    {"nav L R --out D", {"--pitch", "--roll", "--heading", "--max-step"}},
    {"world --out D",
     {"--seed", "--size", "--rocks", "--terrain-size", "--x", "--y", "--heading", "--noise",
      "--misalign-pan", "--misalign-tilt", "--misalign-roll"}},
    {"rig", {"--size"}},
    {"calibrate L R --out F", {"--max-disparity", "--max-shift"}},
    {"eval stereo P", {"--max-disparity", "--levels", "--band", "--right-gain", "--right-offset"}},
    {"eval terrain --seeds 1", {"--size", "--rocks", "--terrain-size"}},
    {"commstime", {"--loops"}},
    {"linktest", {"--bytes", "--mbps", "--message-bytes"}},
    {"image convert I O --colour", {"--min", "--max"}},
    {"emulate L R --platform onboard",
     {"--seed", "--size", "--external-kb", "--occam-style", "--pitch", "--roll"}},
    {"fault --platform onboard --inject hang:module0@1s", {"--seed", "--scrub"}},
    {"campaign F", {"--runs", "--jobs", "--replay"}},
    {"traverse",
     {"--seed", "--rocks", "--slope", "--drive-m", "--hazard-memory", "--slip", "--goal-m",
      "--size", "--max-cycles"}},
    {"eval traverse",
     {"--slope", "--drive-m", "--hazard-memory", "--slip", "--goal-m", "--size", "--jobs",
      "--replay"}},
};

// Values no numeric option takes. 4294967312 is 2^32 + 16 (16 once wrapped to 32 bits) and is
// above every bound but --seed's, which is checked on its own below.
const std::vector<std::string> kBadValues = {"nan", "inf", "-inf", "1e309", "1x", "''", "0x10"};

// "a b c": built with append, which (unlike a chain of operator+) GCC 12 does not misread as
// an overlapping copy.
std::string words(std::initializer_list<std::string_view> parts) {
  std::string text;
  for (std::string_view part : parts) {
    if (!text.empty())
      text.push_back(' ');
    text.append(part);
  }
  return text;
}

void expect_usage_error(const std::string& arguments, const std::string& option) {
  const auto result = run_marsokhod(arguments);
  EXPECT_EQ(result.exit_code, 2) << arguments << "\n" << result.err;
  EXPECT_NE(result.err.find(option + ": "), std::string::npos) << arguments << "\n" << result.err;
}

TEST(OptionValues, NonFiniteOverflowingAndJunkValuesAreUsageErrorsNamingTheOption) {
  for (const CommandOptions& command : kCommands)
    for (const std::string& option : command.options)
      for (const std::string& value : kBadValues)
        expect_usage_error(words({command.command, option, value}), option);
}

TEST(OptionValues, WrappingIntegersAreUsageErrorsNamingTheOption) {
  // -1 once ran as seed 18446744073709551615; 2^64 would be 0.
  expect_usage_error("world --out D --seed -1", "--seed");
  expect_usage_error("world --out D --seed 18446744073709551616", "--seed");
  for (const auto& [command, option] :
       std::vector<std::pair<std::string, std::string>>{{"world --out D", "--size"},
                                                        {"rig", "--size"},
                                                        {"calibrate L R --out F", "--max-shift"},
                                                        {"eval stereo P", "--levels"},
                                                        {"eval terrain --seeds 1", "--size"},
                                                        {"commstime", "--loops"},
                                                        {"linktest", "--bytes"},
                                                        {"linktest", "--message-bytes"},
                                                        {"linktest", "--mbps"}})
    for (const char* value : {"4294967312", "-1", "1.5"})
      expect_usage_error(words({command, option, value}), option);
}

TEST(OptionValues, TheExamplesOfNanOptionsAreUsageErrors) {
  // Once: exit 0 with "no pixel passed the left-right check", and a 100 % bad score.
  const auto pitch = run_marsokhod("nav L R --out D --pitch nan");
  EXPECT_EQ(pitch.exit_code, 2);
  EXPECT_NE(pitch.err.find("--pitch: 'nan' is not a finite number between -45 and 45"),
            std::string::npos)
      << pitch.err;
  const auto gain = run_marsokhod("eval stereo P --right-gain nan");
  EXPECT_EQ(gain.exit_code, 2);
  EXPECT_NE(gain.err.find("--right-gain: 'nan' is not a finite number between 0.01 and 100"),
            std::string::npos)
      << gain.err;
}

TEST(OptionValues, ValuesJustOutsideTheRangeAreUsageErrors) {
  expect_usage_error("nav L R --out D --pitch 45.001", "--pitch");
  expect_usage_error("world --out D --size 15", "--size");
  expect_usage_error("world --out D --size 2049", "--size");
  expect_usage_error("world --out D --x 100.5", "--x");
  expect_usage_error("world --out D --misalign-pan 3600.5", "--misalign-pan");
  expect_usage_error("rig --size 0x80", "--size");
  expect_usage_error("eval stereo P --max-disparity 4097", "--max-disparity");
  expect_usage_error("commstime --loops 1000000001", "--loops");
  expect_usage_error("image convert I O --colour --min 3.5e38", "--min");
}

// The emulator's memory ends with the T805's address space, #80001000 + 2 GB - 4 KB.
TEST(OptionValues, ExternalMemoryBeyondTheT805AddressSpaceIsAUsageErrorNamingTheOption) {
  for (const char* kb : {"2097149", "4194300"}) {
    const auto result = run_marsokhod(words({"emulate L R --platform onboard --external-kb", kb}));
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_NE(result.err.find("--external-kb: '" + std::string(kb) +
                              "' is not a whole number between 0 and 2097148"),
              std::string::npos)
        << result.err;
  }
}

// Lists of memory sizes: CLI11's own splitting once dropped an empty item without a word.
TEST(OptionValues, AMemorySizeListWithAnEmptyOrBadItemIsAUsageErrorNamingTheOption) {
  for (const char* command : {"emulate L R --platform onboard", "reproduce"})
    for (const char* list :
         {"64,,128", "64,", ",64", "''", "'64;128'", "1e3", "0", "2097149", "nan", "64,-1"})
      expect_usage_error(words({command, "--sweep-external-kb", list}), "--sweep-external-kb");
  const auto empty = run_marsokhod("reproduce --sweep-external-kb 64,,128");
  EXPECT_NE(empty.err.find("'64,,128': item 2 is empty"), std::string::npos) << empty.err;
}

// Seed ranges say what is wrong with them: the range each end takes, the order, the count.
TEST(OptionValues, ASeedRangeItCannotTakeIsRefusedSayingWhy) {
  const std::string campaign =
      "campaign " +
      marsokhod::testing::quoted(fs::path(MARSOKHOD_SOURCE_DIR) / "campaigns" / "hang-power.toml");
  for (const auto& [range, why] : std::vector<std::pair<std::string, std::string>>{
           {"1..18446744073709551616", "each a whole number from 0 to 18446744073709551615"},
           {"x..2", "each a whole number from 0 to 18446744073709551615"},
           {"5..3", "the last seed is below the first"},
           {"1..1001", "at most 1000 seeds"}}) {
    const auto result = run_marsokhod(words({campaign, "--runs 1 --seeds", range}));
    EXPECT_EQ(result.exit_code, 2) << range << "\n" << result.err;
    EXPECT_NE(result.err.find("--seeds '" + range + "': "), std::string::npos) << result.err;
    EXPECT_NE(result.err.find(why), std::string::npos) << range << "\n" << result.err;
  }
}

// One rendered scene, reused by the edge-value runs below.
class EdgeValues : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("marsokhod-option-edges-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    const auto world = run_marsokhod(words({"world --seed 3 --size 128 --out", at("w")}));
    ASSERT_EQ(world.exit_code, 0) << world.err;
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static std::string at(const std::string& name) {
    std::string quoted = "'";
    quoted.append((dir_ / name).string());
    quoted.push_back('\'');
    return quoted;
  }

  static fs::path dir_;
};

fs::path EdgeValues::dir_;

void expect_runs(const std::string& arguments) {
  const auto result = run_marsokhod(arguments);
  EXPECT_EQ(result.exit_code, 0) << arguments << "\n" << result.err;
  EXPECT_EQ(result.err.find("nan"), std::string::npos) << result.err;
  EXPECT_EQ(result.out.find("nan"), std::string::npos) << result.out;
}

TEST_F(EdgeValues, NavRunsAtTheEndsOfItsRanges) {
  const std::string pair = at("w/left.pgm") + " " + at("w/right.pgm") + " --out " + at("n");
  expect_runs("nav " + pair + " --pitch 45 --roll -45 --heading 180 --max-step 5");
  expect_runs("nav " + pair + " --pitch -45 --roll 45 --heading -180 --max-step 0.01 --json");
}

TEST_F(EdgeValues, WorldRunsAtTheEndsOfItsRanges) {
  expect_runs("world --size 16 --terrain-size 8 --rocks 0.5 --noise 64 --heading -360 --seed "
              "18446744073709551615 --x 2 --y -2 --misalign-pan 3600 --misalign-tilt -3600 "
              "--misalign-roll 3600 --out " +
              at("w16"));
  // 2^32 + 16 is a legal 64-bit seed and must be kept as such, not wrapped to 16.
  const auto wide = run_marsokhod("world --size 16 --terrain-size 8 --json --seed 4294967312 "
                                  "--out " +
                                  at("w16b"));
  EXPECT_EQ(wide.exit_code, 0) << wide.err;
  EXPECT_NE(wide.out.find("\"seed\": 4294967312"), std::string::npos) << wide.out;
}

TEST_F(EdgeValues, CalibrateEvalStereoAndRigRunAtTheEndsOfTheirRanges) {
  const std::string pair = at("w/left.pgm") + " " + at("w/right.pgm");
  expect_runs("calibrate " + pair + " --out " + at("c.toml") +
              " --max-shift 32 --max-disparity 1024");
  expect_runs("calibrate " + pair + " --out " + at("c.toml") +
              " --max-shift 2 --max-disparity 1024");
  // A search of 2 px finds no block of this scene: the data's problem, said as such (exit 1).
  const auto narrow =
      run_marsokhod("calibrate " + pair + " --out " + at("c.toml") + " --max-disparity 2");
  EXPECT_EQ(narrow.exit_code, 1);
  EXPECT_NE(narrow.err.find("block matches agree"), std::string::npos) << narrow.err;
  std::ofstream(dir_ / "PAIRS.tsv")
      << "name\tleft\tright\tgt\tgt_scale\tgt_bits\twidth\theight\tmax_gt_disp_px\n"
      << "w\tw/left.pgm\tw/right.pgm\t-\t-\t-\t128\t128\t-\n";
  const std::string index = at("PAIRS.tsv");
  expect_runs("eval stereo " + index +
              " --max-disparity 1 --levels 5 --band 0 --right-gain 0.01 --right-offset 255");
  expect_runs("eval stereo " + index +
              " --max-disparity 127 --levels 0 --band 64 --right-gain 100 --right-offset -255");
  expect_runs("rig --size 128");
  expect_runs("rig --size 256 --json");
}

TEST_F(EdgeValues, CampaignAndEmulateRunAtTheEndsOfTheirRanges) {
  // The largest seed a campaign file can hold, alone; once refused as not a whole number.
  expect_runs(
      "campaign " +
      marsokhod::testing::quoted(fs::path(MARSOKHOD_SOURCE_DIR) / "campaigns" / "hang-power.toml") +
      " --runs 1 --seeds 9223372036854775807..9223372036854775807 --out " + at("c"));
  // The node's memory is mapped lazily: the largest legal size costs what the cycle touches.
  expect_runs("emulate --platform onboard --external-kb 2097148 --out " + at("e"));
  expect_runs("emulate --platform onboard --sweep-external-kb 2097148,1 --out " + at("s"));
}

TEST_F(EdgeValues, EvalTerrainEmulatorAndImageCommandsRunAtTheEndsOfTheirRanges) {
  expect_runs("eval terrain --seeds 18446744073709551615 --size 32 --terrain-size 16 --rocks 0.5");
  expect_runs("commstime --loops 1");
  expect_runs("linktest --bytes 1 --message-bytes 1");
  expect_runs("image convert " + at("w/gt_disparity.pfm") + " " + at("x.png") +
              " --colour --min -3.4028234663852886e+38 --max 3.4028234663852886e+38");
}

} // namespace
