// Every number of a platform or processor file is held to its range before it is narrowed or
// converted to ticks: the examples that used to wrap, and the rule over every integer key.

#include "support/test_files.hpp"

#include "marsokhod/emulator/links/link_framing.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/emulator/platform/platform_limits.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace marsokhod::emulator {
namespace {

namespace limits = platform_limits;

using test_support::kPlatforms;

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A valid platform using every optional key, on the processor file `processor`.
std::string full_platform(const std::filesystem::path& processor) {
  return "[platform]\n"
         "name = \"ranges\"\n"
         "processor = \"" +
         processor.string() +
         "\"\n"
         "link_speed_mbps = 10\n"
         "\n"
         "[[node]]\n"
         "name = \"a\"\n"
         "speed_grade = \"T805-30\"\n"
         "external_kb = 256\n"
         "wait_states = 2\n"
         "\n"
         "[[node]]\n"
         "name = \"b\"\n"
         "speed_grade = \"T805-20\"\n"
         "external_kb = 64\n"
         "\n"
         "[[device]]\n"
         "name = \"store\"\n"
         "kind = \"frame_store\"\n"
         "links = 2\n"
         "cameras = 2\n"
         "image_width = 128\n"
         "image_height = 96\n"
         "bits_per_pixel = 8\n"
         "\n"
         "[[wire]]\n"
         "a = \"a.link0\"\n"
         "b = \"b.link3\"\n"
         "speed_mbps = 20\n"
         "\n"
         "[[wire]]\n"
         "a = \"a.link1\"\n"
         "b = \"store.link1\"\n";
}

/// One integer of a file replaced: which key on which line, and the whole new text.
struct Mutation {
  std::string key;
  int line = 0;
  std::string text;
};

/// Every integer literal of `text` (a plain `key = N`, N inside an inline table or an array),
/// each replaced in turn by `value(N)`. Comments are left alone.
std::vector<Mutation> mutations(const std::string& text,
                                const std::function<std::string(std::int64_t)>& value) {
  // key = N | key = { base = N, per_unit = N, ... } | key = [N, N]
  static const std::regex kPlain(R"(^([A-Za-z0-9_-]+) = (\d+)\s*(#.*)?$)");
  static const std::regex kInline(R"(\b(base|per_unit) = (\d+))");
  static const std::regex kArray(R"(^([A-Za-z0-9_-]+) = \[([0-9, ]+)\])");
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  const auto joined = [&](std::size_t at, const std::string& replacement) {
    std::string out;
    for (std::size_t i = 0; i < lines.size(); ++i)
      out += (i == at ? replacement : lines[i]) + "\n";
    return out;
  };
  std::vector<Mutation> found;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const int number = static_cast<int>(i) + 1;
    std::smatch match;
    if (std::regex_match(line, match, kPlain)) {
      const std::string replaced = match[1].str() + " = " + value(std::stoll(match[2].str()));
      found.push_back({match[1].str(), number, joined(i, replaced)});
      continue;
    }
    if (std::regex_search(line, match, kArray)) {
      // The last element of the array.
      const std::string list = match[2].str();
      const auto comma = list.rfind(',');
      const std::string head = comma == std::string::npos ? "" : list.substr(0, comma + 2);
      const std::string last = list.substr(comma == std::string::npos ? 0 : comma + 2);
      found.push_back({match[1].str(), number,
                       joined(i, match[1].str() + " = [" + head + value(std::stoll(last)) + "]")});
      continue;
    }
    for (auto it = std::sregex_iterator(line.begin(), line.end(), kInline);
         it != std::sregex_iterator(); ++it) {
      const std::smatch& inline_match = *it;
      std::string replaced = line;
      replaced.replace(static_cast<std::size_t>(inline_match.position(0)),
                       static_cast<std::size_t>(inline_match.length(0)),
                       inline_match[1].str() + " = " + value(std::stoll(inline_match[2].str())));
      found.push_back({inline_match[1].str(), number, joined(i, replaced)});
    }
  }
  return found;
}

