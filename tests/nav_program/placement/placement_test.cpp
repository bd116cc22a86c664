// Placement files: the shipped placements, where a platform's default placement is, and every
// error a placement file can hold, each with its file, line and key.

#include "support/test_files.hpp"

#include "marsokhod/nav_program/placement/placement.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace marsokhod::nav_program {
namespace {

namespace fs = std::filesystem;
using emulator::PlatformSpec;

using test_support::kPlatforms;

const PlatformSpec& onboard() {
  static const PlatformSpec platform = emulator::load_platform(kPlatforms / "onboard.toml");
  return platform;
}
const PlatformSpec& pc_card() {
  static const PlatformSpec platform = emulator::load_platform(kPlatforms / "pc-card.toml");
  return platform;
}

/// (process, node) in file order.
using Places = std::vector<std::pair<std::string, std::string>>;

/// The shipped onboard split: acquire, features, matching on module0, the rest on module1.
Places onboard_split() {
  Places places;
  for (const std::string& process : navigation_program_shape().processes)
    places.emplace_back(process, places.size() < 3 ? "module0" : "module1");
  return places;
}

/// The same split on the tests' bench platform: module0's processes on a, module1's on b.
Places bench_split() {
  Places places;
  for (const std::string& process : navigation_program_shape().processes)
    places.emplace_back(process, places.size() < 3 ? "a" : "b");
  return places;
}

/// A two-line [placement] header and three lines per [[process]]: entry k's [[process]] is on
/// line 3 + 3k, its name on 4 + 3k and its node on 5 + 3k.
std::string placement_text(const std::string& platform, const Places& places) {
  std::string text = "[placement]\nplatform = \"" + platform + "\"\n";
  for (const auto& [process, node] : places)
    text += "[[process]]\nname = \"" + process + "\"\nnode = \"" + node + "\"\n";
  return text;
}

/// Each test writes its files to a folder of its own, so that parallel runs cannot collide.
class PlacementFile : public ::testing::Test {
protected:
  void SetUp() override {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() /
              ("marsokhod-placement-" + std::to_string(getpid()) + "-" + test->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(folder_, ignored);
  }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = folder_ / name;
    std::ofstream(path) << text;
    return path;
  }

  /// A platform of three powered nodes and a cold one: a-b wired, b-c on a broken wire, a and c
  /// not wired, and only a and b wired to the frame store.
  PlatformSpec bench() const {
    const fs::path processor = kPlatforms / "processors" / "t805.toml";
    std::string text = "[platform]\nname = \"bench\"\nprocessor = \"" + processor.string() +
                       "\"\nlink_speed_mbps = 10\n";
    for (const std::string node : {"a", "b", "c", "spare"})
      text += "[[node]]\nname = \"" + node +
              "\"\nspeed_grade = \"T805-30\"\nexternal_kb = 256\npowered = " +
              (node == "spare" ? "false" : "true") + "\n";
    text += "[[device]]\nname = \"store\"\nkind = \"frame_store\"\nlinks = 2\ncameras = 2\n"
            "image_width = 128\nimage_height = 128\nbits_per_pixel = 8\n"
            "[[wire]]\na = \"a.link0\"\nb = \"b.link0\"\n"
            "[[wire]]\na = \"b.link1\"\nb = \"c.link1\"\nbroken = true\n"
            "[[wire]]\na = \"a.link3\"\nb = \"store.link0\"\n"
            "[[wire]]\na = \"b.link3\"\nb = \"store.link1\"\n";
    return emulator::load_platform(write("bench.toml", text));
  }

  /// Loads `text` as placement.toml and returns the error it must raise, checked to name the
  /// file it was given.
  PlacementError expect_error(const std::string& text, const PlatformSpec& platform) {
    path_ = write("placement.toml", text);
    try {
      load_placement(path_, platform, navigation_program_shape());
    } catch (const PlacementError& error) {
      EXPECT_EQ(error.file(), path_.string());
      EXPECT_NE(std::string(error.what()).find(path_.string()), std::string::npos) << error.what();
      return error;
    }
    ADD_FAILURE() << "no error for\n" << text;
    return PlacementError("", 0, "", "");
  }

  static bool says(const PlacementError& error, const std::string& piece) {
    return std::string(error.what()).find(piece) != std::string::npos;
  }

