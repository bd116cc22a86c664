// Tests: `marsokhod eval stereo` on real and synthetic pairs, its figures and its errors.
// `marsokhod eval stereo`: the Middlebury bad-1.0 metric over a PAIRS.tsv index, on the real
// pairs and on synthetic ones (8- and 16-bit ground truth, a pair without ground truth), and
// clear errors naming the index file and line for bad indexes.
#include "nav/stereo_test_support.hpp"
#include "support/run_marsokhod.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace marsokhod {
namespace {

namespace fs = std::filesystem;
using testing::run_marsokhod;

const std::string kHeader = "name\tleft\tright\tgt\tgt_scale(disp=value/scale)\tgt_bits\twidth\t"
                            "height\tmax_gt_disp_px\tnotes\n";

// A folder with a random-dot pair (128 x 96, background 6 px, square 14 px), its ground truth
// as 8-bit (x 4) and 16-bit KITTI-style (x 256) images, and an index the test writes.
class EvalStereoCommand : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("marsokhod-eval-stereo-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    const nav::testing::DotPair pair = nav::testing::make_dot_pair(nav::testing::DotScene{});
    imaging::write_image(dir_ / "dots_left.pgm", pair.left.view());
    imaging::write_image(dir_ / "dots_right.pgm", pair.right.view());
    imaging::Image<std::uint8_t> gt8(pair.disparity.width(), pair.disparity.height());
    imaging::Image<std::uint16_t> gt16(pair.disparity.width(), pair.disparity.height());
    for (std::size_t i = 0; i < gt8.size(); ++i) {
      gt8.data()[i] = static_cast<std::uint8_t>(pair.disparity.data()[i] * 4);
      gt16.data()[i] = static_cast<std::uint16_t>(pair.disparity.data()[i] * 256);
    }
    imaging::write_image(dir_ / "dots_gt.pgm", gt8.view());
    imaging::write_image(dir_ / "dots_gt16.pgm", gt16.view());
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path index(const std::string& body) const {
    const fs::path file = dir_ / "PAIRS.tsv";
    std::ofstream(file) << body;
    return file;
  }

  fs::path dir_;
};

TEST_F(EvalStereoCommand, ScoresEightAndSixteenBitGroundTruthAndTimesPairsWithout) {
  const fs::path file = index(
      kHeader + "eight\tdots_left.pgm\tdots_right.pgm\tdots_gt.pgm\t4\t8\t128\t96\t14\t-\n"
                "kitti\tdots_left.pgm\tdots_right.pgm\tdots_gt16.pgm\t256\t16\t128\t96\t14\t-\n"
                "blind\tdots_left.pgm\tdots_right.pgm\t-\t-\t-\t128\t96\t-\t-\n");
  const auto result =
      run_marsokhod("eval stereo '" + file.string() + "' --json --max-disparity 20");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json json = nlohmann::json::parse(result.out);
  ASSERT_EQ(json["pairs"].size(), 3U);
  const nlohmann::json& eight = json["pairs"][0];
  const nlohmann::json& kitti = json["pairs"][1];
  const nlohmann::json& blind = json["pairs"][2];
  EXPECT_EQ(eight["name"], "eight");
  // The same truth in both encodings gives the same score; the left strip the right camera
  // cannot see (6 columns) and the occluded band are filled, so a few percent are bad at most.
  EXPECT_DOUBLE_EQ(eight["bad_percent"].get<double>(), kitti["bad_percent"].get<double>());
  EXPECT_LT(eight["bad_percent"].get<double>(), 5.0);
  EXPECT_TRUE(blind["bad_percent"].is_null());
  EXPECT_GT(blind["seconds"].get<double>(), 0.0);
  EXPECT_NE(blind["note"].get<std::string>().find("no ground truth"), std::string::npos);
  EXPECT_EQ(blind["max_disparity"], 20);
  EXPECT_DOUBLE_EQ(json["mean_bad_percent"].get<double>(), eight["bad_percent"].get<double>());
}

TEST_F(EvalStereoCommand, WritesEachPairsDisparityWithOut) {
  const fs::path file =
      index(kHeader + "eight\tdots_left.pgm\tdots_right.pgm\tdots_gt.pgm\t4\t8\t128\t96\t14\t-\n");
  const fs::path out = dir_ / "out";
  const auto result =
      run_marsokhod("eval stereo '" + file.string() + "' --out '" + out.string() + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("eight"), std::string::npos);
  const imaging::Image<float> disparity = imaging::read_pfm(out / "eight_disparity.pfm");
  EXPECT_EQ(disparity.width(), 128);
  EXPECT_TRUE(fs::exists(out / "eight_disparity.png"));
}

// Runs the command on an index and expects exit 1 with every fragment in the message.
void expect_index_error(const fs::path& file, std::initializer_list<std::string> fragments) {
  const auto result = run_marsokhod("eval stereo '" + file.string() + "'");
  EXPECT_EQ(result.exit_code, 1) << result.out;
  for (const std::string& fragment : fragments)
    EXPECT_NE(result.err.find(fragment), std::string::npos) << result.err;
}

TEST_F(EvalStereoCommand, AHeaderWithoutARequiredColumnIsRefused) {
  expect_index_error(index("name\tleft\tright\tgt\tgt_scale\tgt_bits\twidth\theight\n"),
                     {"PAIRS.tsv:1", "max_gt_disp_px"});
}

TEST_F(EvalStereoCommand, AMissingImageFileIsNamedWithItsLine) {
  expect_index_error(
      index(kHeader + "eight\tdots_left.pgm\tnowhere.pgm\tdots_gt.pgm\t4\t8\t128\t96\t14\t-\n"),
      {"PAIRS.tsv:2", "nowhere.pgm", "does not exist"});
}

TEST_F(EvalStereoCommand, AnImageOfAnotherSizeThanTheIndexSaysIsRefused) {
  expect_index_error(
      index(kHeader + "eight\tdots_left.pgm\tdots_right.pgm\tdots_gt.pgm\t4\t8\t120\t96\t14\t-\n"),
      {"PAIRS.tsv:2", "128x96", "120x96"});
}

TEST_F(EvalStereoCommand, GroundTruthOfAnotherDepthThanGtBitsIsRefused) {
  expect_index_error(
      index(kHeader +
            "eight\tdots_left.pgm\tdots_right.pgm\tdots_gt.pgm\t256\t16\t128\t96\t14\t-\n"),
      {"PAIRS.tsv:2", "16-bit"});
}

TEST_F(EvalStereoCommand, AShortLineAndABadNumberAreRefused) {
  expect_index_error(index(kHeader + "eight\tdots_left.pgm\tdots_right.pgm\n"),
                     {"PAIRS.tsv:2", "missing"});
  expect_index_error(
      index(kHeader +
            "eight\tdots_left.pgm\tdots_right.pgm\tdots_gt.pgm\tfour\t8\t128\t96\t14\t-\n"),
      {"PAIRS.tsv:2", "gt_scale", "four"});
}

// Every file under `dir`, to tell that a run wrote nothing there.
std::vector<fs::path> files_under(const fs::path& dir) {
  std::vector<fs::path> files;
  if (fs::exists(dir))
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir))
      files.push_back(entry.path());
  return files;
}

