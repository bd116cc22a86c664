// The PAIRS.tsv reader: entries with and without ground truth, and errors naming file and line.
#include "marsokhod/eval/common/errors.hpp"
#include "marsokhod/eval/stereo/stereo_pairs.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
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
  EXPECT_EQ(error_of(nowhere),
            nowhere.string() + ": cannot open the pair index: No such file or directory");
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
  EXPECT_EQ(error_of(word), word.string() + ":2: column 'width' is not a whole number: 'wide'");
  const fs::path size = index(kHeader + "a\tl.pgm\tr.pgm\t-\t-\t-\t0\t24\t-\t-\n");
  EXPECT_EQ(error_of(size), size.string() + ":2: size 0x24 is not positive");
  const fs::path scale = index(kHeader + "a\tl.pgm\tr.pgm\tgt.pgm\t0\t8\t32\t24\t-\t-\n");
  EXPECT_EQ(error_of(scale), scale.string() + ":2: gt_scale 0 is not positive");
  const fs::path bits = index(kHeader + "a\tl.pgm\tr.pgm\tgt.pgm\t4\t12\t32\t24\t-\t-\n");
  EXPECT_EQ(error_of(bits), bits.string() + ":2: gt_bits 12 is neither 8 nor 16");
}

// The index is read through the bounded reader: only a regular file of at most 16 MiB, and
// never a wait on a FIFO or an endless read of a device.
TEST_F(StereoPairs, AnIndexThatIsNotARegularFileOrTooLargeIsRefusedNamingIt) {
  const fs::path fifo = dir_ / "fifo.tsv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(error_of(fifo), fifo.string() + ": is a FIFO; a pair index must be a regular file");
  EXPECT_EQ(error_of("/dev/zero"), "/dev/zero: is a device; a pair index must be a regular file");
  EXPECT_EQ(error_of(dir_),
            dir_.string() + ": is a directory; a pair index must be a regular file");
  // A sparse file: its size is what counts, without writing 3 GB.
  const fs::path huge = dir_ / "huge.tsv";
  std::ofstream(huge) << kHeader;
  fs::resize_file(huge, std::uintmax_t{3} << 30);
  EXPECT_EQ(error_of(huge),
            huge.string() + ": is 3221225472 bytes; a pair index is at most 16 MiB");
}

// Numbers are whole or finite: "inf" once scored a perfect 0 %, NaN gave a search range of
// -2147483648 px.
TEST_F(StereoPairs, NonFiniteAndOutOfRangeNumbersAreRefusedNamingColumnAndLine) {
  const auto line = [&](const std::string& scale, const std::string& width,
                        const std::string& largest) {
    return index(kHeader + "# first\na\tl.pgm\tr.pgm\tgt.pgm\t" + scale + "\t8\t" + width +
                 "\t24\t" + largest + "\t-\n");
  };
  const fs::path inf_scale = line("inf", "32", "14");
  EXPECT_EQ(error_of(inf_scale),
            inf_scale.string() + ":3: column 'gt_scale' is not a finite number: 'inf'");
  const fs::path nan_largest = line("4", "32", "nan");
  EXPECT_EQ(error_of(nan_largest),
            nan_largest.string() + ":3: column 'max_gt_disp_px' is not a finite number: 'nan'");
  for (const char* text : {"1e309", "-inf", "1x", "", "+4", "0x10"}) {
    EXPECT_NE(error_of(line(text, "32", "14")).find(":3: column 'gt_scale' is not a finite"),
              std::string::npos)
        << text;
  }
  const fs::path tiny_scale = line("0.0001", "32", "14");
  EXPECT_EQ(error_of(tiny_scale),
            tiny_scale.string() + ":3: gt_scale 0.0001 is not between 0.001 and 65536");
  const fs::path negative_largest = line("4", "32", "-3");
  EXPECT_EQ(error_of(negative_largest),
            negative_largest.string() +
                ":3: max_gt_disp_px -3 is not above 0 and at most 16384 px");
  EXPECT_NE(error_of(line("4", "32", "1e300")).find("max_gt_disp_px 1e+300 is not above 0"),
            std::string::npos);
  // 2^32 + 32 would wrap to 32 as a 32-bit int; the image side limit is 16384.
  const fs::path wrapped = line("4", "4294967328", "14");
  EXPECT_EQ(error_of(wrapped),
            wrapped.string() + ":3: column 'width' is not a whole number: '4294967328'");
  const fs::path wide = line("4", "16385", "14");
  EXPECT_EQ(error_of(wide),
            wide.string() + ":3: size 16385x24 exceeds the largest image side, 16384 px");
  EXPECT_EQ(read_stereo_pairs(line("4", "16384", "16384")).front().width, 16384);
  EXPECT_DOUBLE_EQ(read_stereo_pairs(line("0.001", "32", "14")).front().truth_scale, 0.001);
  EXPECT_DOUBLE_EQ(read_stereo_pairs(line("65536", "32", "14")).front().truth_scale, 65536.0);
}

