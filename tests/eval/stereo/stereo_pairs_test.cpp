// The PAIRS.tsv reader: entries with and without ground truth, and errors naming file and line.
#include "marsokhod/eval/common/errors.hpp"
#include "marsokhod/eval/stereo/stereo_pairs.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace marsokhod::eval {
namespace {

namespace fs = std::filesystem;

const std::string kHeader = "name\tleft\tright\tgt\tgt_scale(disp=value/scale)\tgt_bits\twidth\t"
                            "height\tmax_gt_disp_px\tnotes\n";

// A folder holding the (empty) files the indexes name; only their existence is read.
class StereoPairs : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("marsokhod-stereo-pairs-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    for (const char* name : {"l.pgm", "r.pgm", "gt.pgm"})
      std::ofstream(dir_ / name) << "";
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path index(const std::string& body) const {
    const fs::path file = dir_ / "PAIRS.tsv";
    std::ofstream(file, std::ios::binary) << body;
    return file;
  }

  // The message read_stereo_pairs throws for `file`.
  static std::string error_of(const fs::path& file) {
    try {
      read_stereo_pairs(file);
    } catch (const EvaluationError& error) {
      return error.what();
    }
    ADD_FAILURE() << "no EvaluationError for " << file;
    return {};
  }

  fs::path dir_;
};

TEST_F(StereoPairs, ReadsEntriesWithAndWithoutGroundTruthSkippingCommentsAndBlankLines) {
  const fs::path file =
      index(kHeader + "# a comment\n" + "a\tl.pgm\tr.pgm\tgt.pgm\t256\t16\t64\t48\t14.5\tnote\r\n" +
            "\n" + "b\tl.pgm\tr.pgm\t-\t-\t-\t32\t24\t-\t-\n");
  const std::vector<StereoPairEntry> pairs = read_stereo_pairs(file);
  ASSERT_EQ(pairs.size(), 2U);
  EXPECT_EQ(pairs[0].name, "a");
  EXPECT_EQ(pairs[0].left, dir_ / "l.pgm");
  EXPECT_EQ(pairs[0].right, dir_ / "r.pgm");
  ASSERT_TRUE(pairs[0].truth.has_value());
  EXPECT_EQ(*pairs[0].truth, dir_ / "gt.pgm");
  EXPECT_DOUBLE_EQ(pairs[0].truth_scale, 256.0);
  EXPECT_EQ(pairs[0].truth_bits, 16);
  EXPECT_EQ(pairs[0].width, 64);
  EXPECT_EQ(pairs[0].height, 48);
  ASSERT_TRUE(pairs[0].max_truth_disparity.has_value());
  EXPECT_DOUBLE_EQ(*pairs[0].max_truth_disparity, 14.5);
  EXPECT_EQ(pairs[0].line, 3);
  EXPECT_EQ(pairs[1].name, "b");
  EXPECT_FALSE(pairs[1].truth.has_value());
  EXPECT_FALSE(pairs[1].max_truth_disparity.has_value());
  EXPECT_EQ(pairs[1].line, 5);
}

TEST_F(StereoPairs, AMissingFileAnEmptyIndexAndAnIndexWithoutPairsAreRefused) {
  const fs::path nowhere = dir_ / "NOWHERE.tsv";
  EXPECT_EQ(error_of(nowhere), nowhere.string() + ": cannot open the pair index");
  const fs::path empty = index("");
  EXPECT_EQ(error_of(empty), empty.string() + ": the pair index is empty");
  const fs::path header_only = index(kHeader + "# nothing\n");
  EXPECT_EQ(error_of(header_only), header_only.string() + ": the pair index lists no pair");
}

TEST_F(StereoPairs, AHeaderWithoutARequiredColumnNamesIt) {
  const fs::path file = index("name\tleft\tright\tgt\tgt_scale\tgt_bits\twidth\theight\n");
  EXPECT_EQ(error_of(file), file.string() + ":1: the header lacks the column 'max_gt_disp_px'");
}

TEST_F(StereoPairs, LineErrorsNameTheLineAndTheProblem) {
  const fs::path short_line = index(kHeader + "a\tl.pgm\tr.pgm\n");
  EXPECT_EQ(error_of(short_line),
            short_line.string() + ":2: has 3 fields, the column 'width' is missing");
  const fs::path missing = index(kHeader + "a\tl.pgm\tnone.pgm\t-\t-\t-\t32\t24\t-\t-\n");
  EXPECT_EQ(error_of(missing), missing.string() + ":2: right file " + (dir_ / "none.pgm").string() +
                                   " does not exist");
  const fs::path unnamed = index(kHeader + "\tl.pgm\tr.pgm\t-\t-\t-\t32\t24\t-\t-\n");
  EXPECT_EQ(error_of(unnamed), unnamed.string() + ":2: the pair has no name");
}

TEST_F(StereoPairs, BadNumbersSizesScalesAndDepthsAreRefused) {
  const fs::path word = index(kHeader + "a\tl.pgm\tr.pgm\t-\t-\t-\twide\t24\t-\t-\n");
  EXPECT_EQ(error_of(word), word.string() + ":2: column 'width' is not a number: 'wide'");
  const fs::path size = index(kHeader + "a\tl.pgm\tr.pgm\t-\t-\t-\t0\t24\t-\t-\n");
  EXPECT_EQ(error_of(size), size.string() + ":2: size 0x24 is not positive");
  const fs::path scale = index(kHeader + "a\tl.pgm\tr.pgm\tgt.pgm\t0\t8\t32\t24\t-\t-\n");
  EXPECT_EQ(error_of(scale), scale.string() + ":2: gt_scale 0 is not positive");
  const fs::path bits = index(kHeader + "a\tl.pgm\tr.pgm\tgt.pgm\t4\t12\t32\t24\t-\t-\n");
  EXPECT_EQ(error_of(bits), bits.string() + ":2: gt_bits 12 is neither 8 nor 16");
}

} // namespace
} // namespace marsokhod::eval
