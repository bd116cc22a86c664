// Test support shared by the layers' tests: the source tree's files, scratch files, the
// numbers tests compare with, and byte patterns.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace marsokhod::test_support {

/// The source tree, and its shipped platform files.
inline const std::filesystem::path kSource = MARSOKHOD_SOURCE_DIR;
inline const std::filesystem::path kPlatforms = kSource / "platforms";

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDegree = std::numbers::pi / 180.0;
/// The unknown of the navigation's float maps, and the unbounded double.
inline constexpr float kInf = std::numeric_limits<float>::infinity();
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Writes `text` to `name` in the test scratch folder, the file named for the running test as
/// well: ctest runs a file's tests in parallel processes, which must not write each other's
/// files.
inline std::filesystem::path write_test_file(const std::string& name, const std::string& text) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::filesystem::path path =
      std::filesystem::path(::testing::TempDir()) / (test + "-" + name);
  std::ofstream(path) << text;
  return path;
}

/// `size` bytes counting up by 7 from `first`: a block whose every byte tells where it was.
inline std::vector<std::byte> byte_pattern(std::size_t size, unsigned first = 3) {
  std::vector<std::byte> bytes(size);
  for (std::size_t i = 0; i < size; ++i)
    bytes[i] = std::byte(static_cast<unsigned char>(i * 7 + first));
  return bytes;
}

} // namespace marsokhod::test_support
