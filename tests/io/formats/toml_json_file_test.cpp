// TOML and JSON inputs go through the bounded reader; syntax errors name file and line.
#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/formats/json_file.hpp"
#include "marsokhod/io/formats/toml_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace marsokhod::io {
namespace {

namespace fs = std::filesystem;

fs::path write_temp(const std::string& name, const std::string& text) {
  const fs::path path =
      fs::temp_directory_path() / ("marsokhod_formats_" + std::to_string(::getpid()) + name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

template <class Parse>
std::string json_error_of(Parse parse) {
  try {
    parse();
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(TomlFile, ParsesAValidFile) {
  const fs::path path = write_temp("ok.toml", "[a]\nb = 2\n");
  EXPECT_EQ(parse_toml_file(path, "test file")["a"]["b"].value<int>(), 2);
  fs::remove(path);
}

TEST(TomlFile, SyntaxErrorNamesFileLineAndText) {
  const fs::path path = write_temp("bad.toml", "[a]\nb = = 2\n");
  const std::string message = json_error_of([&] { parse_toml_file(path, "test file"); });
  EXPECT_EQ(message.rfind(path.string() + ":2: TOML syntax error", 0), 0U) << message;
  EXPECT_NE(message.find("\"b = = 2\""), std::string::npos) << message;
  fs::remove(path);
}

TEST(TomlFile, DeviceIsRefusedBeforeParsing) {
  EXPECT_NE(json_error_of([] { parse_toml_file("/dev/zero", "test file"); }).find("is a device"),
            std::string::npos);
}

TEST(JsonFile, ParsesAValidFile) {
  const fs::path path = write_temp("ok.json", R"({"a": [1, "x\"]"]})");
  EXPECT_EQ(parse_json_file(path, "test file")["a"][0].get<int>(), 1);
  fs::remove(path);
}

TEST(JsonFile, SyntaxErrorNamesTheFile) {
  const fs::path path = write_temp("bad.json", "{\"a\": }");
  const std::string message = json_error_of([&] { parse_json_file(path, "test file"); });
  EXPECT_EQ(message.rfind(path.string() + ": not a test file: parse error at line 1", 0), 0U)
      << message;
  EXPECT_EQ(message.find("json.exception"), std::string::npos) << message;
  fs::remove(path);
}

TEST(JsonFile, NumberTooLargeForADoubleNamesTheFile) {
  const fs::path path = write_temp("huge.json", R"({"a": 1e999})");
  const std::string message = json_error_of([&] { parse_json_file(path, "test file"); });
  EXPECT_EQ(message.rfind(path.string() + ": not a test file", 0), 0U) << message;
  fs::remove(path);
}

TEST(JsonFile, DeepNestingIsRefusedBeforeParsing) {
  const fs::path path = write_temp("deep.json", std::string(100000, '['));
  const std::string message = json_error_of([&] { parse_json_file(path, "test file"); });
  EXPECT_NE(message.find("deeper than 64 levels"), std::string::npos) << message;
  fs::remove(path);
}

} // namespace
} // namespace marsokhod::io