  fs::path folder_;
  fs::path path_;
};

TEST_F(PlacementFile, ShippedOnboardPlacementPutsStereoOnModule0AndTheRestOnModule1) {
  const fs::path file = kPlatforms / "placements" / "onboard.toml";
  const Placement placement = load_placement(file, onboard(), navigation_program_shape());
  EXPECT_EQ(placement.source, file.string());
  EXPECT_EQ(placement.platform, "onboard");
  EXPECT_FALSE(placement.description.empty());
  ASSERT_EQ(placement.places.size(), 10U);
  for (const std::string process : {"acquire", "features", "matching"})
    EXPECT_EQ(placement.node_of(process), "module0") << process;
  for (const std::string process :
       {"refine", "range", "zones", "path", "drive", "motion", "telemetry"})
    EXPECT_EQ(placement.node_of(process), "module1") << process;
  EXPECT_EQ(placement.places.front().process, "acquire"); // file order
  EXPECT_GT(placement.places.front().line, 0);
}

TEST_F(PlacementFile, ShippedPcCardPlacementPutsEveryProcessOnTheCard) {
  const Placement placement = load_placement(kPlatforms / "placements" / "pc-card.toml", pc_card(),
                                             navigation_program_shape());
  EXPECT_EQ(placement.platform, "pc-card");
  ASSERT_EQ(placement.places.size(), 10U);
  for (const std::string& process : navigation_program_shape().processes)
    EXPECT_EQ(placement.node_of(process), "card") << process;
}

TEST_F(PlacementFile, DefaultPlacementFileIsThePlatformsNameInPlacementsBesideIt) {
  EXPECT_EQ(default_placement_file(onboard()), kPlatforms / "placements" / "onboard.toml");
  EXPECT_EQ(default_placement_file(pc_card()), kPlatforms / "placements" / "pc-card.toml");
  const Placement placement =
      load_placement(default_placement_file(onboard()), onboard(), navigation_program_shape());
  EXPECT_EQ(placement.node_of("matching"), "module0");
}

TEST_F(PlacementFile, MissingDefaultPlacementIsAnErrorNamingThePathItLookedFor) {
  PlatformSpec platform = onboard();
  platform.source = (folder_ / "onboard.toml").string();
  const fs::path expected = folder_ / "placements" / "onboard.toml";
  try {
    default_placement_file(platform);
    FAIL() << "no error";
  } catch (const PlacementError& error) {
    EXPECT_EQ(error.file(), expected.string());
    EXPECT_EQ(error.line(), 0);
    EXPECT_EQ(error.key(), "");
    EXPECT_EQ(std::string(error.what()).rfind(expected.string() + ": ", 0), 0U) << error.what();
    EXPECT_TRUE(says(error, "platform 'onboard'")) << error.what();
  }
}

TEST_F(PlacementFile, NodeOfAProcessNotPlacedIsOutOfRange) {
  const Placement placement = load_placement(kPlatforms / "placements" / "onboard.toml", onboard(),
                                             navigation_program_shape());
  EXPECT_THROW((void)placement.node_of("steering"), std::out_of_range);
}

TEST_F(PlacementFile, BenchPlatformOfTheTestsTakesTheOnboardSplit) {
  Places places = bench_split();
  const fs::path file = write("placement.toml", placement_text("bench", places));
  const Placement placement = load_placement(file, bench(), navigation_program_shape());
  EXPECT_EQ(placement.node_of("range"), "b");
  EXPECT_EQ(placement.places[3].line, 14); // entry 3's node: 5 + 3 * 3
}

TEST_F(PlacementFile, MessageHasThePlatformErrorShapeFileLineQuotedKeyProblem) {
  const PlacementError error("p.toml", 7, "process[1].node", "is wrong");
  EXPECT_STREQ(error.what(), "p.toml:7: 'process[1].node': is wrong");
  EXPECT_STREQ(PlacementError("p.toml", 0, "placement", "x").what(), "p.toml: 'placement': x");
  EXPECT_STREQ(PlacementError("p.toml", 3, "", "x").what(), "p.toml:3: x");
}

TEST_F(PlacementFile, UnknownTopLevelKeyIsAnError) {
  const PlacementError error = expect_error("# a comment\n"
                                            "[placement]\n"
                                            "platform = \"onboard\"\n"
                                            "\n"
                                            "[[processes]]\n"
                                            "name = \"acquire\"\n",
                                            onboard());
  EXPECT_EQ(error.line(), 5);
  EXPECT_EQ(error.key(), "processes");
  EXPECT_TRUE(says(error, "unknown key")) << error.what();
  EXPECT_TRUE(says(error, "only [placement] and [[process]] tables")) << error.what();
}

TEST_F(PlacementFile, UnknownKeyInThePlacementTableIsAnError) {
  const PlacementError error = expect_error("[placement]\n"
                                            "platform = \"onboard\"\n"
                                            "descripton = \"typo\"\n",
                                            onboard());
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.key(), "placement.descripton");
  EXPECT_TRUE(says(error, "unknown key (this table takes platform, description)")) << error.what();
}

