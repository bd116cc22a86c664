// Runs the built `marsokhod image` command on files written here and checks exit codes,
// messages and output.

#include "marsokhod/imaging/image/image_io.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

class ImageCommand : public ::testing::Test {
protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() /
              (std::string("marsokhod_cli_") + info->test_suite_name() + "_" + info->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(folder_, ignored);
  }

  fs::path file(const std::string& leaf) const { return folder_ / leaf; }

  fs::path write(const std::string& leaf, const Bytes& bytes) const {
    std::ofstream stream(file(leaf), std::ios::binary);
    stream.write(reinterpret_cast<const char*>(bytes.data()),
                 static_cast<std::streamsize>(bytes.size()));
    return file(leaf);
  }

  fs::path write(const std::string& leaf, std::string_view text) const {
    return write(leaf, Bytes(text.begin(), text.end()));
  }

  Bytes read(const fs::path& path) const {
    std::ifstream stream(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>());
  }

  CommandResult run(const std::string& arguments) const {
    const fs::path out = file("stdout.txt");
    const fs::path err = file("stderr.txt");
    const std::string command = fmt::format("'{}' {} > '{}' 2> '{}'", MARSOKHOD_BINARY, arguments,
                                            out.string(), err.string());
    const int status = std::system(command.c_str());
    CommandResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    const Bytes out_bytes = read(out);
    const Bytes err_bytes = read(err);
    result.out.assign(out_bytes.begin(), out_bytes.end());
    result.err.assign(err_bytes.begin(), err_bytes.end());
    return result;
  }

  static std::string quoted(const fs::path& path) { return fmt::format("'{}'", path.string()); }

  fs::path folder_;
};

// A file that must be refused: exit 1 and "marsokhod: error: <path>: ...<problem>...".
void expect_bad_file(const CommandResult& run, const fs::path& path, std::string_view problem) {
  EXPECT_EQ(run.exit_code, 1) << run.err;
  const std::string prefix = fmt::format("marsokhod: error: {}: ", path.string());
  EXPECT_NE(run.err.find(prefix), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(problem), std::string::npos) << "no \"" << problem << "\" in " << run.err;
}

Bytes text_bytes(std::string_view text, std::initializer_list<int> raw = {}) {
  Bytes bytes(text.begin(), text.end());
  for (int value : raw)
    bytes.push_back(static_cast<std::uint8_t>(value));
  return bytes;
}