/// The values that used to wrap or overflow: 2^32 + N (an int32 sees N), 2^31 + N (negative
/// as an int32), -1 - N, and the int64 extremes.
const std::vector<std::function<std::string(std::int64_t)>>& wrapping_values() {
  static const std::vector<std::function<std::string(std::int64_t)>> values = {
      [](std::int64_t n) { return std::to_string((std::int64_t{1} << 32) + n); },
      [](std::int64_t n) { return std::to_string((std::int64_t{1} << 31) + n); },
      [](std::int64_t n) { return std::to_string(-1 - n); },
      [](std::int64_t) { return std::to_string(std::numeric_limits<std::int64_t>::max()); },
      [](std::int64_t) { return std::to_string(std::numeric_limits<std::int64_t>::min()); },
  };
  return values;
}

/// Loads `platform` and expects the out-of-range error of `mutation` in `file`.
void expect_out_of_range(const std::filesystem::path& platform, const std::string& file,
                         const Mutation& mutation) {
  try {
    load_platform(platform);
    ADD_FAILURE() << "accepted line " << mutation.line << " of:\n" << mutation.text;
  } catch (const PlatformError& error) {
    EXPECT_EQ(error.file(), file) << error.what();
    EXPECT_EQ(error.key(), mutation.key) << error.what();
    EXPECT_EQ(error.line(), mutation.line) << error.what();
    EXPECT_NE(std::string(error.what()).find("out of range"), std::string::npos) << error.what();
  }
}

TEST(PlatformRanges, TheTestPlatformsAreValid) {
  const auto processor = kPlatforms / "processors" / "t805.toml";
  const PlatformSpec spec =
      load_platform(test_support::write_test_file("full.toml", full_platform(processor)));
  EXPECT_EQ(spec.nodes.at(0).cpu.costs.wait_states, 2);
  EXPECT_EQ(spec.wires.at(0).speed_mbps, 20);
  EXPECT_EQ(spec.devices.at(0).image_height, 96);
  // The rule tests below must find every integer of both files.
  EXPECT_GE(mutations(
                read(processor), [](std::int64_t) { return "0"; })
                .size(),
            80U);
  EXPECT_EQ(mutations(full_platform(processor), [](std::int64_t) { return "0"; }).size(), 10U);
}

TEST(PlatformRanges, EveryIntegerOfTheProcessorFileIsCheckedBeforeItIsNarrowed) {
  const std::string processor = read(kPlatforms / "processors" / "t805.toml");
  for (const auto& value : wrapping_values()) {
    for (const Mutation& mutation : mutations(processor, value)) {
      SCOPED_TRACE(mutation.key + " on line " + std::to_string(mutation.line));
      const auto processor_path =
          test_support::write_test_file("ranges-processor.toml", mutation.text);
      const auto platform = test_support::write_test_file("ranges-uses-processor.toml",
                                                          full_platform(processor_path));
      expect_out_of_range(platform, processor_path.string(), mutation);
    }
  }
}

TEST(PlatformRanges, EveryIntegerOfThePlatformFileIsCheckedBeforeItIsNarrowed) {
  const std::string text = full_platform(kPlatforms / "processors" / "t805.toml");
  for (const auto& value : wrapping_values()) {
    for (const Mutation& mutation : mutations(text, value)) {
      SCOPED_TRACE(mutation.key + " on line " + std::to_string(mutation.line));
      const auto path = test_support::write_test_file("ranges-platform.toml", mutation.text);
      expect_out_of_range(path, path.string(), mutation);
    }
  }
}

/// `text` with the line starting with `prefix` replaced by `replacement`.
std::string with_line(std::string text, const std::string& prefix, const std::string& replacement) {
  const auto at = text.find("\n" + prefix);
  EXPECT_NE(at, std::string::npos) << prefix;
  const auto end = text.find('\n', at + 1);
  text.replace(at + 1, end - at - 1, replacement);
  return text;
}

PlatformError processor_error(const std::string& prefix, const std::string& replacement) {
  const std::string processor =
      with_line(read(kPlatforms / "processors" / "t805.toml"), prefix, replacement);
  const auto processor_path = test_support::write_test_file("example-processor.toml", processor);
  try {
    load_platform(
        test_support::write_test_file("example-platform.toml", full_platform(processor_path)));
  } catch (const PlatformError& error) {
    EXPECT_EQ(error.file(), processor_path.string());
    return error;
  }
  ADD_FAILURE() << "accepted " << replacement;
  return PlatformError("", 0, "", "");
}