// The example: a pair named ../../x once wrote ../../x_disparity.pfm beside --out, exit 0.
TEST_F(EvalStereoCommand, APairNameThatWouldLeaveTheOutputFolderIsRefusedAndNothingIsWritten) {
  const fs::path out = dir_ / "deep" / "out";
  for (const std::string& name :
       std::vector<std::string>{"../../x", "../x", (dir_ / "abs").string()}) {
    const fs::path file =
        index(kHeader + name + "\tdots_left.pgm\tdots_right.pgm\t-\t-\t-\t128\t96\t14\t-\n");
    const auto before = files_under(dir_);
    const auto result =
        run_marsokhod("eval stereo '" + file.string() + "' --out '" + out.string() + "'");
    EXPECT_EQ(result.exit_code, 1) << name;
    EXPECT_NE(result.err.find(file.string() + ":2: pair name '" + name + "'"), std::string::npos)
        << result.err;
    EXPECT_EQ(files_under(dir_), before) << name;
  }
}

TEST_F(EvalStereoCommand, TwoPairsOfOneNameAreRefusedBeforeEitherOverwritesTheOther) {
  const std::string line = "twin\tdots_left.pgm\tdots_right.pgm\t-\t-\t-\t128\t96\t14\t-\n";
  expect_index_error(index(kHeader + line + line), {"PAIRS.tsv:3", "'twin'", "line 2"});
}