TEST_F(ImageCommand, HelpExitsZero) {
  const CommandResult help = run("image --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("info"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("convert"), std::string::npos) << help.out;
  EXPECT_EQ(run("image info --help").exit_code, 0);
  const CommandResult convert_help = run("image convert --help");
  EXPECT_EQ(convert_help.exit_code, 0);
  EXPECT_NE(convert_help.out.find("--colour"), std::string::npos) << convert_help.out;
}

TEST_F(ImageCommand, MissingArgumentExitsTwo) {
  EXPECT_EQ(run("image").exit_code, 2);
  EXPECT_EQ(run("image info").exit_code, 2);
  const fs::path input = write("in.pgm", text_bytes("P5 1 1 255\n", {0}));
  EXPECT_EQ(run("image convert " + quoted(input)).exit_code, 2);
}

TEST_F(ImageCommand, ColourOptionsWithoutColourExitTwo) {
  const fs::path input = write("in.pgm", text_bytes("P5 1 1 255\n", {0}));
  EXPECT_EQ(
      run("image convert " + quoted(input) + " " + quoted(file("o.png")) + " --min 1").exit_code,
      2);
  EXPECT_FALSE(fs::exists(file("o.png")));
}

TEST_F(ImageCommand, MinNotBelowMaxExitsTwo) {
  const fs::path input = write("in.pgm", text_bytes("P5 1 1 255\n", {0}));
  const CommandResult result = run("image convert " + quoted(input) + " " + quoted(file("o.png")) +
                                   " --colour --min 5 --max 1");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--min 5 must be below --max 1"), std::string::npos) << result.err;
  const CommandResult nan = run(
      fmt::format("image convert {} {} --colour --min nan", quoted(input), quoted(file("o.png"))));
  EXPECT_EQ(nan.exit_code, 2) << nan.err;
  EXPECT_FALSE(fs::exists(file("o.png")));
}

TEST_F(ImageCommand, MalformedFilesExitOneNamingFileAndProblem) {
  struct Case {
    std::string leaf;
    Bytes bytes;
    std::string problem;
  };
  Bytes png;
  {
    imaging::Image<std::uint8_t> image(8, 8, 1, 100);
    imaging::write_image(file("valid.png"), image.view());
    png = read(file("valid.png"));
  }
  Bytes truncated_png(png.begin(), png.begin() + static_cast<std::ptrdiff_t>(png.size() / 2));
  Bytes bad_crc_png = png;
  bad_crc_png[8 + 8 + 13] ^= 0x40; // first byte of the IHDR CRC
  Bytes huge_pgm = text_bytes("P5 16385 16385 255\n");
  const std::vector<Case> cases = {
      {"truncated.pgm", text_bytes("P5 4 4 255\n", {1, 2, 3}), "truncated pixel data"},
      {"magic.pgm", text_bytes("P3 1 1 255\n1 2 3\n"), "unsupported netpbm format P3"},
      {"unknown.pgm", text_bytes("GIF89a"), "unknown image format"},
      {"maxval0.pgm", text_bytes("P5 1 1 0\n", {0}), "maxval 0 is out of range"},
      {"maxval_big.pgm", text_bytes("P5 1 1 65536\n", {0, 0}), "maxval 65536 is out of range"},
      {"width0.pgm", text_bytes("P5 0 1 255\n"), "width 0 is out of range"},
      {"height0.ppm", text_bytes("P6 1 0 255\n"), "height 0 is out of range"},
      {"wide.pgm", huge_pgm, "width 16385 is out of range"},
      {"tall.pgm", text_bytes("P5 1 99999 255\n"), "height 99999 is out of range"},
      {"comment.pgm", text_bytes("P5 1 1 # unterminated"), "comment runs to the end"},
      {"glued.pgm", text_bytes("P5 1 1 255#c\n", {7}), "expected one whitespace byte after maxval"},
      {"negative.pgm", text_bytes("P5 -1 1 255\n"), "expected width"},
      {"garbage.pgm", text_bytes("P5 1 1 25x\n"), "expected one whitespace byte after maxval"},
      {"overflow.pgm", text_bytes("P5 4294967297 1 255\n", {0}),
       "width 4294967297 is out of range"},
      {"scale0.pfm", text_bytes("Pf 1 1 0\n", {0, 0, 0, 0}), "scale 0"},
      {"scale_text.pfm", text_bytes("Pf 1 1 big\n", {0, 0, 0, 0}), "scale 'big'"},
      {"truncated.pfm", text_bytes("Pf 2 1 -1\n", {0, 0, 0, 0}), "truncated pixel data"},
      {"truncated.png", truncated_png, "truncated"},
      {"crc.png", bad_crc_png, "CRC"},
      {"empty.pgm", {}, "empty file"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.leaf);
    const fs::path path = write(c.leaf, c.bytes);
    expect_bad_file(run("image info " + quoted(path)), path, c.problem);
    expect_bad_file(run("image convert " + quoted(path) + " " + quoted(file("out.pgm"))), path,
                    c.problem);
  }
  EXPECT_FALSE(fs::exists(file("out.pgm")));
}

TEST_F(ImageCommand, MissingFileAndDirectoryExitOne) {
  expect_bad_file(run("image info " + quoted(file("absent.pgm"))), file("absent.pgm"),
                  "no such file");
  fs::create_directory(file("folder.pgm"));
  expect_bad_file(run("image info " + quoted(file("folder.pgm"))), file("folder.pgm"),
                  "is a directory");
}

TEST_F(ImageCommand, InfoJsonDescribesTheImage) {
  // Samples 0, 10, 250 and 40: mean 75.
  const fs::path input = write("g.pgm", text_bytes("P5 2 2 255\n", {0, 10, 250, 40}));
  const CommandResult result = run("image info --json " + quoted(input));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json info = nlohmann::json::parse(result.out);
  EXPECT_EQ(info["format"], "pgm");
  EXPECT_EQ(info["width"], 2);
  EXPECT_EQ(info["height"], 2);
  EXPECT_EQ(info["channels"], 1);
  EXPECT_EQ(info["bit_depth"], 8);
  EXPECT_EQ(info["min"], 0.0);
  EXPECT_EQ(info["max"], 250.0);
  EXPECT_EQ(info["mean"], 75.0);
  EXPECT_EQ(info["non_finite"], 0);
}

TEST_F(ImageCommand, InfoCountsNonFiniteFloatsSeparately) {
  imaging::Image<float> field(2, 2);
  field(0, 0) = std::numeric_limits<float>::infinity();
  field(1, 0) = std::numeric_limits<float>::quiet_NaN();
  field(0, 1) = -1.5F;
  field(1, 1) = 4.5F;
  imaging::write_image(file("d.pfm"), field.view());
  const CommandResult result = run("image info --json " + quoted(file("d.pfm")));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json info = nlohmann::json::parse(result.out);
  EXPECT_EQ(info["format"], "pfm");
  EXPECT_EQ(info["bit_depth"], 32);
  EXPECT_EQ(info["non_finite"], 2);
  EXPECT_EQ(info["min"], -1.5);
  EXPECT_EQ(info["max"], 4.5);
  EXPECT_EQ(info["mean"], 1.5);
}

TEST_F(ImageCommand, InfoTextNamesEachField) {
  const fs::path input = write("c.ppm", text_bytes("P6 1 1 65535\n", {0, 1, 0, 2, 0, 3}));
  const CommandResult result = run("image info " + quoted(input));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* line : {"format:     ppm", "width:      1", "channels:   3", "bit depth:  16",
                           "min:        1", "max:        3", "mean:       2", "non-finite: 0"})
    EXPECT_NE(result.out.find(line), std::string::npos) << "no \"" << line << "\" in\n"
                                                        << result.out;
}