// A pair name becomes <name>_disparity.pfm inside --out: it must be one plain file name.
TEST_F(StereoPairs, PairNamesThatWouldLeaveTheOutputFolderAreRefused) {
  const auto named = [&](const std::string& name) {
    return index(kHeader + name + "\tl.pgm\tr.pgm\t-\t-\t-\t32\t24\t-\t-\n");
  };
  const fs::path up = named("../../x");
  EXPECT_EQ(error_of(up), up.string() +
                              ":2: pair name '../../x' has a '..' part; it must stay inside "
                              "the output folder");
  const fs::path absolute = named("/tmp/x");
  EXPECT_EQ(error_of(absolute), absolute.string() +
                                    ":2: pair name '/tmp/x' is an absolute path; it must stay "
                                    "inside the output folder");
  const fs::path nested = named("a/b");
  EXPECT_EQ(error_of(nested),
            nested.string() + ":2: pair name 'a/b' holds a '/'; it names files in one folder");
  std::vector<std::string> taken;
  for (const char* name : {"..", ".", "a/../b", "x\x01y"})
    if (error_of(named(name)).find(":2: pair name '") == std::string::npos)
      taken.push_back(name);
  EXPECT_EQ(taken, std::vector<std::string>{});
  EXPECT_EQ(read_stereo_pairs(named("tsukuba.v2-left")).front().name, "tsukuba.v2-left");
}

TEST_F(StereoPairs, ADuplicatePairNameIsRefusedNamingBothLines) {
  const std::string entry = "a\tl.pgm\tr.pgm\t-\t-\t-\t32\t24\t-\t-\n";
  const fs::path file = index(kHeader + entry + "b" + entry.substr(1) + entry);
  EXPECT_EQ(error_of(file), file.string() + ":4: pair name 'a' is already used on line 2");
}

// Image paths are inputs: anywhere (an absolute path is fine), but regular files only.
TEST_F(StereoPairs, ImagePathsMayBeAnywhereButMustBeRegularFiles) {
  const fs::path elsewhere = dir_ / "sub" / "left.pgm";
  fs::create_directories(elsewhere.parent_path());
  std::ofstream(elsewhere) << "";
  const fs::path absolute =
      index(kHeader + "a\t" + elsewhere.string() + "\tsub/../r.pgm\t-\t-\t-\t32\t24\t-\t-\n");
  const std::vector<StereoPairEntry> pairs = read_stereo_pairs(absolute);
  EXPECT_EQ(pairs.front().left, elsewhere);
  const fs::path folder = index(kHeader + "a\tsub\tr.pgm\t-\t-\t-\t32\t24\t-\t-\n");
  EXPECT_EQ(error_of(folder), folder.string() + ":2: left file " + (dir_ / "sub").string() +
                                  " is not a regular file");
  const fs::path device = index(kHeader + "a\tl.pgm\t/dev/zero\t-\t-\t-\t32\t24\t-\t-\n");
  EXPECT_EQ(error_of(device), device.string() + ":2: right file /dev/zero is not a regular file");
  const fs::path empty = index(kHeader + "a\t\tr.pgm\t-\t-\t-\t32\t24\t-\t-\n");
  EXPECT_EQ(error_of(empty), empty.string() + ":2: column 'left' is empty; it names a file");
}

} // namespace
} // namespace marsokhod::eval
