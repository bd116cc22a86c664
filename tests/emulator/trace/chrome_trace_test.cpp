// Chrome Trace Event JSON output: slices, counters, instants and flows.

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/trace/chrome_trace.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <sstream>
#include <vector>

namespace marsokhod::emulator {
namespace {

using nlohmann::json;

json parse(const std::string& text) {
  return json::parse(text);
}

TEST(ChromeTrace, TimestampsAreMicrosecondsExactToThePicosecond) {
  EXPECT_EQ(trace_timestamp(0), "0.000000");
  EXPECT_EQ(trace_timestamp(1'234'567), "1.234567");
  EXPECT_EQ(trace_timestamp(33'333), "0.033333");
  EXPECT_EQ(trace_timestamp(1'000'000'000'000'000), "1000000000.000000");
}

TEST(ChromeTrace, GroupsBecomeProcessesAndTracksThreadsInDeclarationOrder) {
  std::ostringstream out;
  {
    ChromeTraceWriter writer(out);
    EXPECT_EQ(writer.track("module1", "cpu"), 0U);
    EXPECT_EQ(writer.track("module0", "cpu"), 1U);
    EXPECT_EQ(writer.track("module1", "link0 out"), 2U);
    EXPECT_EQ(writer.track("module1", "cpu"), 0U); // same pair, same track
  }
  const json trace = parse(out.str());
  std::map<std::string, int> pid_of;
  std::map<std::string, int> tid_of;
  for (const json& event : trace["traceEvents"]) {
    if (event["name"] == "process_name")
      pid_of[event["args"]["name"]] = event["pid"];
    if (event["name"] == "thread_name")
      tid_of[std::to_string(event["pid"].get<int>()) + "/" +
             event["args"]["name"].get<std::string>()] = event["tid"];
  }
  EXPECT_EQ(pid_of["module1"], 1);
  EXPECT_EQ(pid_of["module0"], 2);
  EXPECT_EQ(tid_of["1/cpu"], 1);
  EXPECT_EQ(tid_of["1/link0 out"], 2);
  EXPECT_EQ(tid_of["2/cpu"], 1);
}

TEST(ChromeTrace, RecordsBecomeTraceEvents) {
  std::ostringstream out;
  {
    ChromeTraceWriter writer(out);
    const TrackId cpu = writer.track("node0", "cpu");
    const TrackId memory = writer.track("node0", "memory");
    writer.begin_slice(cpu, 1'500'000, "consumer \"main\"");
    writer.end_slice(cpu, 2'000'000);
    writer.counter(memory, 2'000'000, "high_water", 4096);
    writer.instant(cpu, 3'000'000, "memory fault", "process p");
    writer.flow_begin(cpu, 1'500'000, 7);
    writer.flow_end(memory, 2'000'000, 7);
  }
  const json events = parse(out.str())["traceEvents"];
  std::vector<json> records;
  for (const json& event : events)
    if (event["ph"] != "M")
      records.push_back(event);
  ASSERT_EQ(records.size(), 6U);
  EXPECT_EQ(records[0]["ph"], "B");
  EXPECT_EQ(records[0]["name"], "consumer \"main\"");
  EXPECT_DOUBLE_EQ(records[0]["ts"].get<double>(), 1.5);
  EXPECT_EQ(records[1]["ph"], "E");
  EXPECT_DOUBLE_EQ(records[1]["ts"].get<double>(), 2.0);
  EXPECT_EQ(records[2]["ph"], "C");
  EXPECT_EQ(records[2]["args"]["high_water"], 4096);
  EXPECT_EQ(records[3]["ph"], "i");
  EXPECT_EQ(records[3]["args"]["detail"], "process p");
  EXPECT_EQ(records[4]["ph"], "s");
  EXPECT_EQ(records[5]["ph"], "f");
  EXPECT_EQ(records[4]["id"], records[5]["id"]);
}

TEST(ChromeTrace, CloseEndsOpenSlicesAndIgnoresUnmatchedEnds) {
  std::ostringstream out;
  ChromeTraceWriter writer(out);
  const TrackId cpu = writer.track("node0", "cpu");
  writer.end_slice(cpu, 10); // nothing open
  writer.begin_slice(cpu, 20, "a");
  writer.begin_slice(cpu, 30, "b");
  writer.close();
  int balance = 0;
  const json trace = parse(out.str());
  for (const json& event : trace["traceEvents"])
    balance += event["ph"] == "B" ? 1 : event["ph"] == "E" ? -1 : 0;
  EXPECT_EQ(balance, 0);
  EXPECT_THROW(writer.begin_slice(cpu, 40, "late"), std::logic_error);
}

/// A small link scenario traced from start to end.
std::string traced_link_run() {
  std::ostringstream out;
  {
    ChromeTraceWriter writer(out);
    Kernel kernel;
    kernel.set_trace(&writer);
    Cpu& a = kernel.add_cpu("a");
    Cpu& b = kernel.add_cpu("b");
    LinkTiming timing{100'000, 1'100'000, 200'000, 550'000, 300'000, 0};
    Link link(kernel, "a.link0", "b.link0", timing);
    std::vector<std::byte> sent(50, std::byte{0x42});
    std::vector<std::byte> received(50);
    kernel.spawn(a, "sender", [&] {
      link.port(0).output(sent);
      kernel.consume(microseconds(3));
      link.port(0).output(sent);
    });
    kernel.spawn(b, "receiver", [&] {
      link.port(1).input(received);
      link.port(1).input(received);
    });
    kernel.run();
  }
  return out.str();
}

TEST(ChromeTrace, LinkRunTraceIsValidJsonWithBalancedSlicesPerTrack) {
  const json events = parse(traced_link_run())["traceEvents"];
  std::map<std::pair<int, int>, int> open;
  std::map<std::pair<int, int>, std::string> names;
  int transfers = 0;
  int flow_ends = 0;
  for (const json& event : events) {
    flow_ends += event["ph"] == "f" ? 1 : 0;
    const std::pair<int, int> track{event["pid"], event.value("tid", 0)};
    if (event["ph"] == "M" && event["name"] == "thread_name")
      names[track] = event["args"]["name"];
    if (event["ph"] == "B") {
      ++open[track];
      transfers += names[track] == "link0 out" ? 1 : 0;
    }
    if (event["ph"] == "E") {
      --open[track];
      EXPECT_GE(open[track], 0);
    }
  }
  for (const auto& [track, count] : open)
    EXPECT_EQ(count, 0);
  EXPECT_EQ(transfers, 2); // two output messages on a's link0 out
  EXPECT_EQ(flow_ends, 2); // each arrow ends where its last byte arrived
}

TEST(ChromeTrace, IdenticalRunsGiveByteIdenticalTraces) {
  const std::string first = traced_link_run();
  EXPECT_EQ(first, traced_link_run());
  EXPECT_GT(first.size(), 500U);
}

} // namespace
} // namespace marsokhod::emulator
