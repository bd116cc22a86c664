// Tests: the emulated timeline read from a hand-written Chrome trace: lanes named by the
// trace's metadata in node and track order, a span per begin and end, times in seconds.

#include "cli/command.hpp"
#include "report/trace_timeline.hpp"
#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;

fs::path write_trace(const std::string& name, const std::string& text) {
  const fs::path file = marsokhod::testing::fresh_folder("timeline", name) / "trace.json";
  std::ofstream(file) << text;
  return file;
}

// Node 2's CPU runs "matching" from 1.5 s to 2.0 s inside "cycle" (0.5 s to 3.0 s); node 1's
// link sends one message from 0.25 s to 0.75 s. Chrome traces count microseconds.
constexpr const char* kTrace = R"({"traceEvents": [
  {"ph": "M", "name": "process_name", "pid": 2, "args": {"name": "module1"}},
  {"ph": "M", "name": "thread_name", "pid": 2, "tid": 1, "args": {"name": "cpu"}},
  {"ph": "M", "name": "process_name", "pid": 1, "args": {"name": "module0"}},
  {"ph": "M", "name": "thread_name", "pid": 1, "tid": 3, "args": {"name": "link0 out"}},
  {"ph": "B", "pid": 2, "tid": 1, "ts": 500000, "name": "cycle"},
  {"ph": "B", "pid": 1, "tid": 3, "ts": 250000, "name": "out 4 bytes"},
  {"ph": "E", "pid": 1, "tid": 3, "ts": 750000},
  {"ph": "B", "pid": 2, "tid": 1, "ts": 1500000, "name": "matching"},
  {"ph": "E", "pid": 2, "tid": 1, "ts": 2000000},
  {"ph": "E", "pid": 2, "tid": 1, "ts": 3000000},
  {"ph": "C", "pid": 1, "ts": 100, "name": "memory", "args": {"bytes": 1}}
]})";

TEST(TraceTimeline, LanesFollowTheTracesNodesAndSpansPairBeginWithEnd) {
  const std::string html = timeline_chart(write_trace("spans", kTrace), "t");
  EXPECT_NE(html.find(R"(const lanes = ["module0 / link0 out","module1 / cpu"];)"),
            std::string::npos)
      << html;
  // Ended in this order: the message, matching (nested), then the cycle.
  EXPECT_NE(html.find(R"(const spans = [[0,0.25,0.75,"out 4 bytes"],[1,1.5,2.0,"matching"],)"
                      R"([1,0.5,3.0,"cycle"]];)"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("of the cycle's 3.000 s"), std::string::npos);
  EXPECT_NE(html.find("<canvas id=\"t\">"), std::string::npos);
}

TEST(TraceTimeline, ATraceWithoutSpansDrawsNothingAndAnythingElseIsRefused) {
  EXPECT_EQ(timeline_chart(write_trace("empty", R"({"traceEvents": []})"), "t"), "");
  const fs::path not_trace = write_trace("other", R"({"events": []})");
  try {
    (void)timeline_chart(not_trace, "t");
    ADD_FAILURE() << "a JSON file without traceEvents was read as a trace";
  } catch (const CommandError& error) {
    EXPECT_NE(std::string(error.what()).find(not_trace.string() + ": not a Chrome trace"),
              std::string::npos)
        << error.what();
  }
  EXPECT_THROW((void)timeline_chart(write_trace("broken", "{"), "t"), CommandError);
}

} // namespace
} // namespace marsokhod::apps
