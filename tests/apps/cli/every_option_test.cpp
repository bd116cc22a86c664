// Tests: every option of every command that takes a value is held to the readers' contract.
// Numeric options have their check (option_checks_test.cpp); every other one is classified
// here by what it takes, and the binary is run with a value of the wrong kind for each: a
// folder for an input file, a regular file for an output folder, a folder for an output file,
// a word outside a choice, a list or range it cannot read. Each must be exit 1 naming the path
// or exit 2 naming the option, never a crash, a hang or a run. A new option that is not
// classified fails the first test, so that it joins the contract when it is added.
#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "support/run_marsokhod.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;
using marsokhod::testing::quoted;
using marsokhod::testing::run_marsokhod;

/// What an option takes, and so which wrong value it is given.
enum class Takes {
  input_file,    ///< given a folder: exit 1 naming it
  input_folder,  ///< given a regular file: exit 1 naming it
  output_folder, ///< given a regular file: exit 1 naming it
  output_file,   ///< given a folder: exit 1 naming it
  choice,        ///< given a word not offered: exit 2 naming the option
  text,          ///< a list, range or spec, given junk: exit 2 naming the option
  label,         ///< free text printed as given (a chart's title, a unit): nothing to refuse
};

/// One option, the command line that gives it `{}` (the wrong value) and the folder {D}.
struct OptionCase {
  std::string where; ///< "marsokhod nav --scene", as the walk names it
  Takes takes;
  std::string line; ///< arguments; {} is the wrong value, {L} {R} a valid pair, {D} a folder
};

