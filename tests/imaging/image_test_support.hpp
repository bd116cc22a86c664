// Test support for the imaging tests: hand-written bytes, temporary folders, error checks.
#pragma once

// Helpers shared by the image tests: byte buffers written by hand, temporary folders and
// checks that an ImageError names the file and the problem.

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <memory_resource>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace marsokhod::imaging::testing {

using Bytes = std::vector<std::uint8_t>;

/// The bytes of a text header followed by raw bytes.
inline Bytes bytes_of(std::string_view text, std::initializer_list<int> raw = {}) {
  Bytes bytes(text.begin(), text.end());
  for (int value : raw)
    bytes.push_back(static_cast<std::uint8_t>(value));
  return bytes;
}

inline void append(Bytes& bytes, std::string_view text) {
  bytes.insert(bytes.end(), text.begin(), text.end());
}

/// Runs `action`, expects an ImageError whose message starts with "<name>: " and contains
/// every fragment; returns the message for further checks.
inline std::string expect_image_error(const std::function<void()>& action, std::string_view name,
                                      std::initializer_list<std::string_view> fragments) {
  try {
    action();
  } catch (const ImageError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(std::string(name) + ": ", 0), 0U) << message;
    for (std::string_view fragment : fragments)
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "message \"" << message << "\" lacks \"" << fragment << "\"";
    return message;
  } catch (const std::exception& error) {
    ADD_FAILURE() << "expected ImageError, got another exception: " << error.what();
    return {};
  }
  ADD_FAILURE() << "expected ImageError, got none";
  return {};
}

/// decode_image on bytes that must fail.
inline std::string expect_decode_error(const Bytes& bytes, std::string_view name,
                                       std::initializer_list<std::string_view> fragments) {
  return expect_image_error([&] { (void)decode_image(bytes, name); }, name, fragments);
}

/// A fresh folder under the system temporary folder, removed at the end of the test.
class TemporaryFolder {
public:
  TemporaryFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string leaf = std::string("marsokhod_") + info->test_suite_name() + "_" + info->name();
    path_ = std::filesystem::temp_directory_path() / leaf;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(std::string_view leaf) const { return path_ / leaf; }

private:
  std::filesystem::path path_;
};

inline void write_bytes(const std::filesystem::path& path, const Bytes& bytes) {
  std::ofstream stream(path, std::ios::binary);
  stream.write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
}

inline Bytes read_bytes(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>());
}

/// A default memory resource that remembers the largest single request, to show that a
/// reader refuses a lying header before it allocates the pixels the header promises.
class LargestRequestResource : public std::pmr::memory_resource {
public:
  LargestRequestResource() : previous_(std::pmr::set_default_resource(this)) {}
  LargestRequestResource(const LargestRequestResource&) = delete;
  LargestRequestResource& operator=(const LargestRequestResource&) = delete;
  ~LargestRequestResource() override { std::pmr::set_default_resource(previous_); }
  std::size_t largest() const { return largest_; }

private:
  void* do_allocate(std::size_t bytes, std::size_t alignment) override {
    largest_ = std::max(largest_, bytes);
    return previous_->allocate(bytes, alignment);
  }
  void do_deallocate(void* p, std::size_t bytes, std::size_t alignment) override {
    previous_->deallocate(p, bytes, alignment);
  }
  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
    return this == &other;
  }

  std::pmr::memory_resource* previous_;
  std::size_t largest_ = 0;
};

} // namespace marsokhod::imaging::testing