TEST(PlatformRanges, CostTableBaseOfTwoToThe31IsRefusedNotNegative) {
  // As an int32 it was -2^31: Commstime got faster.
  const PlatformError error = processor_error("in = ", "in = { base = 2147483648, per_unit = 2 }");
  EXPECT_EQ(error.key(), "base");
  EXPECT_NE(std::string(error.what()).find("between 0 and 1000"), std::string::npos)
      << error.what();
  EXPECT_NE(std::string(error.what()).find("'in'"), std::string::npos) << error.what();
}

TEST(PlatformRanges, WaitStatesAtTwoToThe32IsRefusedNotZero) {
  std::string text = full_platform(kPlatforms / "processors" / "t805.toml");
  text = with_line(text, "wait_states = 2", "wait_states = 4294967296");
  const auto path = test_support::write_test_file("wait.toml", text);
  try {
    load_platform(path);
    FAIL() << "wait_states = 2^32 accepted";
  } catch (const PlatformError& error) {
    EXPECT_EQ(error.key(), "wait_states");
    EXPECT_NE(std::string(error.what()).find("4294967296 is out of range"), std::string::npos)
        << error.what();
  }
}

TEST(PlatformRanges, WireSpeedThatWouldWrapToAT805SpeedIsRefused) {
  // 2^32 + 10 narrowed to an int is 10, a T805 speed.
  std::string text = full_platform(kPlatforms / "processors" / "t805.toml");
  text = with_line(text, "speed_mbps = 20", "speed_mbps = 4294967306");
  EXPECT_THROW(load_platform(test_support::write_test_file("wire-speed.toml", text)),
               PlatformError);
}

TEST(PlatformRanges, ProcessorCountsThatWouldWrapAreRefused) {
  EXPECT_EQ(processor_error("links = ", "links = 4294967300").key(), "links");
  EXPECT_EQ(
      processor_error("external_access_cycles = ", "external_access_cycles = 4294967299").key(),
      "external_access_cycles");
  EXPECT_EQ(processor_error("links = ", "links = 5").key(), "links"); // a node models 4 links
  EXPECT_EQ(processor_error("external_access_cycles = ", "external_access_cycles = 2").key(),
            "external_access_cycles"); // the EMI takes at least 3 cycles
}

TEST(PlatformRanges, HugeTimesAreRefusedBeforeTheyBecomeTicks) {
  // A cycle of INT64_MAX ps printed "-0.000 us"; timeslice_ns * 1000 overflowed.
  EXPECT_EQ(processor_error("T805-30 = ", "T805-30 = 9223372036854775807").key(), "T805-30");
  EXPECT_EQ(processor_error("T805-30 = ", "T805-30 = 1").key(), "T805-30");
  EXPECT_EQ(processor_error("timeslice_ns = ", "timeslice_ns = 9223372036854776").key(),
            "timeslice_ns");
  EXPECT_EQ(processor_error("high_timer_tick_ns = ", "high_timer_tick_ns = 1000001").key(),
            "high_timer_tick_ns");
  EXPECT_EQ(
      processor_error("ack_turnaround_ps = ", "ack_turnaround_ps = 9223372036854775807").key(),
      "ack_turnaround_ps");
}

TEST(PlatformRanges, RealNumbersMustBeFiniteAndInRange) {
  for (const std::string value : {"1e300", "-1.0", "nan", "inf", "-inf", "1000.5"}) {
    SCOPED_TRACE(value);
    const PlatformError error = processor_error("ack_delay_bits = ", "ack_delay_bits = " + value);
    EXPECT_EQ(error.key(), "ack_delay_bits");
  }
  EXPECT_EQ(processor_error("data_packet_bits = ", "data_packet_bits = 0.5").key(),
            "data_packet_bits");
}

/// The shipped processor file with every time at the largest value its range allows.
std::string slowest_processor() {
  std::string text = read(kPlatforms / "processors" / "t805.toml");
  const auto set = [&](const std::string& key, std::int64_t value) {
    text = with_line(text, key + " = ", key + " = " + std::to_string(value));
  };
  set("timeslice_ns", limits::kMaxTimesliceNs);
  set("slices_before_deschedule", limits::kMaxSlicesBeforeDeschedule);
  set("high_timer_tick_ns", limits::kMaxTimerTickNs);
  set("low_timer_tick_ns", limits::kMaxTimerTickNs);
  set("external_access_cycles", limits::kMaxExternalAccessCycles);
  set("event_latency_cycles", limits::kMaxInstructionCycles);
  set("event_latency_max_cycles", limits::kMaxInstructionCycles);
  set("T805-30", limits::kMaxCyclePs);
  set("ack_turnaround_ps", limits::kMaxAckTurnaroundPs);
  set("data_packet_bits", static_cast<std::int64_t>(limits::kMaxLinkBits));
  set("mul", limits::kMaxInstructionCycles);
  text = with_line(text, "link_speeds_mbps = ", "link_speeds_mbps = [1, 10]");
  return text;
}

