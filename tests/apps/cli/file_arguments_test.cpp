// Tests: file and folder arguments of the wrong kind (a folder for a file, a file for a folder,
// a full disk) are exit 1 with a message naming the path and the problem.
#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using marsokhod::testing::CommandResult;
using marsokhod::testing::quoted;
using marsokhod::testing::run_marsokhod;

// One small rendered scene, a regular file and a folder to misuse.
class FileArguments : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("marsokhod-file-arguments-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "folder");
    std::ofstream(dir_ / "file") << "not a folder\n";
    const auto world = run_marsokhod("world --size 64 --out " + quoted(dir_ / "w"));
    ASSERT_EQ(world.exit_code, 0) << world.err;
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static std::string pair() {
    return quoted(dir_ / "w" / "left.pgm") + " " + quoted(dir_ / "w" / "right.pgm");
  }

  static fs::path dir_;
};

fs::path FileArguments::dir_;

void expect_error_naming(const CommandResult& result, const fs::path& path,
                         const std::string& problem) {
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.err.find(path.string() + ": "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(problem), std::string::npos) << result.err;
}

TEST_F(FileArguments, AFolderGivenForAnInputFileIsNamedAsAFolder) {
  const fs::path folder = dir_ / "folder";
  const std::string out = " --out " + quoted(dir_ / "n");
  // The scene reader's own message may vary; the apps name the file whatever it says.
  const auto scene = run_marsokhod("nav " + pair() + out + " --scene " + quoted(folder));
  EXPECT_EQ(scene.exit_code, 1);
  EXPECT_EQ(scene.err.rfind("marsokhod: error: " + folder.string() + ": ", 0), 0U) << scene.err;
  expect_error_naming(run_marsokhod("commstime --platform " + quoted(folder)), folder, "directory");
  expect_error_naming(run_marsokhod("linktest --platform " + quoted(folder)), folder, "directory");
  expect_error_naming(run_marsokhod("eval stereo " + quoted(folder)), folder, "directory");
  expect_error_naming(run_marsokhod("rig --rig " + quoted(folder)), folder, "directory");
}

TEST_F(FileArguments, AnExistingFileGivenForAnOutputFolderIsAnError) {
  const fs::path file = dir_ / "file";
  expect_error_naming(run_marsokhod("nav " + pair() + " --out " + quoted(file)), file,
                      "output folder");
  expect_error_naming(run_marsokhod("world --size 16 --terrain-size 8 --out " + quoted(file)), file,
                      "output folder");
  expect_error_naming(
      run_marsokhod("eval terrain --seeds 1 --size 32 --terrain-size 16 --pictures " +
                    quoted(file)),
      file, "output folder");
  // The file is left as it was.
  std::ifstream in(file);
  std::string text;
  std::getline(in, text);
  EXPECT_EQ(text, "not a folder");
}

TEST_F(FileArguments, AnOutputFileThatIsAFolderOrInAMissingFolderIsAnError) {
  const fs::path folder = dir_ / "folder";
  expect_error_naming(run_marsokhod("calibrate " + pair() + " --out " + quoted(folder)), folder,
                      "is a directory");
  const fs::path nowhere = dir_ / "missing" / "c.toml";
  expect_error_naming(run_marsokhod("calibrate " + pair() + " --out " + quoted(nowhere)), nowhere,
                      "does not exist");
  expect_error_naming(run_marsokhod("commstime --loops 10 --trace " + quoted(folder)), folder,
                      "cannot write the trace file");
}

// /dev/full opens and then fails every write: the trace's last flush at the latest must tell.
TEST_F(FileArguments, ATraceFileOnAFullDiskIsAnErrorNamingIt) {
  expect_error_naming(run_marsokhod("commstime --loops 10 --trace /dev/full"), "/dev/full",
                      "No space left on device");
  expect_error_naming(run_marsokhod("linktest --bytes 100 --trace /dev/full"), "/dev/full",
                      "No space left on device");
}

} // namespace
