// The checked TOML table reader: every getter's type and range errors name file, line and key.
#include "marsokhod/io/formats/keyed_file_error.hpp"
#include "marsokhod/io/formats/toml_table.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace marsokhod::io {
namespace {

toml::table parsed(const std::string& text) {
  return toml::parse(text, std::string("t.toml"));
}

/// A file kind's own error, as PlatformError or CampaignError are.
class TestFileError : public KeyedFileError {
public:
  using KeyedFileError::KeyedFileError;
};

/// The [node] table of `body` (its keys start on line 2), read from "t.toml".
class TableTest : public testing::Test {
protected:
  TomlTable node(const std::string& body, std::string where = "a [[node]]") {
    document_ = parsed("[node]\n" + body);
    return TomlTable(*document_["node"].as_table(), "t.toml", std::move(where),
                     throw_keyed<TestFileError>);
  }

  toml::table document_;
};

template <class Read>
TestFileError error_of(Read read) {
  try {
    read();
  } catch (const TestFileError& error) {
    return error;
  }
  ADD_FAILURE() << "no TestFileError";
  return TestFileError("", 0, "", "");
}

TEST(KeyedFileError, SaysFileLineAndKey) {
  EXPECT_STREQ(KeyedFileError("p.toml", 7, "a.b", "is wrong").what(), "p.toml:7: 'a.b': is wrong");
  EXPECT_STREQ(KeyedFileError("p.toml", 0, "a", "x").what(), "p.toml: 'a': x");
  EXPECT_STREQ(KeyedFileError("p.toml", 3, "", "x").what(), "p.toml:3: x");
  const KeyedFileError error("p.toml", 7, "a.b", "is wrong");
  EXPECT_EQ(error.file(), "p.toml");
  EXPECT_EQ(error.line(), 7);
  EXPECT_EQ(error.key(), "a.b");
  EXPECT_EQ(error.problem(), "is wrong");
}

TEST_F(TableTest, ThrowsTheFileKindsOwnError) {
  TomlTable table = node("links = \"four\"\n");
  EXPECT_THROW(table.integer_in("links", 1, 4), TestFileError);
}

TEST_F(TableTest, WithoutAThrowerThrowsTheBase) {
  document_ = parsed("links = 9\n");
  TomlTable table(document_, "t.toml", "");
  try {
    table.integer_in("links", 1, 4);
    ADD_FAILURE() << "accepted 9";
  } catch (const KeyedFileError& error) {
    EXPECT_STREQ(error.what(), "t.toml:1: 'links': 9 is out of range: it must be between 1 and 4");
  }
}

TEST_F(TableTest, IntegerInRange) {
  TomlTable table = node("links = 4\n");
  EXPECT_EQ(table.integer_in("links", 1, 4), 4);
}

TEST_F(TableTest, IntegerOfAnotherTypeNamesFileLineKeyAndType) {
  TomlTable table = node("name = \"a\"\nlinks = \"four\"\n");
  const TestFileError error = error_of([&] { table.integer_in("links", 1, 4); });
  EXPECT_STREQ(error.what(), "t.toml:3: 'links': must be an integer, not a string (a [[node]])");
  EXPECT_EQ(error.file(), "t.toml");
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.key(), "links");
}

TEST_F(TableTest, IntegerOutOfRangeIsRefusedBeforeNarrowing) {
  // 2^32 + 3 would be 3 as a uint32_t, in range.
  TomlTable table = node("wait_states = 4294967299\n");
  EXPECT_STREQ(
      error_of([&] { table.integer_in<std::uint32_t>("wait_states", 0, 64, "cycles"); }).what(),
      "t.toml:2: 'wait_states': 4294967299 is out of range: it must be between 0 and 64 "
      "cycles (a [[node]])");
  TomlTable negative = node("wait_states = -1\n");
  EXPECT_NE(std::string(
                error_of([&] { negative.integer_in<std::uint32_t>("wait_states", 0, 64); }).what())
                .find("-1 is out of range"),
            std::string::npos);
  TomlTable wide = node("n = 9223372036854775807\n");
  EXPECT_EQ(wide.integer_in<std::int64_t>("n", 0, std::numeric_limits<std::int64_t>::max()),
            std::numeric_limits<std::int64_t>::max());
  EXPECT_THROW(wide.integer_in<int>("n", 0, std::numeric_limits<int>::max()), TestFileError);
}

TEST_F(TableTest, MissingIntegerIsRefusedAtTheTablesLine) {
  TomlTable table = node("name = \"a\"\n");
  const TestFileError error = error_of([&] { table.integer_in("links", 1, 4); });
  EXPECT_STREQ(error.what(), "t.toml:1: 'links': missing in a [[node]]");
}

