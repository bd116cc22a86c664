// Doubles written into TOML files: the shortest text that reads back to the same double,
// always a TOML float.

#include "marsokhod/io/formats/toml_float.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cmath>
#include <string>

namespace marsokhod::io {
namespace {

double read_back(const std::string& text) {
  const toml::table table = toml::parse("x = " + text);
  return *table["x"].value_exact<double>();
}

TEST(TomlFloat, AWholeNumberIsWrittenAsAFloat) {
  EXPECT_EQ(toml_float(1.0), "1.0");
  EXPECT_EQ(toml_float(0.0), "0.0");
  EXPECT_EQ(toml_float(-12.0), "-12.0");
  EXPECT_TRUE(toml::parse("x = " + toml_float(3.0))["x"].is_floating_point());
}

TEST(TomlFloat, IsTheShortestTextThatReadsBackToTheSameDouble) {
  EXPECT_EQ(toml_float(0.1), "0.1");
  EXPECT_EQ(toml_float(0.5), "0.5");
  for (const double value : {0.1, 1.0 / 3.0, 2.718281828459045, 1e-300, 6.02214076e23, -0.0625,
                             std::nextafter(1.0, 2.0)})
    EXPECT_EQ(read_back(toml_float(value)), value) << toml_float(value);
}

TEST(TomlFloat, KeepsItsExponentForVeryLargeAndSmallValues) {
  EXPECT_EQ(toml_float(1e300), "1e+300");
  EXPECT_EQ(read_back(toml_float(1e300)), 1e300);
  EXPECT_EQ(read_back(toml_float(-4.9e-324)), -4.9e-324);
}

} // namespace
} // namespace marsokhod::io
