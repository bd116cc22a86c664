// Platform and processor files: what they describe and every error they can hold.

#include "support/test_files.hpp"

#include "marsokhod/emulator/platform/platform.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace marsokhod::emulator {
namespace {

using test_support::kPlatforms;

/// A small valid platform; each test breaks one thing in it.
std::string base_platform() {
  return "[platform]\n"
         "name = \"test\"\n"
         "processor = \"" +
         (kPlatforms / "processors" / "t805.toml").string() +
         "\"\n"
         "link_speed_mbps = 10\n"
         "\n"
         "[[node]]\n"
         "name = \"a\"\n"
         "speed_grade = \"T805-30\"\n"
         "external_kb = 256\n"
         "\n"
         "[[node]]\n"
         "name = \"b\"\n"
         "speed_grade = \"T805-20\"\n"
         "external_kb = 64\n"
         "powered = false\n"
         "\n"
         "[[wire]]\n"
         "a = \"a.link0\"\n"
         "b = \"b.link3\"\n";
}

/// 1-based line of the first line containing `marker`, counted here independently.
int line_of(const std::string& text, const std::string& marker) {
  const auto at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i)
    line += text[i] == '\n' ? 1 : 0;
  return line;
}

/// Loads `text` and returns the error it must raise.
PlatformError expect_error(const std::string& name, const std::string& text) {
  const auto path = test_support::write_test_file(name, text);
  try {
    load_platform(path);
  } catch (const PlatformError& error) {
    EXPECT_EQ(error.file(), path.string());
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
    return error;
  }
  ADD_FAILURE() << "no error for " << name;
  return PlatformError("", 0, "", "");
}

TEST(Platform, OnboardHasFourModulesTwoPoweredInAFullMesh) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  ASSERT_EQ(onboard.nodes.size(), 4U);
  int powered = 0;
  for (const NodeSpec& node : onboard.nodes) {
    EXPECT_EQ(node.speed_grade, "T805-30");
    EXPECT_EQ(node.cpu.cycle, 33'333);                  // T805.md: -30 = 33.3 ns
    EXPECT_EQ(node.memory.external_bytes, 256U * 1024); // paper: 256 KB per module
    EXPECT_EQ(node.memory.on_chip_bytes, 4096U);
    powered += node.powered ? 1 : 0;
  }
  EXPECT_EQ(powered, 2);
  std::set<std::pair<std::string, std::string>> pairs;
  for (const WireSpec& wire : onboard.wires) {
    EXPECT_EQ(wire.speed_mbps, 10);
    if (!wire.a.device && !wire.b.device)
      pairs.insert(std::minmax(wire.a.owner, wire.b.owner));
  }
  EXPECT_EQ(pairs.size(), 6U); // 4 choose 2: every module talks to the other three
  for (const NodeSpec& node : onboard.nodes) {
    for (int link = 0; link < 4; ++link)
      EXPECT_NE(onboard.wire_at({node.name, link, false}), nullptr) << node.name << link;
    const WireSpec* devices = onboard.wire_at({node.name, 3, false});
    EXPECT_TRUE(devices->a.device || devices->b.device);
  }
  ASSERT_EQ(onboard.devices.size(), 1U);
  EXPECT_EQ(onboard.devices[0].kind, DeviceKind::frame_store);
}

TEST(Platform, PcCardHasOneT805WithAHostLink) {
  const PlatformSpec card = load_platform(kPlatforms / "pc-card.toml");
  ASSERT_EQ(card.nodes.size(), 1U);
  EXPECT_GE(card.nodes[0].memory.external_bytes, 1024U * 1024);
  ASSERT_EQ(card.devices.size(), 1U);
  EXPECT_EQ(card.devices[0].kind, DeviceKind::host);
  const WireSpec* host = card.wire_at({card.nodes[0].name, 0, false});
  ASSERT_NE(host, nullptr);
  EXPECT_TRUE(host->b.device);
}

