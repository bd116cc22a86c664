// The bounded text reader refuses what is not a small regular file, naming the file and limit.
#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/files/text_file.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace marsokhod::io {
namespace {

namespace fs = std::filesystem;

class TextFileTest : public ::testing::Test {
protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("marsokhod_text_file_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = folder_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  std::string error_of(const fs::path& path, std::size_t limit = kMaxTextFileBytes) const {
    try {
      read_text_file(path, "test file", limit);
    } catch (const InputError& error) {
      return error.what();
    }
    return "no error";
  }

  fs::path folder_;
};

TEST_F(TextFileTest, ReadsARegularFileWhole) {
  const std::string text = std::string("a = 1\n\0b = 2\n", 13);
  EXPECT_EQ(read_text_file(write("ok.toml", text), "test file"), text);
}

TEST_F(TextFileTest, EmptyFileReadsAsEmptyText) {
  EXPECT_EQ(read_text_file(write("empty.toml", ""), "test file"), "");
}

TEST_F(TextFileTest, MissingFileIsNamed) {
  const fs::path path = folder_ / "absent.toml";
  const std::string message = error_of(path);
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("No such file"), std::string::npos) << message;
}

TEST_F(TextFileTest, DirectoryIsRefusedAsADirectory) {
  const std::string message = error_of(folder_);
  EXPECT_NE(message.find("is a directory; a test file must be a regular file"), std::string::npos)
      << message;
}

TEST_F(TextFileTest, FifoWithoutWriterIsRefusedWithoutWaiting) {
  const fs::path fifo = folder_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto result = std::async(std::launch::async, [&] { return error_of(fifo); });
  ASSERT_EQ(result.wait_for(std::chrono::seconds(5)), std::future_status::ready)
      << "reading a FIFO without a writer blocked";
  EXPECT_NE(result.get().find("is a FIFO"), std::string::npos);
}

TEST_F(TextFileTest, DeviceIsRefused) {
  EXPECT_NE(error_of("/dev/zero").find("is a device"), std::string::npos);
}

TEST_F(TextFileTest, FileOverTheLimitIsRefusedWithTheLimitStated) {
  const fs::path path = write("big.toml", std::string(4097, 'x'));
  const std::string message = error_of(path, 4096);
  EXPECT_NE(message.find("is 4097 bytes; a test file is at most 4096 bytes"), std::string::npos)
      << message;
  EXPECT_EQ(read_text_file(write("edge.toml", std::string(4096, 'x')), "test file", 4096).size(),
            4096U);
}

TEST_F(TextFileTest, SparseHugeFileIsRefusedWithoutReadingIt) {
  const fs::path path = folder_ / "sparse.toml";
  { std::ofstream(path, std::ios::binary) << "a = 1\n"; }
  fs::resize_file(path, std::uintmax_t{3} << 30); // 3 GiB of holes: no disk, no memory
  const std::string message = error_of(path);
  EXPECT_NE(message.find("at most 16 MiB"), std::string::npos) << message;
}

TEST(ByteCountText, StatesWholeMebibytesAndOtherwiseBytes) {
  EXPECT_EQ(byte_count_text(std::size_t{16} << 20), "16 MiB");
  EXPECT_EQ(byte_count_text(4096), "4096 bytes");
}

} // namespace
} // namespace marsokhod::io
