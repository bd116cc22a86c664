// Names joined to an output folder cannot leave it.
#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/paths/contained_path.hpp"

#include <gtest/gtest.h>

namespace marsokhod::io {
namespace {

TEST(ContainedPath, PlainAndNestedNamesStayInside) {
  EXPECT_EQ(path_inside("out", "Teddy", "pair name"), std::filesystem::path("out/Teddy"));
  EXPECT_EQ(path_inside("out", "2003/Cones", "pair name"), std::filesystem::path("out/2003/Cones"));
  EXPECT_FALSE(contained_name_problem("a..b").has_value()); // dots inside a name are fine
}

TEST(ContainedPath, EscapingNamesAreRefused) {
  for (const char* name : {"../x", "../../x", "a/../../x", "a/..", "..", "/etc/x", "/"})
    EXPECT_TRUE(contained_name_problem(name).has_value()) << name;
}

TEST(ContainedPath, EmptyDotAndControlCharacterNamesAreRefused) {
  for (const char* name : {"", ".", "./a", "a/", "a\nb", "a\tb"})
    EXPECT_TRUE(contained_name_problem(name).has_value()) << name;
}

TEST(ContainedPath, RefusalNamesWhatAndWhy) {
  try {
    path_inside("out", "../../x", "pair name");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "pair name '../../x' has a '..' part; it must stay inside the output folder");
  }
}

} // namespace
} // namespace marsokhod::io