TEST(Platform, ProcessorFileCarriesTheDataBookTable) {
  const PlatformSpec card = load_platform(kPlatforms / "pc-card.toml");
  const CpuSpec& cpu = card.nodes[0].cpu;
  // T805.md: in/out 2w+19, ldl 2, move 2w+8, timeslice 1.024 ms, timers 1 us / 64 us.
  EXPECT_EQ(cpu.costs[Instruction::in].base, 19);
  EXPECT_EQ(cpu.costs[Instruction::in].per_unit, 2);
  EXPECT_EQ(cpu.costs[Instruction::ldl].base, 2);
  EXPECT_EQ(cpu.costs[Instruction::move].base, 8);
  EXPECT_TRUE(cpu.costs[Instruction::fpmul].fpu);
  EXPECT_EQ(cpu.timeslice, 1'024'000'000);
  EXPECT_EQ(cpu.high_timer_tick, 1'000'000);
  EXPECT_EQ(cpu.low_timer_tick, 64'000'000);
  EXPECT_EQ(cpu.costs.event_latency_cycles, 19);
  EXPECT_EQ(card.link_timing.data_packet_bits, 11.0);
  EXPECT_EQ(card.link_timing.ack_packet_bits, 2.0);
  EXPECT_EQ(card.nodes[0].memory.reserved_on_chip_bytes, 0x70U); // MemStart #80000070
}

TEST(Platform, BasePlatformOfTheTestsIsValid) {
  const PlatformSpec spec =
      load_platform(test_support::write_test_file("base.toml", base_platform()));
  EXPECT_EQ(spec.nodes.size(), 2U);
  EXPECT_EQ(spec.nodes[1].cpu.cycle, 50'000);
  EXPECT_FALSE(spec.nodes[1].powered);
  EXPECT_EQ(spec.wires.at(0).b.link, 3);
}

TEST(Platform, UnknownKeyIsAnErrorWithItsLine) {
  std::string text = base_platform();
  text.replace(text.find("external_kb = 64"), 16, "external_kb = 64\nexternal_mb = 2");
  const PlatformError error = expect_error("unknown.toml", text);
  EXPECT_EQ(error.key(), "external_mb");
  EXPECT_EQ(error.line(), line_of(text, "external_mb"));
}

TEST(Platform, ZeroMemoryIsAnError) {
  std::string text = base_platform();
  text.replace(text.find("external_kb = 64"), 16, "external_kb = 0");
  const PlatformError error = expect_error("zero.toml", text);
  EXPECT_EQ(error.key(), "external_kb");
  EXPECT_EQ(error.line(), line_of(text, "external_kb = 0"));
}

TEST(Platform, LinkToAMissingNodeIsAnError) {
  std::string text = base_platform() + "\n[[wire]]\na = \"a.link1\"\nb = \"c.link0\"\n";
  const PlatformError error = expect_error("missing.toml", text);
  EXPECT_EQ(error.key(), "b");
  EXPECT_EQ(error.line(), line_of(text, "b = \"c.link0\""));
  EXPECT_NE(std::string(error.what()).find("'c'"), std::string::npos) << error.what();
}

TEST(Platform, FifthLinkIsAnError) {
  std::string text = base_platform() + "\n[[wire]]\na = \"a.link4\"\nb = \"b.link0\"\n";
  const PlatformError error = expect_error("fifth.toml", text);
  EXPECT_EQ(error.key(), "a");
  EXPECT_EQ(error.line(), line_of(text, "a = \"a.link4\""));
}

TEST(Platform, LinkWiredTwiceIsAnError) {
  std::string text = base_platform() + "\n[[wire]]\na = \"b.link3\"\nb = \"b.link2\"\n";
  const PlatformError error = expect_error("twice.toml", text);
  EXPECT_EQ(error.key(), "a");
  EXPECT_EQ(error.line(), line_of(text, "a = \"b.link3\""));
  EXPECT_NE(std::string(error.what()).find("already wired"), std::string::npos) << error.what();
}

TEST(Platform, LinkEndWiredTwiceNamesBothLines) {
  std::string text = base_platform() + "\n[[wire]]\na = \"a.link2\"\nb = \"a.link0\"\n";
  const PlatformError error = expect_error("twice-lines.toml", text);
  EXPECT_EQ(error.key(), "b");
  EXPECT_EQ(error.line(), line_of(text, "b = \"a.link0\"")); // the second wiring
  const std::string first = "line " + std::to_string(line_of(text, "a = \"a.link0\""));
  EXPECT_NE(std::string(error.what()).find("a.link0 is already wired on " + first),
            std::string::npos)
      << error.what();
}

TEST(Platform, OnlyTheCanonicalLinkSpellingIsAccepted) {
  // link00 and link-0 used to parse as link 0 and slip past the "already wired" check, which
  // compared the text.
  for (const std::string end :
       {"a.link00", "a.link-0", "a.link+0", "a.link01", "a.link 0", "a.link", "a.link0x", "a.Link0",
        ".link0", "a", "a.b.link0", "a.link99999999999999999999"}) {
    SCOPED_TRACE(end);
    std::string text = base_platform() + "\n[[wire]]\na = \"" + end + "\"\nb = \"b.link0\"\n";
    const PlatformError error = expect_error("spelling.toml", text);
    EXPECT_EQ(error.key(), "a");
    EXPECT_EQ(error.line(), line_of(text, "a = \"" + end + "\""));
  }
}

TEST(Platform, EveryLinkEndIsWiredOnceHoweverTheWiresAreOrdered) {
  // The general rule: each (owner, link) pair at most once, whichever key and wire it is on.
  const std::vector<std::string> ends = {"a.link1", "a.link2", "b.link0", "b.link1"};
  for (const std::string& end : ends) {
    for (const std::string& other : ends) {
      if (other == end)
        continue;
      std::string text = base_platform() + "\n[[wire]]\na = \"" + end + "\"\nb = \"" + other +
                         "\"\n\n[[wire]]\na = \"" + other + "\"\nb = \"b.link2\"\n";
      SCOPED_TRACE(end + " then " + other);
      const PlatformError error = expect_error("once.toml", text);
      EXPECT_EQ(error.key(), "a");
      EXPECT_NE(std::string(error.what()).find("already wired"), std::string::npos) << error.what();
    }
  }
}

TEST(Platform, LinkSpeedOutsideTheT805SettingsIsAnError) {
  std::string text = base_platform() + "speed_mbps = 15\n";
  const PlatformError error = expect_error("speed.toml", text);
  EXPECT_EQ(error.key(), "speed_mbps");
  EXPECT_EQ(error.line(), line_of(text, "speed_mbps = 15"));
}

TEST(Platform, UnknownSpeedGradeIsAnError) {
  std::string text = base_platform();
  text.replace(text.find("T805-20"), 7, "T805-35");
  const PlatformError error = expect_error("grade.toml", text);
  EXPECT_EQ(error.key(), "speed_grade");
  EXPECT_EQ(error.line(), line_of(text, "T805-35"));
}

TEST(Platform, DuplicateNodeNameIsAnError) {
  std::string text = base_platform();
  text.replace(text.find("name = \"b\""), 10, "name = \"a\"");
  const PlatformError error = expect_error("duplicate.toml", text);
  EXPECT_EQ(error.key(), "name");
}

TEST(Platform, MissingRequiredKeyNamesTheTable) {
  std::string text = base_platform();
  text.replace(text.find("speed_grade = \"T805-20\"\n"), 24, "");
  const PlatformError error = expect_error("required.toml", text);
  EXPECT_EQ(error.key(), "speed_grade");
  EXPECT_EQ(error.line(), line_of(text, "[[node]]\nname = \"b\""));
}

TEST(Platform, WrongValueTypeIsAnError) {
  std::string text = base_platform();
  text.replace(text.find("external_kb = 64"), 16, "external_kb = \"64\"");
  const PlatformError error = expect_error("type.toml", text);
  EXPECT_EQ(error.key(), "external_kb");
}

TEST(Platform, TomlSyntaxErrorNamesFileAndLine) {
  std::string text = base_platform() + "[[wire]\n";
  const PlatformError error = expect_error("syntax.toml", text);
  EXPECT_EQ(error.line(), line_of(text, "[[wire]\n"));
}

TEST(Platform, MissingFileIsAnError) {
  EXPECT_THROW(load_platform(kPlatforms / "no-such-platform.toml"), PlatformError);
}

/// The error `load_platform(path)` raises; it must name `file`.
PlatformError load_error(const std::filesystem::path& path) {
  try {
    load_platform(path);
  } catch (const PlatformError& error) {
    return error;
  }
  ADD_FAILURE() << "no error for " << path;
  return PlatformError("", 0, "", "");
}

void expect_in(const PlatformError& error, const std::string& part) {
  EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
}

/// Files that are no regular file of a sane size, none of which may hang or exhaust memory.
std::vector<std::filesystem::path> unreadable_files() {
  // One folder per test and process: CTest runs the tests that share this helper in parallel,
  // and one must not truncate the other's big file while it is being read.
  const std::filesystem::path folder =
      std::filesystem::path(testing::TempDir()) /
      ("unreadable-" + std::to_string(::getpid()) + "-" +
       ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::create_directories(folder);
  const auto fifo = folder / "fifo.toml";
  std::filesystem::remove(fifo);
  EXPECT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto big = folder / "big.toml";
  {
    std::ofstream out(big);
    out << "# padding\n";
  }
  std::filesystem::resize_file(big, (std::uintmax_t{16} << 20) + 1);
  return {folder, fifo, "/dev/zero", big, folder / "absent.toml"};
}

TEST(Platform, UnreadablePlatformFileIsAnErrorNamingItAndWhy) {
  const auto files = unreadable_files();
  const std::vector<std::string> why = {"is a directory", "is a FIFO", "is a device",
                                        "a platform file is at most 16 MiB", "cannot open"};
  for (std::size_t i = 0; i < files.size(); ++i) {
    SCOPED_TRACE(files[i].string());
    const PlatformError error = load_error(files[i]);
    EXPECT_EQ(error.file(), files[i].string());
    expect_in(error, why[i]);
    expect_in(error, "platform file");
  }
}

TEST(Platform, UnreadableProcessorFileIsAProcessorFileErrorAtTheProcessorKey) {
  const auto files = unreadable_files();
  const std::vector<std::string> why = {"is a directory", "is a FIFO", "is a device",
                                        "a processor file is at most 16 MiB", "cannot open"};
  const std::string original = (kPlatforms / "processors" / "t805.toml").string();
  for (std::size_t i = 0; i < files.size(); ++i) {
    SCOPED_TRACE(files[i].string());
    std::string text = base_platform();
    text.replace(text.find(original), original.size(), files[i].string());
    const auto path = test_support::write_test_file("unreadable-processor.toml", text);
    const PlatformError error = load_error(path);
    EXPECT_EQ(error.file(), path.string());
    EXPECT_EQ(error.key(), "processor");
    EXPECT_EQ(error.line(), line_of(text, "processor = "));
    expect_in(error, files[i].string());
    expect_in(error, why[i]);
    expect_in(error, "processor file");
  }
}

TEST(Platform, ProcessorFileErrorsSayProcessorFile) {
  std::ifstream in(kPlatforms / "processors" / "t805.toml");
  std::string processor((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  processor.replace(processor.find("[speed_grades]"), 14, "[speed_grades");
  const auto processor_path = test_support::write_test_file("syntax-processor.toml", processor);
  std::string text = base_platform();
  const std::string original = (kPlatforms / "processors" / "t805.toml").string();
  text.replace(text.find(original), original.size(), processor_path.string());
  const PlatformError error =
      load_error(test_support::write_test_file("uses-syntax-processor.toml", text));
  EXPECT_EQ(error.file(), processor_path.string());
  EXPECT_EQ(error.line(), line_of(processor, "[speed_grades"));
  expect_in(error, "TOML syntax error");
}

TEST(Platform, UnknownInstructionInTheCostTableIsAnError) {
  std::ifstream in(kPlatforms / "processors" / "t805.toml");
  std::string processor((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  processor += "frobnicate = 3\n";
  const auto processor_path = test_support::write_test_file("bad-processor.toml", processor);
  std::string text = base_platform();
  const std::string original = (kPlatforms / "processors" / "t805.toml").string();
  text.replace(text.find(original), original.size(), processor_path.string());
  const auto path = test_support::write_test_file("uses-bad-processor.toml", text);
  try {
    load_platform(path);
    FAIL() << "expected an error";
  } catch (const PlatformError& error) {
    EXPECT_EQ(error.file(), processor_path.string());
    EXPECT_EQ(error.key(), "frobnicate");
    EXPECT_EQ(error.line(), line_of(processor, "frobnicate"));
  }
}

} // namespace
} // namespace marsokhod::emulator