TEST_F(PlacementFile, UnknownKeyInAProcessIsAnErrorWithItsIndex) {
  const PlacementError error = expect_error("[placement]\n"
                                            "platform = \"onboard\"\n"
                                            "[[process]]\n"
                                            "name = \"acquire\"\n"
                                            "node = \"module0\"\n"
                                            "[[process]]\n"
                                            "name = \"features\"\n"
                                            "nod = \"module0\"\n",
                                            onboard());
  EXPECT_EQ(error.line(), 8);
  EXPECT_EQ(error.key(), "process[1].nod");
  EXPECT_TRUE(says(error, "unknown key (this table takes name, node)")) << error.what();
}

TEST_F(PlacementFile, WrongTypeNamesTheTypeFound) {
  const PlacementError error = expect_error("[placement]\n"
                                            "platform = \"onboard\"\n"
                                            "[[process]]\n"
                                            "name = \"acquire\"\n"
                                            "node = \"module0\"\n"
                                            "[[process]]\n"
                                            "name = \"features\"\n"
                                            "node = \"module0\"\n"
                                            "[[process]]\n"
                                            "name = \"matching\"\n"
                                            "node = 0\n",
                                            onboard());
  EXPECT_EQ(error.line(), 11);
  EXPECT_EQ(error.key(), "process[2].node");
  EXPECT_TRUE(says(error, "must be a string, not an integer")) << error.what();
}

TEST_F(PlacementFile, ProcessNotWrittenAsTablesIsAnError) {
  // Above [placement]: below it, the key would belong to that table.
  const PlacementError error = expect_error("process = \"acquire\"\n"
                                            "[placement]\n"
                                            "platform = \"onboard\"\n",
                                            onboard());
  EXPECT_EQ(error.line(), 1);
  EXPECT_EQ(error.key(), "process");
  EXPECT_TRUE(says(error, "must be written as [[process]] tables, not a string")) << error.what();
}

TEST_F(PlacementFile, MissingPlacementTableIsAnErrorOfTheWholeFile) {
  const PlacementError error = expect_error("[[process]]\n"
                                            "name = \"acquire\"\n"
                                            "node = \"module0\"\n",
                                            onboard());
  EXPECT_EQ(error.line(), 0);
  EXPECT_EQ(error.key(), "placement");
  EXPECT_TRUE(says(error, "missing [placement] table")) << error.what();
  EXPECT_TRUE(says(error, "platform = \"onboard\"")) << error.what();
}

TEST_F(PlacementFile, PlacementForAnotherPlatformNamesBothAndThePlatformFile) {
  const PlacementError error = expect_error(placement_text("pc-card", onboard_split()), onboard());
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(error.key(), "placement.platform");
  EXPECT_TRUE(says(error, "this placement is for platform 'pc-card' but the platform is "
                          "'onboard' (" +
                              onboard().source + ")"))
      << error.what();
}

TEST_F(PlacementFile, MissingPlatformKeyIsAnErrorAtThePlacementTable) {
  const PlacementError error = expect_error("\n"
                                            "[placement]\n"
                                            "description = \"for no platform\"\n",
                                            onboard());
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(error.key(), "placement.platform");
  EXPECT_TRUE(says(error, "missing")) << error.what();
}

TEST_F(PlacementFile, ProcessWithoutANameIsAnErrorListingTheProcesses) {
  const PlacementError error = expect_error("[placement]\n"
                                            "platform = \"onboard\"\n"
                                            "\n"
                                            "[[process]]\n"
                                            "node = \"module0\"\n",
                                            onboard());
  EXPECT_EQ(error.line(), 4); // the [[process]] table that lacks it
  EXPECT_EQ(error.key(), "process[0].name");
  EXPECT_TRUE(says(error, "missing")) << error.what();
  EXPECT_TRUE(says(error, "acquire, features, matching")) << error.what();
}