TEST(PlatformRanges, TheLargestTimesConvertToTicksWithoutOverflow) {
  const auto processor =
      test_support::write_test_file("slowest-processor.toml", slowest_processor());
  std::string text = full_platform(processor);
  text = with_line(text, "wait_states = 2", "wait_states = 64");
  text = with_line(text, "speed_mbps = 20", "speed_mbps = 1");
  const PlatformSpec spec = load_platform(test_support::write_test_file("slowest.toml", text));
  const NodeSpec& node = spec.nodes.at(0);
  EXPECT_EQ(node.cpu.cycle, 1'000'000);
  EXPECT_EQ(node.cpu.timeslice, 1'000'000'000'000);
  EXPECT_EQ(node.cpu.high_timer_tick, 1'000'000'000);
  const LinkTiming timing = LinkTiming::from(spec.link_timing, 1);
  EXPECT_EQ(timing.bit, 1'000'000);
  EXPECT_EQ(timing.data_packet, 1'000 * 1'000'000);
  EXPECT_GT(timing.ack_turnaround, 0);

  // The slowest instruction at the slowest clock, charged for real.
  Kernel kernel;
  Node emulated(kernel, node);
  Tick done = -1;
  emulated.spawn("worker", [&] {
    emulated.compute(InstructionMix().add(Instruction::mul, 1000));
    done = kernel.now();
  });
  kernel.run();
  EXPECT_EQ(done, Tick{1000} * 1000 * 1'000'000);
}

TEST(PlatformRanges, AbsurdDeviceSizesAreRefused) {
  const std::string text = full_platform(kPlatforms / "processors" / "t805.toml");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"links = 2", "links = 33"},
      {"cameras = 2", "cameras = 257"},
      {"image_width = 128", "image_width = 2049"},
      {"image_height = 96", "image_height = 0"},
      {"bits_per_pixel = 8", "bits_per_pixel = 12"},
  };
  for (const auto& [line, replacement] : cases) {
    SCOPED_TRACE(replacement);
    const auto path =
        test_support::write_test_file("device.toml", with_line(text, line, replacement));
    try {
      load_platform(path);
      ADD_FAILURE() << "accepted";
    } catch (const PlatformError& error) {
      EXPECT_EQ(error.key(), replacement.substr(0, replacement.find(' ')));
    }
  }
}

TEST(PlatformRanges, MoreNodesThanTheLimitAreRefused) {
  std::string text = full_platform(kPlatforms / "processors" / "t805.toml");
  for (std::size_t i = 0; i < limits::kMaxNodes; ++i)
    text += "\n[[node]]\nname = \"n" + std::to_string(i) +
            "\"\nspeed_grade = \"T805-30\"\nexternal_kb = 1\n";
  const auto path = test_support::write_test_file("many.toml", text);
  try {
    load_platform(path);
    FAIL() << "accepted " << limits::kMaxNodes + 2 << " nodes";
  } catch (const PlatformError& error) {
    EXPECT_EQ(error.key(), "node");
    EXPECT_NE(std::string(error.what()).find("at most 1024"), std::string::npos) << error.what();
  }
}

TEST(PlatformRanges, NamesAreShortAndPlain) {
  const std::string text = full_platform(kPlatforms / "processors" / "t805.toml");
  for (const std::string& name : {std::string("a b"), std::string("a.b"), std::string("a\\u0007"),
                                  std::string(""), std::string(65, 'x')}) {
    SCOPED_TRACE(name);
    const auto path = test_support::write_test_file(
        "name.toml", with_line(text, "name = \"b\"", "name = \"" + name + "\""));
    try {
      load_platform(path);
      ADD_FAILURE() << "accepted";
    } catch (const PlatformError& error) {
      EXPECT_EQ(error.key(), "name");
    }
  }
}

} // namespace
} // namespace marsokhod::emulator
