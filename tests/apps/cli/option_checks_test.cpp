// Tests: every numeric option of every command is read through one check (finite, in range,
// no wrap), and that check refuses what CLI11's own conversion would let through.
#include "cli/command.hpp"
#include "cli/option_checks.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace marsokhod::apps {
namespace {

// One option and the command path it belongs to, for messages.
struct FoundOption {
  std::string where;
  CLI::Option* option;
};

void collect(CLI::App& app, const std::string& path, std::vector<FoundOption>& found) {
  for (CLI::Option* option : app.get_options())
    found.push_back({path + " " + option->get_name(), option});
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    collect(*sub, path + " " + sub->get_name(), found);
}

// The numeric options of every command the command line offers, through the same factories.
class AllOptions : public ::testing::Test {
protected:
  void SetUp() override {
    for (CommandFactory factory : command_factories())
      commands_.push_back(factory(root_));
    collect(root_, "marsokhod", options_);
    for (const FoundOption& found : options_) {
      const std::string type = found.option->get_type_name();
      // The type name starts with CLI11's name for the stored type; the check adds ":range".
      if (type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0 || type.rfind("FLOAT", 0) == 0)
        numeric_.push_back(found);
    }
  }

  static std::string check(const FoundOption& found, std::string text) {
    return found.option->get_validator(kCheckedNumber)->operator()(text);
  }
  static bool is_integer(const FoundOption& found) {
    return found.option->get_type_name().rfind("FLOAT", 0) != 0;
  }

  CLI::App root_{"test", "marsokhod"};
  std::vector<Command> commands_;
  std::vector<FoundOption> options_;
  std::vector<FoundOption> numeric_;
};

TEST_F(AllOptions, EveryNumericOptionOfEveryCommandHasTheCheck) {
  // nav 4, world 11, rig 1, calibrate 2, eval stereo 5, eval terrain 3, commstime 1,
  // linktest 3, image convert 2, and since then emulate, fault, campaign, traverse and eval
  // traverse: 60 in all, a lower bound, so that a lost walk cannot pass vacuously.
  EXPECT_GE(numeric_.size(), 60U);
  std::vector<std::string> unchecked;
  for (const FoundOption& found : numeric_)
    if (found.option->get_validator(kCheckedNumber) == nullptr)
      unchecked.push_back(found.where);
  EXPECT_EQ(unchecked, std::vector<std::string>{});
}

// Everything listed here was taken by an option (or, for wide, changed on the way in).
TEST_F(AllOptions, EveryNumericOptionRefusesNonFiniteJunkAndWrappingValues) {
  std::vector<std::string> taken;
  for (const FoundOption& found : numeric_) {
    if (found.option->get_validator(kCheckedNumber) == nullptr)
      continue;
    for (const char* bad :
         {"nan", "NaN", "inf", "-inf", "1e309", "-1e309", "", "1x", "x", " 1", "0x10", "+1", "1,5"})
      if (check(found, bad).empty())
        taken.push_back(found.where + " '" + bad + "'");
    if (!is_integer(found))
      continue;
    // 2^64 + 16 wraps to 16 in 64 bits; -1 is 2^64 - 1 to an unsigned, and no option is negative.
    for (const char* bad : {"18446744073709551632", "-1", "1.5", "1e3"})
      if (check(found, bad).empty())
        taken.push_back(found.where + " '" + bad + "'");
    // 2^32 + 16 wraps to 16 in 32 bits: refused, or (--seed, 64 bits) taken as itself.
    std::string wide = "4294967312";
    if (found.option->get_validator(kCheckedNumber)->operator()(wide).empty() &&
        wide != "4294967312")
      taken.push_back(found.where + " 4294967312 as " + wide);
  }
  EXPECT_EQ(taken, std::vector<std::string>{});
}

TEST_F(AllOptions, EveryNumericOptionsDefaultPassesItsOwnCheck) {
  std::vector<std::string> refused;
  for (const FoundOption& found : numeric_) {
    const std::string value = found.option->get_default_str();
    if (!value.empty() && found.option->get_validator(kCheckedNumber) != nullptr &&
        !check(found, value).empty())
      refused.push_back(found.where + " default " + value);
  }
  EXPECT_EQ(refused, std::vector<std::string>{});
}

// The values of `texts` that `check` takes.
std::vector<std::string> taken_by(const CLI::Validator& check,
                                  const std::vector<std::string>& texts) {
  std::vector<std::string> taken;
  for (std::string text : texts)
    if (check(text).empty())
      taken.push_back(text);
  return taken;
}

TEST(RealBetween, TakesFiniteDecimalsInTheClosedRangeAndQuotesWhatItRefuses) {
  CLI::Validator check = real_between(-45.0, 45.0);
  const std::vector<std::string> good = {"-45", "45", "0", "-0", "1e1", "44.999", "4.5e+1"};
  EXPECT_EQ(taken_by(check, good), good);
  std::string nan = "nan";
  EXPECT_EQ(check(nan), "'nan' is not a finite number between -45 and 45");
  std::string above = "45.0000001";
  EXPECT_EQ(check(above), "'45.0000001' is not a finite number between -45 and 45");
}

TEST(IntegerBetween, TakesDecimalIntegersWithoutWrapAndRewritesThemCanonically) {
  CLI::Validator check = integer_between<std::uint64_t>(0, UINT64_MAX);
  std::string top = "18446744073709551615";
  EXPECT_EQ(check(top), "");
  std::string minus_one = "-1";
  EXPECT_EQ(check(minus_one), "'-1' is not a whole number between 0 and 18446744073709551615");
  // CLI11 alone reads a leading 0 as octal: 010 would be 8.
  std::string leading_zero = "010";
  EXPECT_EQ(check(leading_zero), "");
  EXPECT_EQ(leading_zero, "10");
  CLI::Validator small = integer_between(2, 32);
  EXPECT_EQ(taken_by(small, {"1", "2", "32", "33", "4294967298", "2.0"}),
            (std::vector<std::string>{"2", "32"}));
}

TEST(IntegerOneOf, TakesOnlyTheListedValuesInDecimal) {
  CLI::Validator check = integer_one_of({128, 256});
  std::string hex = "0x80";
  EXPECT_EQ(check(hex), "'0x80' is not one of 128, 256");
  std::string padded = "0128";
  EXPECT_EQ(check(padded), "");
  EXPECT_EQ(padded, "128");
}

} // namespace
} // namespace marsokhod::apps