TEST_F(TableTest, OptionalIntegerFallsBackOnlyWhenAbsent) {
  TomlTable table = node("wait_states = 2\n");
  EXPECT_EQ(table.optional_integer_in("wait_states", 0, 64, 7), 2);
  EXPECT_EQ(table.optional_integer_in("per_unit", 0, 64, 7), 7);
  TomlTable wrong = node("wait_states = 65\n");
  EXPECT_EQ(error_of([&] { wrong.optional_integer_in("wait_states", 0, 64, 7); }).key(),
            "wait_states");
}

TEST_F(TableTest, AnyIntegerOrNothing) {
  TomlTable table = node("seed = -9223372036854775808\nweight = 1.5\n");
  EXPECT_EQ(table.optional_integer("seed"), std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(table.optional_integer("runs"), std::nullopt);
  EXPECT_STREQ(error_of([&] { table.optional_integer("weight"); }).what(),
               "t.toml:3: 'weight': must be an integer, not a floating-point number (a [[node]])");
}

TEST_F(TableTest, IntegersInCheckEveryElement) {
  TomlTable table = node("speeds = [5, 10, 20]\n");
  EXPECT_EQ(table.integers_in("speeds", 1, 1000), (std::vector<int>{5, 10, 20}));
  EXPECT_TRUE(table.integers_in("absent", 1, 1000).empty());
  TomlTable big = node("speeds = [5, 4294967306]\n");
  EXPECT_NE(std::string(error_of([&] { big.integers_in<std::uint32_t>("speeds", 1, 1000); }).what())
                .find("4294967306 is out of range: it must be between 1 and 1000"),
            std::string::npos);
  TomlTable text = node("speeds = [5, \"10\"]\n");
  EXPECT_STREQ(error_of([&] { text.integers_in("speeds", 1, 1000); }).what(),
               "t.toml:2: 'speeds': must be an integer, not a string (a [[node]])");
  TomlTable scalar = node("speeds = 5\n");
  EXPECT_STREQ(error_of([&] { scalar.integers_in("speeds", 1, 1000); }).what(),
               "t.toml:2: 'speeds': must be an array, not an integer (a [[node]])");
}

TEST_F(TableTest, NumbersAreFiniteAndInRange) {
  TomlTable table = node("bits = 5.5\nwhole = 11\n");
  EXPECT_EQ(table.number_in("bits", 0, 1000), 5.5);
  EXPECT_EQ(table.number_in("whole", 0, 1000), 11.0);
  EXPECT_EQ(table.optional_number("absent"), std::nullopt);
  EXPECT_STREQ(error_of([&] { table.number_in("bits", 0, 1); }).what(),
               "t.toml:2: 'bits': 5.5 is out of range: it must be between 0 and 1 (a [[node]])");
  EXPECT_STREQ(error_of([&] { table.number_in("absent", 0, 1); }).what(),
               "t.toml:1: 'absent': missing in a [[node]]");
  for (const std::string value : {"nan", "inf", "-inf"}) {
    TomlTable odd = node("bits = " + value + "\n");
    EXPECT_STREQ(
        error_of([&] { odd.optional_number("bits"); }).what(),
        ("t.toml:2: 'bits': must be a finite number, not " + value + " (a [[node]])").c_str());
  }
  TomlTable text = node("bits = \"5\"\n");
  EXPECT_STREQ(error_of([&] { text.number_in("bits", 0, 1000); }).what(),
               "t.toml:2: 'bits': must be a finite number, not a string (a [[node]])");
}

TEST_F(TableTest, Strings) {
  TomlTable table = node("name = \"a\"\nlinks = 4\n");
  EXPECT_EQ(table.string("name"), "a");
  EXPECT_EQ(table.optional_string("name"), "a");
  EXPECT_EQ(table.optional_string("description"), std::nullopt);
  EXPECT_STREQ(error_of([&] { table.string("links"); }).what(),
               "t.toml:3: 'links': must be a string, not an integer (a [[node]])");
  EXPECT_STREQ(error_of([&] { table.optional_string("links"); }).what(),
               "t.toml:3: 'links': must be a string, not an integer (a [[node]])");
  EXPECT_STREQ(error_of([&] { table.string("kind"); }).what(),
               "t.toml:1: 'kind': missing in a [[node]]");
}

TEST_F(TableTest, BooleansFallBackWhenAbsent) {
  TomlTable table = node("powered = false\nbroken = 1\n");
  EXPECT_FALSE(table.boolean("powered", true));
  EXPECT_TRUE(table.boolean("absent", true));
  EXPECT_STREQ(error_of([&] { table.boolean("broken", false); }).what(),
               "t.toml:3: 'broken': must be true or false, not an integer (a [[node]])");
}

TEST_F(TableTest, TablesAndArrays) {
  TomlTable table = node("inner = { a = 1 }\nlist = [1, 2]\n");
  ASSERT_NE(table.optional_table("inner"), nullptr);
  EXPECT_EQ(table.optional_table("inner")->size(), 1U);
  ASSERT_NE(table.optional_array("list"), nullptr);
  EXPECT_EQ(table.optional_array("list")->size(), 2U);
  EXPECT_EQ(table.optional_table("absent"), nullptr);
  EXPECT_EQ(table.optional_array("absent"), nullptr);
  EXPECT_STREQ(error_of([&] { table.optional_table("list"); }).what(),
               "t.toml:3: 'list': must be a table, not an array (a [[node]])");
  EXPECT_STREQ(error_of([&] { table.optional_array("inner"); }).what(),
               "t.toml:2: 'inner': must be an array, not a table (a [[node]])");
}

TEST_F(TableTest, UnknownKeysAreRefusedAtTheirLine) {
  TomlTable table = node("name = \"a\"\nnmae = \"b\"\n");
  EXPECT_EQ(table.string("name"), "a");
  EXPECT_STREQ(error_of([&] { table.reject_unknown_keys(); }).what(),
               "t.toml:3: 'nmae': unknown key in a [[node]]");
  EXPECT_STREQ(error_of([&] { table.reject_unknown_keys("is not a key of [node]"); }).what(),
               "t.toml:3: 'nmae': is not a key of [node]");
}

TEST_F(TableTest, KeysAskedForAreKnownEvenWhenAbsentOrWrong) {
  TomlTable table = node("name = \"a\"\n");
  EXPECT_EQ(table.string("name"), "a");
  EXPECT_EQ(table.optional_integer_in("wait_states", 0, 64, 0), 0);
  EXPECT_TRUE(table.boolean("powered", true));
  EXPECT_NO_THROW(table.reject_unknown_keys());
}

TEST_F(TableTest, ExpectedKeysCanBeCheckedBeforeAnyRead) {
  TomlTable table = node("name = \"a\"\nnod = \"b\"\n");
  table.expect_keys({"name", "node"});
  EXPECT_EQ(error_of([&] { table.reject_unknown_keys(); }).key(), "nod");
  TomlTable good = node("name = \"a\"\nnode = \"b\"\n");
  good.expect_keys({"name", "node"});
  EXPECT_NO_THROW(good.reject_unknown_keys());
}

TEST_F(TableTest, FailNamesTheKeysLineOrTheTables) {
  TomlTable table = node("name = \"a\"\n");
  EXPECT_STREQ(error_of([&] { table.fail("name", "is taken"); }).what(),
               "t.toml:2: 'name': is taken (a [[node]])");
  EXPECT_STREQ(error_of([&] { table.fail("kind", "is needed"); }).what(),
               "t.toml:1: 'kind': is needed (a [[node]])");
  EXPECT_EQ(table.line_of("name"), 2);
  EXPECT_EQ(table.line_of("kind"), 1);
  EXPECT_EQ(table.line(), 1);
}

TEST_F(TableTest, WithoutAPlaceProblemsAreSaidAsGiven) {
  TomlTable table = node("name = 1\nextra = 2\n", "");
  EXPECT_STREQ(error_of([&] { table.string("name"); }).what(),
               "t.toml:2: 'name': must be a string, not an integer");
  EXPECT_STREQ(error_of([&] { table.string("kind"); }).what(), "t.toml:1: 'kind': missing");
  EXPECT_STREQ(error_of([&] { table.reject_unknown_keys(); }).what(),
               "t.toml:3: 'extra': unknown key");
}

TEST_F(TableTest, APrefixNamesKeysByTheirPlaceInTheFile) {
  document_ = parsed("[[process]]\nname = \"a\"\nnod = 1\n");
  const toml::table& entry = *document_["process"].as_array()->front().as_table();
  TomlTable table(entry, "t.toml", "", throw_keyed<TestFileError>, "process[0]");
  EXPECT_EQ(table.key_name("node"), "process[0].node");
  table.expect_keys({"name", "node"});
  EXPECT_STREQ(error_of([&] {
                 table.reject_unknown_keys("unknown key (this table takes name, node)");
               }).what(),
               "t.toml:3: 'process[0].nod': unknown key (this table takes name, node)");
  EXPECT_EQ(error_of([&] { table.fail("name", "is wrong"); }).key(), "process[0].name");
}

} // namespace
} // namespace marsokhod::io