// gt_scale inf once scored a perfect 0 %, max_gt_disp_px nan a search range of -2147483648 px.
TEST_F(EvalStereoCommand, NonFiniteNumbersInTheIndexAreRefusedNamingTheColumn) {
  expect_index_error(
      index(kHeader +
            "eight\tdots_left.pgm\tdots_right.pgm\tdots_gt.pgm\tinf\t8\t128\t96\t14\t-\n"),
      {"PAIRS.tsv:2", "gt_scale", "'inf'"});
  for (const char* largest : {"nan", "1e309", "1e300", "-5"}) {
    const auto result =
        run_marsokhod("eval stereo '" +
                      index(kHeader + "eight\tdots_left.pgm\tdots_right.pgm\t-\t-\t-\t128\t96\t" +
                            largest + "\t-\n")
                          .string() +
                      "'");
    EXPECT_EQ(result.exit_code, 1) << largest;
    EXPECT_NE(result.err.find("PAIRS.tsv:2: "), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("max_gt_disp_px"), std::string::npos) << result.err;
    EXPECT_EQ(result.err.find("-2147483648"), std::string::npos) << result.err;
  }
}

TEST_F(EvalStereoCommand, OptionsThatDoNotSuitAPairNameItsLine) {
  const fs::path file =
      index(kHeader + "eight\tdots_left.pgm\tdots_right.pgm\t-\t-\t-\t128\t96\t-\t-\n");
  // 6 pyramid layers would leave a 4x3 top layer of a 128x96 image.
  const auto levels = run_marsokhod("eval stereo '" + file.string() + "' --levels 6");
  EXPECT_EQ(levels.exit_code, 1);
  EXPECT_NE(levels.err.find("PAIRS.tsv:2: "), std::string::npos) << levels.err;
  EXPECT_NE(levels.err.find("pyramid layers"), std::string::npos) << levels.err;
  const auto range = run_marsokhod("eval stereo '" + file.string() + "' --max-disparity 4096");
  EXPECT_EQ(range.exit_code, 1);
  EXPECT_NE(range.err.find("PAIRS.tsv:2: search range 4096 px (--max-disparity) does not fit in "
                           "an image 128 px wide"),
            std::string::npos)
      << range.err;
}

TEST_F(EvalStereoCommand, AnOutThatIsAnExistingFileIsAnErrorNamingIt) {
  const fs::path file =
      index(kHeader + "eight\tdots_left.pgm\tdots_right.pgm\t-\t-\t-\t128\t96\t14\t-\n");
  const fs::path taken = dir_ / "taken";
  std::ofstream(taken) << "x";
  const auto result =
      run_marsokhod("eval stereo '" + file.string() + "' --out '" + taken.string() + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find(taken.string()), std::string::npos) << result.err;
}

TEST(EvalStereoRealData, ReportsEveryPairAndAMeanBelowTheSgbmPeer) {
  const fs::path tsv = fs::path(MARSOKHOD_SHARED_DATA) / "stereo" / "PAIRS.tsv";
  if (!fs::exists(tsv))
    GTEST_SKIP() << "no " << tsv;
  const auto result = run_marsokhod("eval stereo '" + tsv.string() + "' --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json json = nlohmann::json::parse(result.out);
  ASSERT_EQ(json["pairs"].size(), 5U);
  EXPECT_EQ(json["pairs"][0]["name"], "tsukuba");
  // tsukuba_nonocc.pgm sits beside its ground truth: only tsukuba has the non-occluded figure.
  EXPECT_TRUE(json["pairs"][0].contains("bad_percent_nonocc"));
  EXPECT_FALSE(json["pairs"][1].contains("bad_percent_nonocc"));
  EXPECT_TRUE(json["pairs"][4]["bad_percent"].is_null());
  // StereoSGBM's mean over the four pairs with ground truth, from the data README.
  EXPECT_LE(json["mean_bad_percent"].get<double>(), 17.4);
}

} // namespace
} // namespace marsokhod