TEST_F(PlacementFile, EmptyNodeIsAnErrorListingThePoweredNodes) {
  const PlacementError error = expect_error("[placement]\n"
                                            "platform = \"onboard\"\n"
                                            "[[process]]\n"
                                            "name = \"acquire\"\n"
                                            "node = \"\"\n",
                                            onboard());
  EXPECT_EQ(error.line(), 5);
  EXPECT_EQ(error.key(), "process[0].node");
  EXPECT_TRUE(says(error, "not be empty")) << error.what();
  EXPECT_TRUE(says(error, "powered nodes: module0, module1")) << error.what();
}

TEST_F(PlacementFile, UnknownProcessIsAnErrorListingTheKnownOnes) {
  const PlacementError error = expect_error("[placement]\n"
                                            "platform = \"onboard\"\n"
                                            "[[process]]\n"
                                            "name = \"steering\"\n"
                                            "node = \"module0\"\n",
                                            onboard());
  EXPECT_EQ(error.line(), 4);
  EXPECT_EQ(error.key(), "process[0].name");
  EXPECT_TRUE(says(error, "'steering' is not a process of the program")) << error.what();
  EXPECT_TRUE(says(error, "motion, telemetry")) << error.what();
}

TEST_F(PlacementFile, UnknownNodeIsAnErrorListingThePoweredNodes) {
  Places places = onboard_split();
  places[4].second = "module9";
  const PlacementError error = expect_error(placement_text("onboard", places), onboard());
  EXPECT_EQ(error.line(), 17); // entry 4's node: 5 + 3 * 4
  EXPECT_EQ(error.key(), "process[4].node");
  EXPECT_TRUE(says(error, "'module9' is not a node of platform 'onboard'")) << error.what();
  EXPECT_TRUE(says(error, "powered nodes: module0, module1")) << error.what();
}

TEST_F(PlacementFile, DeviceNamedAsNodeSaysDevicesCannotRunProcesses) {
  Places places = onboard_split();
  places[0].second = "rover_io";
  const PlacementError error = expect_error(placement_text("onboard", places), onboard());
  EXPECT_EQ(error.line(), 5);
  EXPECT_EQ(error.key(), "process[0].node");
  EXPECT_TRUE(says(error, "'rover_io' is a device")) << error.what();
  EXPECT_TRUE(says(error, "devices cannot run processes")) << error.what();
}

TEST_F(PlacementFile, ColdSpareNodeIsAnErrorListingThePoweredNodes) {
  Places places = onboard_split();
  places[8].second = "module2";
  const PlacementError error = expect_error(placement_text("onboard", places), onboard());
  EXPECT_EQ(error.line(), 29); // entry 8's node: 5 + 3 * 8
  EXPECT_EQ(error.key(), "process[8].node");
  EXPECT_TRUE(says(error, "'module2' is not powered")) << error.what();
  EXPECT_TRUE(says(error, "powered nodes: module0, module1")) << error.what();
}

TEST_F(PlacementFile, ProcessPlacedTwiceNamesBothLines) {
  Places places = onboard_split();
  places.insert(places.begin() + 5, {"features", "module1"});
  const PlacementError error = expect_error(placement_text("onboard", places), onboard());
  EXPECT_EQ(error.line(), 19); // entry 5's name: 4 + 3 * 5
  EXPECT_EQ(error.key(), "process[5].name");
  EXPECT_TRUE(says(error, "'features' is already placed on line 8 (on module0)")) << error.what();
}

TEST_F(PlacementFile, ProcessOfTheProgramNotPlacedIsAnErrorAtThePlacementTable) {
  Places places = onboard_split();
  places.erase(places.begin() + 5); // zones
  places.pop_back();                // telemetry
  const PlacementError error =
      expect_error("# two missing\n" + placement_text("onboard", places), onboard());
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(error.key(), "process");
  EXPECT_TRUE(says(error, "not placed: zones, telemetry")) << error.what();
}

TEST_F(PlacementFile, ChannelBetweenUnwiredNodesIsAnErrorAtTheLaterPlacedProcess) {
  Places places = bench_split();
  places[3].second = "c"; // refine: matching's bands would go from a to c
  const PlacementError error = expect_error(placement_text("bench", places), bench());
  EXPECT_EQ(error.line(), 14); // entry 3's node: 5 + 3 * 3
  EXPECT_EQ(error.key(), "process[3].node");
  EXPECT_TRUE(says(error, "channel 'matched' from matching (on a) to refine (on c) has no "
                          "route: no wire joins a and c"))
      << error.what();
}

