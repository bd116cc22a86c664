// Checked numbers: no NaN or infinity, no wrap, no trailing junk, exact narrowing.
#include "marsokhod/io/numbers/checked_number.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

namespace marsokhod::io {
namespace {

TEST(ParseFinite, AcceptsOrdinaryDecimalAndScientificText) {
  EXPECT_EQ(parse_finite("1.5"), 1.5);
  EXPECT_EQ(parse_finite("-45"), -45.0);
  EXPECT_EQ(parse_finite("1e3"), 1000.0);
}

TEST(ParseFinite, RefusesNanInfinityAndOverflow) {
  for (const char* text : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e309", "-1e999"})
    EXPECT_FALSE(parse_finite(text).has_value()) << text;
}

TEST(ParseFinite, RefusesJunkAroundTheNumber) {
  for (const char* text : {"", " 1", "1 ", "1x", "+1", "0x10", "1,5", "--1"})
    EXPECT_FALSE(parse_finite(text).has_value()) << '"' << text << '"';
}

TEST(ParseInteger, RefusesValuesThatWouldWrap) {
  EXPECT_FALSE(parse_integer<std::uint64_t>("-1").has_value());
  EXPECT_FALSE(parse_integer<std::int32_t>("4294967297").has_value()); // 2^32 + 1
  EXPECT_FALSE(parse_integer<std::int32_t>("2147483648").has_value()); // 2^31
  EXPECT_FALSE(parse_integer<std::int64_t>("9223372036854775808").has_value());
  EXPECT_EQ(parse_integer<std::int32_t>("-2147483648"), std::numeric_limits<std::int32_t>::min());
  EXPECT_EQ(parse_integer<std::uint64_t>("18446744073709551615"),
            std::numeric_limits<std::uint64_t>::max());
}

TEST(ParseInteger, RefusesFractionsExponentsAndJunk) {
  for (const char* text : {"", "1.0", "1e3", " 7", "7 ", "+7", "0x7", "7a"})
    EXPECT_FALSE(parse_integer<int>(text).has_value()) << '"' << text << '"';
}

TEST(Narrow, KeepsOnlyExactlyRepresentableValues) {
  EXPECT_EQ(narrow<std::int32_t>(std::int64_t{-5}), -5);
  EXPECT_FALSE(narrow<std::int32_t>(std::int64_t{1} << 32).has_value());
  EXPECT_FALSE(narrow<std::int32_t>(std::int64_t{1} << 31).has_value());
  EXPECT_FALSE(narrow<std::uint32_t>(std::int64_t{-1}).has_value());
}

TEST(IntegerFromReal, RefusesFractionsNanAndOutOfRange) {
  EXPECT_EQ(integer_from_real<int>(12.0), 12);
  EXPECT_FALSE(integer_from_real<int>(12.5).has_value());
  EXPECT_FALSE(integer_from_real<int>(std::numeric_limits<double>::quiet_NaN()).has_value());
  EXPECT_FALSE(integer_from_real<int>(2147483648.0).has_value());
  EXPECT_EQ(integer_from_real<int>(-2147483648.0), std::numeric_limits<int>::min());
  EXPECT_FALSE(integer_from_real<std::int64_t>(9223372036854775808.0).has_value());
  EXPECT_FALSE(integer_from_real<std::uint64_t>(-1.0).has_value());
}

} // namespace
} // namespace marsokhod::io