bool has_number_check(CLI::Option* option) {
  try {
    return option->get_validator(kCheckedNumber) != nullptr;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

void collect(CLI::App& app, const std::string& path, std::vector<std::string>& found) {
  for (CLI::Option* option : app.get_options()) {
    const bool flag = option->get_type_name().empty(); // --help, --json and the like
    if (flag || has_number_check(option))
      continue;
    found.push_back(path + " " + option->get_name());
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    collect(*sub, path + " " + sub->get_name(), found);
}

std::vector<std::string> value_options() {
  CLI::App root{"test", "marsokhod"};
  std::vector<Command> commands;
  for (CommandFactory factory : command_factories())
    commands.push_back(factory(root));
  std::vector<std::string> found;
  collect(root, "marsokhod", found);
  return found;
}

const std::vector<OptionCase> kCases = {
    {"marsokhod world --out", Takes::output_folder, "world --size 16 --terrain-size 8 --out {}"},
    {"marsokhod world --light", Takes::choice,
     "world --size 16 --terrain-size 8 --out {D} --light {}"},
    {"marsokhod world --rig", Takes::input_file, "world --out {D} --rig {}"},
    {"marsokhod image info FILE", Takes::input_file, "image info {}"},
    {"marsokhod image convert IN", Takes::input_file, "image convert {} {D}/o.png"},
    {"marsokhod image convert OUT", Takes::output_file, "image convert {L} {}"},
    {"marsokhod image convert --unit", Takes::label, ""},
    {"marsokhod image convert --title", Takes::label, ""},
    {"marsokhod rig --rig", Takes::input_file, "rig --rig {}"},
    {"marsokhod nav LEFT", Takes::input_file, "nav {} {R} --out {D}"},
    {"marsokhod nav RIGHT", Takes::input_file, "nav {L} {} --out {D}"},
    {"marsokhod nav --out", Takes::output_folder, "nav {L} {R} --out {}"},
    {"marsokhod nav --rig", Takes::input_file, "nav {L} {R} --out {D} --rig {}"},
    {"marsokhod nav --scene", Takes::input_file, "nav {L} {R} --out {D} --scene {}"},
    {"marsokhod nav --calibration", Takes::input_file, "nav {L} {R} --out {D} --calibration {}"},
    {"marsokhod nav --disparity", Takes::input_file, "nav {L} {R} --out {D} --disparity {}"},
    {"marsokhod calibrate LEFT", Takes::input_file, "calibrate {} {R} --out {D}/c.toml"},
    {"marsokhod calibrate RIGHT", Takes::input_file, "calibrate {L} {} --out {D}/c.toml"},
    {"marsokhod calibrate --out", Takes::output_file, "calibrate {L} {R} --out {}"},
    {"marsokhod eval stereo PAIRS", Takes::input_file, "eval stereo {}"},
    {"marsokhod eval stereo --out", Takes::output_folder,
     "eval stereo {P} --max-disparity 16 --out {}"},
    {"marsokhod eval stereo --feature", Takes::choice,
     "eval stereo {P} --max-disparity 16 --out {D} --feature {}"},
    {"marsokhod eval stereo --fill", Takes::choice,
     "eval stereo {P} --max-disparity 16 --out {D} --fill {}"},
    {"marsokhod eval terrain --seeds", Takes::text, "eval terrain --size 32 --seeds {}"},
    {"marsokhod eval terrain --target", Takes::text,
     "eval terrain --seeds 1 --size 32 --target {}"},
    {"marsokhod eval terrain --light", Takes::choice,
     "eval terrain --seeds 1 --size 32 --light {}"},
    {"marsokhod eval terrain --pictures", Takes::output_folder,
     "eval terrain --seeds 1 --size 32 --terrain-size 16 --pictures {}"},
    {"marsokhod eval traverse --seeds", Takes::text, "eval traverse --seeds {}"},
    {"marsokhod eval traverse --rocks", Takes::text, "eval traverse --seeds 1 --rocks {}"},
    {"marsokhod eval traverse --light", Takes::choice, "eval traverse --seeds 1 --light {}"},
    {"marsokhod eval traverse --platform", Takes::choice, "eval traverse --seeds 1 --platform {}"},
    {"marsokhod eval traverse --faults", Takes::input_file,
     "eval traverse --seeds 1 --platform onboard --faults {}"},
    {"marsokhod eval traverse --out", Takes::output_folder,
     "eval traverse --seeds 1 --goal-m 5 --size 64 --out {}"},
    {"marsokhod linktest --platform", Takes::input_file, "linktest --bytes 1 --platform {}"},
    {"marsokhod linktest --mode", Takes::choice, "linktest --bytes 1 --mode {}"},
    {"marsokhod linktest --trace", Takes::output_file, "linktest --bytes 1 --trace {}"},
    {"marsokhod commstime --platform", Takes::input_file, "commstime --loops 1 --platform {}"},
    {"marsokhod commstime --node", Takes::text, "commstime --loops 1 --node {}"},
    {"marsokhod commstime --delta", Takes::choice, "commstime --loops 1 --delta {}"},
    {"marsokhod commstime --trace", Takes::output_file, "commstime --loops 1 --trace {}"},
    {"marsokhod emulate LEFT RIGHT", Takes::input_file, "emulate {} {R} --platform onboard"},
    {"marsokhod emulate --platform", Takes::input_file, "emulate {L} {R} --platform {}"},
    {"marsokhod emulate --placement", Takes::input_file,
     "emulate {L} {R} --platform onboard --out {D} --placement {}"},
    {"marsokhod emulate --out", Takes::output_folder,
     "emulate {L} {R} --platform onboard --out {}"},
    {"marsokhod emulate --trace", Takes::output_file,
     "emulate {L} {R} --platform onboard --out {D} --trace {}"},
    {"marsokhod emulate --rig", Takes::input_file,
     "emulate {L} {R} --platform onboard --out {D} --rig {}"},
    {"marsokhod emulate --scene", Takes::input_file,
     "emulate {L} {R} --platform onboard --out {D} --scene {}"},
    {"marsokhod emulate --calibration", Takes::input_file,
     "emulate {L} {R} --platform onboard --out {D} --calibration {}"},
    {"marsokhod reproduce --seeds", Takes::text, "reproduce --seeds {}"},
    {"marsokhod reproduce --out", Takes::output_folder,
     "reproduce --seeds 1 --sweep-external-kb 256 --out {}"},
    {"marsokhod fault --platform", Takes::input_file,
     "fault --inject hang:module0@1s --platform {}"},
    {"marsokhod fault --inject", Takes::text, "fault --platform onboard --inject {}"},
    {"marsokhod fault --trace", Takes::output_file,
     "fault --platform onboard --inject hang:module0@1s --trace {}"},
    {"marsokhod fault --out", Takes::output_folder,
     "fault --platform onboard --inject hang:module0@1s --out {}"},
    {"marsokhod campaign FILE", Takes::input_file, "campaign {} --runs 1"},
    {"marsokhod campaign --seeds", Takes::text, "campaign {C} --runs 1 --seeds {}"},
    {"marsokhod campaign --out", Takes::output_folder,
     "campaign {C} --runs 1 --seeds 2..2 --out {}"},
    {"marsokhod traverse --normal-path", Takes::text, "traverse --max-cycles 1 --normal-path {}"},
    {"marsokhod eval traverse --normal-path", Takes::text,
     "eval traverse --seeds 1 --normal-path {}"},
    {"marsokhod report DIR", Takes::input_folder, "report {} --out {D}.html"},
    {"marsokhod report --out", Takes::output_file, "report {W} --out {}"},
    {"marsokhod report --title", Takes::label, ""},
    {"marsokhod traverse --light", Takes::choice, "traverse --max-cycles 1 --light {}"},
    {"marsokhod traverse --platform", Takes::choice, "traverse --max-cycles 1 --platform {}"},
    {"marsokhod traverse --faults", Takes::input_file,
     "traverse --max-cycles 1 --platform onboard --faults {}"},
    {"marsokhod traverse --out", Takes::output_folder,
     "traverse --max-cycles 1 --goal-m 5 --size 64 --out {}"},
};

TEST(EveryOption, EveryOptionTakingAValueIsClassified) {
  const std::vector<std::string> found = value_options();
  EXPECT_GE(found.size(), kCases.size());
  std::vector<std::string> unclassified;
  for (const std::string& where : found)
    if (std::none_of(kCases.begin(), kCases.end(),
                     [&](const OptionCase& c) { return c.where == where; }))
      unclassified.push_back(where);
  EXPECT_EQ(unclassified, std::vector<std::string>{});
  std::vector<std::string> gone;
  for (const OptionCase& c : kCases)
    if (std::find(found.begin(), found.end(), c.where) == found.end())
      gone.push_back(c.where);
  EXPECT_EQ(gone, std::vector<std::string>{});
}

// A small pair, its pair index, a folder, a regular file and a shipped campaign.
class WrongValues : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir_ = marsokhod::testing::fresh_folder("every-option", "files");
    const auto world = run_marsokhod("world --size 64 --out " + quoted(dir_ / "w"));
    ASSERT_EQ(world.exit_code, 0) << world.err;
    fs::create_directories(dir_ / "folder");
    std::ofstream(dir_ / "file") << "a regular file\n";
    std::ofstream(dir_ / "PAIRS.tsv")
        << "name\tleft\tright\tgt\tgt_scale\tgt_bits\twidth\theight\tmax_gt_disp_px\n"
        << "w\tw/left.pgm\tw/right.pgm\t-\t-\t-\t64\t64\t-\n";
  }

  /// The case's line with its wrong value and every placeholder filled in.
  static std::string line(const OptionCase& c, const std::string& value, int number) {
    const std::map<std::string, std::string> fill = {
        {"{}", value},
        {"{L}", quoted(dir_ / "w" / "left.pgm")},
        {"{R}", quoted(dir_ / "w" / "right.pgm")},
        {"{W}", quoted(dir_ / "w")},
        {"{P}", quoted(dir_ / "PAIRS.tsv")},
        {"{C}", quoted(fs::path(MARSOKHOD_SOURCE_DIR) / "campaigns" / "hang-power.toml")},
        {"{D}", quoted(dir_ / fmt::format("out-{}", number))}};
    std::string text = c.line;
    for (const auto& [key, with] : fill)
      for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at))
        text.replace(at, key.size(), with);
    return text;
  }

  static fs::path dir_;
};

fs::path WrongValues::dir_;

std::string option_name(const OptionCase& c) {
  return c.where.substr(c.where.rfind(' ') + 1);
}

TEST_F(WrongValues, EachIsExitOneNamingThePathOrExitTwoNamingTheOption) {
  int number = 0;
  int run = 0;
  for (const OptionCase& c : kCases) {
    ++number;
    if (c.takes == Takes::label)
      continue;
    const bool path = c.takes != Takes::choice && c.takes != Takes::text;
    const fs::path wrong =
        dir_ /
        (c.takes == Takes::output_folder || c.takes == Takes::input_folder ? "file" : "folder");
    const std::string value = path ? quoted(wrong) : (c.takes == Takes::choice ? "bogus" : "x..");
    const std::string arguments = line(c, value, number);
    const auto result = run_marsokhod(arguments);
    ++run;
    SCOPED_TRACE(c.where + ": marsokhod " + arguments + "\n" + result.err);
    EXPECT_EQ(result.exit_code, path ? 1 : 2);
    const std::string named = path ? wrong.string() : option_name(c);
    EXPECT_NE(result.err.find(named), std::string::npos) << "no " << named;
  }
  EXPECT_GE(run, 50);
}

} // namespace
} // namespace marsokhod::apps