// The largest memory `image info` took: run directly, so wait4 reports the command alone.
long peak_kib_of_info(const fs::path& image, const fs::path& out) {
  const pid_t child = fork();
  if (child == 0) {
    const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::execl(MARSOKHOD_BINARY, MARSOKHOD_BINARY, "image", "info", "--json", image.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  if (child < 0 || ::wait4(child, &status, 0, &usage) != child || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0)
    return -1;
  return usage.ru_maxrss;
}

// 16384 x 2048 16-bit RGB: 201 MB of pixels, which the image in memory doubled when info
// read it whole. The last sample is 65535, so the figures need the last strip too.
TEST_F(ImageCommand, InfoOnAVeryLargePpmTakesLittleMemory) {
  const std::string header = "P6 16384 2048 65535\n";
  const fs::path input = write("large.ppm", header);
  const std::uint64_t pixels = std::uint64_t{16384} * 2048;
  ASSERT_EQ(::truncate(input.c_str(), static_cast<off_t>(header.size() + pixels * 6 - 2)), 0);
  std::ofstream(input, std::ios::binary | std::ios::app) << '\xff' << '\xff';
  const long peak_kib = peak_kib_of_info(input, file("info.json"));
  ASSERT_GT(peak_kib, 0) << "image info failed";
  EXPECT_LT(peak_kib, 64 * 1024) << "KiB";
  const Bytes out = read(file("info.json"));
  const nlohmann::json info = nlohmann::json::parse(std::string(out.begin(), out.end()));
  EXPECT_EQ(info["width"], 16384);
  EXPECT_EQ(info["height"], 2048);
  EXPECT_EQ(info["bit_depth"], 16);
  EXPECT_EQ(info["min"], 0.0);
  EXPECT_EQ(info["max"], 65535.0);
  EXPECT_EQ(info["mean"], 65535.0 / static_cast<double>(pixels * 3));
}

TEST_F(ImageCommand, ConvertKeepsPixelsAcrossFormats) {
  const fs::path input = write("g.pgm", text_bytes("P5 3 1 65535\n", {0, 1, 0x80, 0, 0xff, 0xff}));
  ASSERT_EQ(run("image convert " + quoted(input) + " " + quoted(file("g.png"))).exit_code, 0);
  const imaging::AnyImage back = imaging::read_image(file("g.png"));
  const auto& image = std::get<imaging::Image<std::uint16_t>>(back);
  EXPECT_EQ(image(0, 0), 1);
  EXPECT_EQ(image(1, 0), 0x8000);
  EXPECT_EQ(image(2, 0), 0xffff);
  ASSERT_EQ(run("image convert " + quoted(input) + " " + quoted(file("g.pfm"))).exit_code, 0);
  EXPECT_EQ(imaging::read_pfm(file("g.pfm"))(1, 0), 32768.0F);
}

TEST_F(ImageCommand, ConvertColourRendersAPictureWithLegend) {
  imaging::Image<float> field(64, 48);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x)
      field(x, y) = static_cast<float>(x);
  imaging::write_image(file("d.pfm"), field.view());
  const CommandResult result =
      run("image convert " + quoted(file("d.pfm")) + " " + quoted(file("d.png")) +
          " --colour --min 0 --max 63 --unit px --title disparity");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const imaging::AnyImage picture = imaging::read_image(file("d.png"));
  const auto& rgb = std::get<imaging::Image<std::uint8_t>>(picture);
  EXPECT_EQ(rgb.channels(), 3);
  EXPECT_GT(rgb.width(), 64);
  // Column 0 holds the minimum: viridis' first colour (68, 1, 84).
  EXPECT_EQ(rgb(0, 0, 0), 68);
  EXPECT_EQ(rgb(0, 0, 1), 1);
  EXPECT_EQ(rgb(0, 0, 2), 84);
}

TEST_F(ImageCommand, ConvertColourNeedsOneChannel) {
  const fs::path input = write("c.ppm", text_bytes("P6 1 1 255\n", {1, 2, 3}));
  const CommandResult result =
      run("image convert " + quoted(input) + " " + quoted(file("c.png")) + " --colour");
  expect_bad_file(result, input, "--colour needs a one-channel image");
}

TEST_F(ImageCommand, ConvertFloatToIntegerFormatIsRefused) {
  imaging::write_image(file("d.pfm"), imaging::Image<float>(2, 2).view());
  const CommandResult result =
      run("image convert " + quoted(file("d.pfm")) + " " + quoted(file("d.png")));
  expect_bad_file(result, file("d.png"), "float pixels go to .pfm");
}

TEST_F(ImageCommand, ConvertIntoMissingFolderNamesIt) {
  const fs::path input = write("g.pgm", text_bytes("P5 1 1 255\n", {9}));
  const fs::path output = file("missing") / "g.png";
  expect_bad_file(run("image convert " + quoted(input) + " " + quoted(output)), output,
                  "does not exist");
}

} // namespace
} // namespace marsokhod::apps