TEST_F(PlacementFile, TwoChannelsOnOneLinkDirectionAreAnErrorAtTheLaterPlacedProcess) {
  Places places = bench_split();
  places[1].second = "b"; // features on b: images go from a to b, features from b back to a
  const PlacementError error = expect_error(placement_text("bench", places), bench());
  // matched (matching on a -> refine on b) is the second channel from a to b.
  EXPECT_EQ(error.line(), 14); // entry 3 (refine)'s node: 5 + 3 * 3
  EXPECT_EQ(error.key(), "process[3].node");
  EXPECT_TRUE(says(error, "channels 'images' and 'matched' would both need the link from a to b"))
      << error.what();
  EXPECT_TRUE(says(error, "one channel on each direction of a link")) << error.what();
}

TEST_F(PlacementFile, ChannelOverABrokenWireIsAnErrorNamingTheWire) {
  Places places = bench_split();
  // motion placed first, drive later: the later one is reported, whichever end it is.
  std::swap(places[7], places[8]);
  places[7].second = "c";
  const PlacementError error = expect_error(placement_text("bench", places), bench());
  EXPECT_EQ(error.line(), 29); // entry 8 (drive)'s node: 5 + 3 * 8
  EXPECT_EQ(error.key(), "process[8].node");
  EXPECT_TRUE(says(error, "channel 'commands' from drive (on b) to motion (on c) has no route"))
      << error.what();
  EXPECT_TRUE(says(error, "the wire joining b and c")) << error.what();
  EXPECT_TRUE(says(error, "is broken")) << error.what();
}

TEST_F(PlacementFile, DeviceUseOnANodeWithoutADeviceWireIsAnError) {
  Places places; // every channel stays on c, but c has no wire to the frame store
  for (const std::string& process : navigation_program_shape().processes)
    places.emplace_back(process, "c");
  const PlacementError error = expect_error(placement_text("bench", places), bench());
  EXPECT_EQ(error.line(), 5);
  EXPECT_EQ(error.key(), "process[0].node");
  EXPECT_TRUE(says(error, "process 'acquire' needs images from the frame store, but its node c "
                          "has no unbroken wire"))
      << error.what();
  EXPECT_TRUE(says(error, "powered nodes with one: a, b")) << error.what();
}

TEST_F(PlacementFile, DeviceUseNeedsThePeerDevicePowered) {
  PlatformSpec platform = bench();
  platform.devices.at(0).powered = false; // the frame store is off: its wires carry nothing
  const PlacementError error = expect_error(placement_text("bench", bench_split()), platform);
  EXPECT_EQ(error.line(), 5);
  EXPECT_EQ(error.key(), "process[0].node");
  EXPECT_TRUE(says(error, "no unbroken wire to a powered frame_store or host device"))
      << error.what();
  EXPECT_TRUE(says(error, "no powered node has one")) << error.what();
}

TEST_F(PlacementFile, TomlSyntaxErrorKeepsItsLine) {
  const PlacementError error = expect_error("[placement]\n"
                                            "platform = \"onboard\"\n"
                                            "[[process]\n",
                                            onboard());
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.key(), "");
  EXPECT_TRUE(says(error, "TOML syntax error")) << error.what();
}

TEST_F(PlacementFile, FolderInsteadOfAFileIsAnErrorNamingIt) {
  const fs::path folder = folder_ / "placement.toml";
  fs::create_directories(folder);
  try {
    load_placement(folder, onboard(), navigation_program_shape());
    FAIL() << "no error";
  } catch (const PlacementError& error) {
    EXPECT_EQ(error.file(), folder.string());
    EXPECT_EQ(error.line(), 0);
    EXPECT_TRUE(says(error, "is a directory; a placement file must be a regular file"))
        << error.what();
  }
}

TEST_F(PlacementFile, ShapeNamingAProcessItDoesNotListIsAProgramError) {
  ProgramShape shape = navigation_program_shape();
  shape.channels.push_back({"steer", "drive", "steering"});
  EXPECT_THROW(load_placement(kPlatforms / "placements" / "onboard.toml", onboard(), shape),
               std::invalid_argument);
}

} // namespace
} // namespace marsokhod::nav_program
