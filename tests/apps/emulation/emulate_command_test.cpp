// `marsokhod emulate`: the emulated cycle writes what `marsokhod nav` writes, stops cleanly on a
// memory fault, repeats itself byte for byte, and refuses what it cannot run.
#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using marsokhod::testing::quoted;
using marsokhod::testing::run_marsokhod;
using marsokhod::testing::slurp;

fs::path emulate_folder(const std::string& name) {
  return marsokhod::testing::fresh_folder("marsokhod-emulate-tests", name);
}

const fs::path kStereo = fs::path(MARSOKHOD_SHARED_DATA) / "stereo";

struct Outcome {
  int exit_code = -1;
  nlohmann::json summary;
  std::string err;
};

Outcome emulate(const std::string& arguments) {
  const auto result = run_marsokhod("emulate " + arguments + " --json");
  Outcome outcome{result.exit_code, nlohmann::json(), result.err};
  if (!result.out.empty())
    outcome.summary = nlohmann::json::parse(result.out);
  return outcome;
}

// nav's outputs for a pair, as the reference the emulation must reproduce.
fs::path nav_outputs(const fs::path& left, const fs::path& right, const std::string& extra,
                     const std::string& name) {
  const fs::path out = emulate_folder(name);
  const auto nav = run_marsokhod("nav " + quoted(left) + " " + quoted(right) + " " + extra +
                                 " --out " + quoted(out));
  EXPECT_EQ(nav.exit_code, 0) << nav.err;
  return out;
}

// Either the emulated cycle ran and wrote nav's bytes, or it stopped on a memory fault it
// reports; nothing else is acceptable. Returns whether it ran.
bool same_as_nav_or_memory_fault(const Outcome& run, const fs::path& nav, const fs::path& out,
                                 const std::string& what) {
  if (run.exit_code == 1) {
    EXPECT_FALSE(run.summary.is_null()) << what << ": " << run.err;
    EXPECT_TRUE(run.summary["memory_fault"].is_object()) << what << ": " << run.err;
    return false;
  }
  EXPECT_EQ(run.exit_code, 0) << what << ": " << run.err;
  EXPECT_TRUE(run.summary["memory_fault"].is_null()) << what;
  for (const char* file : {"path.json", "disparity.pfm"})
    EXPECT_EQ(slurp(out / file), slurp(nav / file)) << what << ": " << file;
  return true;
}

// The command writes nav's files where its cycle runs: the emulated cycle itself is held to the
// native one on world seeds 1..20 at both sizes by tests/nav_program/run/world_scene_cycles_test;
// here the files the two commands write are compared on two scenes at each size.
TEST(EmulateCommand, WritesTheSamePathAndDisparityAsNavForWorldSeedsOnBothPlatforms) {
  for (const int size : {128, 256})
    for (const int seed : {1, 2}) {
      const std::string scene = std::to_string(seed) + "-" + std::to_string(size);
      const fs::path world = emulate_folder("world-" + scene);
      ASSERT_EQ(run_marsokhod("world --seed " + std::to_string(seed) + " --size " +
                              std::to_string(size) + " --out " + quoted(world))
                    .exit_code,
                0);
      const fs::path nav = nav_outputs(world / "left.pgm", world / "right.pgm",
                                       "--scene " + quoted(world / "scene.json"), "nav-" + scene);
      for (const char* platform : {"pc-card", "onboard"}) {
        const std::string what = std::string(platform) + " seed " + scene;
        const fs::path out = emulate_folder(std::string("emulated-") + platform);
        const Outcome run =
            emulate("--platform " + std::string(platform) + " --seed " + std::to_string(seed) +
                    " --size " + std::to_string(size) + " --out " + quoted(out));
        const bool ran = same_as_nav_or_memory_fault(run, nav, out, what);
        // The card holds both sizes, the onboard modules the paper's 128 x 128.
        const bool must_run = std::string(platform) == "pc-card" || size == 128;
        EXPECT_TRUE(ran || !must_run) << what;
      }
    }
}

TEST(EmulateCommand, GivenPairWithItsSceneEqualsTheRenderedScene) {
  const fs::path world = emulate_folder("world-given");
  ASSERT_EQ(run_marsokhod("world --seed 4 --size 128 --out " + quoted(world)).exit_code, 0);
  const fs::path rendered = emulate_folder("rendered");
  const fs::path given = emulate_folder("given");
  ASSERT_EQ(emulate("--platform pc-card --seed 4 --out " + quoted(rendered)).exit_code, 0);
  ASSERT_EQ(emulate(quoted(world / "left.pgm") + " " + quoted(world / "right.pgm") + " --scene " +
                    quoted(world / "scene.json") + " --platform pc-card --out " + quoted(given))
                .exit_code,
            0);
  for (const char* file : {"path.json", "disparity.pfm", "zones.png", "range.pfm"})
    EXPECT_EQ(slurp(rendered / file), slurp(given / file)) << file;
}

TEST(EmulateCommand, RealPairsEqualNavWhereTheMemoryHoldsThem) {
  if (!fs::exists(kStereo / "PAIRS.tsv"))
    GTEST_SKIP() << "no real pairs at " << kStereo << " (../shared/data is absent)";
  for (const char* name : {"tsukuba", "venus", "aloe", "rocks1"}) {
    const fs::path left = kStereo / (std::string(name) + "_left.pgm");
    const fs::path right = kStereo / (std::string(name) + "_right.pgm");
    const fs::path nav = nav_outputs(left, right, "", std::string("nav-") + name);
    // On the card as it is, and on a card with 32 MB (a what-if run that must hold them).
    for (const char* memory : {"", " --external-kb 32768"}) {
      const fs::path out = emulate_folder(std::string("real-") + name);
      const Outcome run = emulate(quoted(left) + " " + quoted(right) + " --platform pc-card" +
                                  memory + " --out " + quoted(out));
      const bool ran = same_as_nav_or_memory_fault(run, nav, out, std::string(name) + memory);
      if (std::string(memory).empty())
        continue;
      EXPECT_TRUE(ran) << name << " did not fit 32 MB: " << run.err;
    }
  }
}

TEST(EmulateCommand, MemoryFaultStopsTheCycleNamingNodeProcessAndBuffer) {
  const fs::path out = emulate_folder("fault");
  const fs::path trace = out / "trace.json";
  const Outcome run = emulate("--platform onboard --external-kb 32 --out " + quoted(out) +
                              " --trace " + quoted(trace));
  EXPECT_EQ(run.exit_code, 1);
  ASSERT_TRUE(run.summary["memory_fault"].is_object()) << run.err;
  const nlohmann::json& fault = run.summary["memory_fault"];
  EXPECT_EQ(fault["node"], "module0");
  EXPECT_FALSE(fault["process"].get<std::string>().empty());
  EXPECT_GT(fault["requested_bytes"].get<std::size_t>(), 0U);
  // The message names the node, the process and what the buffer was for.
  EXPECT_NE(run.err.find("memory fault on module0"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("process " + fault["process"].get<std::string>()), std::string::npos);
  EXPECT_NE(run.err.find(fault["what"].get<std::string>()), std::string::npos);
  EXPECT_FALSE(run.summary["found"].get<bool>());
  // Every process's high-water mark is reported, and none exceeds its node's memory.
  ASSERT_EQ(run.summary["processes"].size(), 10U);
  for (const auto& process : run.summary["processes"])
    EXPECT_LE(process["peak_bytes"].get<std::size_t>(), 36U * 1024) << process["name"];
  // The trace up to the fault is a whole JSON document.
  const nlohmann::json events = nlohmann::json::parse(slurp(trace));
  EXPECT_GT(events["traceEvents"].size(), 0U);
  // No products are written after a fault.
  EXPECT_FALSE(fs::exists(out / "path.json"));
}

TEST(EmulateCommand, TwoRunsGiveTheSameTraceAndSummaryApartFromHostTime) {
  // The card; the two modules as shipped, whose link carries the matched bands and whose
  // zones work the terrain out again strip by strip; and the modules with room for the maps.
  for (const std::string platform : {"pc-card", "onboard", "onboard --external-kb 1024"}) {
    std::vector<std::string> traces;
    std::vector<nlohmann::json> summaries;
    for (int run = 0; run < 2; ++run) {
      const fs::path out = emulate_folder("repeat-" + std::to_string(run));
      Outcome outcome = emulate("--platform " + platform + " --seed 3 --out " + quoted(out) +
                                " --trace " + quoted(out / "trace.json"));
      ASSERT_EQ(outcome.exit_code, 0) << platform << ": " << outcome.err;
      outcome.summary.erase("host_seconds");
      outcome.summary.erase("outputs"); // the folders differ by name only
      summaries.push_back(outcome.summary);
      traces.push_back(slurp(out / "trace.json"));
    }
    EXPECT_EQ(summaries[0], summaries[1]) << platform;
    EXPECT_EQ(traces[0], traces[1]) << platform;
    EXPECT_GT(traces[0].size(), 1000U) << platform;
  }
}

TEST(EmulateCommand, TraceHasATrackPerCpuStageAndLinkDirection) {
  const fs::path out = emulate_folder("tracks");
  ASSERT_EQ(emulate("--platform pc-card --seed 2 --out " + quoted(out) + " --trace " +
                    quoted(out / "trace.json"))
                .exit_code,
            0);
  const nlohmann::json trace = nlohmann::json::parse(slurp(out / "trace.json"));
  std::vector<std::string> threads;
  for (const auto& event : trace["traceEvents"])
    if (event.value("ph", "") == "M" && event.value("name", "") == "thread_name")
      threads.push_back(event["args"]["name"]);
  for (const char* track :
       {"cpu", "stage matching", "stage zones", "link0 out", "link0 in", "memory"})
    EXPECT_NE(std::find(threads.begin(), threads.end(), track), threads.end()) << track;
}

TEST(EmulateCommand, SweepRunsOneCyclePerMemorySizeAndWritesItsTableAndPicture) {
  const fs::path out = emulate_folder("sweep");
  const Outcome sweep = emulate(
      "--platform onboard --seed 1 --sweep-external-kb 32,256,1024,640 --out " + quoted(out));
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  const nlohmann::json& points = sweep.summary["sweep"];
  ASSERT_EQ(points.size(), 4U);
  EXPECT_EQ(points[0]["external_kb"], 32);
  // 32 KB cannot hold the first image: no time, the fault named.
  EXPECT_TRUE(points[0]["emulated_seconds"].is_null());
  EXPECT_EQ(points[0]["memory_fault"]["node"], "module0");
  // 256 KB, as shipped, is the same cycle as a plain run; 1 MB keeps the terrain's maps and
  // does less again, so it is faster.
  const Outcome plain = emulate("--platform onboard --seed 1 --out " + quoted(emulate_folder("p")));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(points[1]["emulated_seconds"], plain.summary["emulated_seconds"]);
  EXPECT_FALSE(points[1]["terrain_kept"].get<bool>());
  EXPECT_GT(points[1]["recomputed_units"].get<std::uint64_t>(), 0U);
  EXPECT_TRUE(points[2]["terrain_kept"].get<bool>());
  EXPECT_LT(points[2]["emulated_seconds"].get<double>(),
            points[1]["emulated_seconds"].get<double>());
  EXPECT_LT(points[2]["recomputed_units"].get<std::uint64_t>(),
            points[1]["recomputed_units"].get<std::uint64_t>());
  // 640 KB keeps the maps too: the zones let go of theirs before the path takes its row
  // sweep's buffers (each hand-over is closed by its sender), so the plan's fit holds.
  EXPECT_TRUE(points[3]["memory_fault"].is_null()) << points[3]["memory_fault"];
  EXPECT_TRUE(points[3]["terrain_kept"].get<bool>());
  EXPECT_GE(points[3]["emulated_seconds"].get<double>(),
            points[2]["emulated_seconds"].get<double>());
  EXPECT_LT(points[3]["emulated_seconds"].get<double>(),
            points[1]["emulated_seconds"].get<double>());
  // The files: the JSON printed, a CSV line per size, a PNG picture.
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "sweep.json"))["sweep"], points);
  const std::string csv = slurp(out / "sweep.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  EXPECT_EQ(csv.rfind("external_kb,emulated_seconds,memory_fault", 0), 0U);
  EXPECT_EQ(slurp(out / "sweep.png").substr(1, 3), "PNG");
}

// The fitted style factor is the default and is reported; the table's own style (1) charges
// every unit of work its table cycles, so the cycle is shorter, by at most the factor.
TEST(EmulateCommand, RunsAtTheFittedOccamStyleUnlessToldAnother) {
  const Outcome fitted =
      emulate("--platform pc-card --seed 2 --out " + quoted(emulate_folder("f")));
  const Outcome table =
      emulate("--platform pc-card --seed 2 --occam-style 1 --out " + quoted(emulate_folder("t")));
  ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
  ASSERT_EQ(table.exit_code, 0) << table.err;
  const double factor = fitted.summary["occam_style_factor"];
  EXPECT_GT(factor, 1.0);
  EXPECT_EQ(table.summary["occam_style_factor"], 1.0);
  const double ratio = fitted.summary["emulated_seconds"].get<double>() /
                       table.summary["emulated_seconds"].get<double>();
  EXPECT_GT(ratio, 1.0 + 0.9 * (factor - 1.0));
  EXPECT_LE(ratio, factor);
}

TEST(EmulateCommand, RefusesWhatItCannotRun) {
  const fs::path out = emulate_folder("refusals");
  const struct {
    std::string arguments;
    int exit_code;
    std::string message;
  } cases[] = {
      {"--out " + quoted(out), 2, "--platform"},
      {"--platform no-such-platform --out " + quoted(out), 1, "no-such-platform"},
      {"--platform pc-card --size 200 --out " + quoted(out), 2, "--size"},
      {"--platform pc-card --rig x.toml --out " + quoted(out), 2, "given pair"},
      {"onlyleft.pgm --platform pc-card --out " + quoted(out), 2, "LEFT and RIGHT"},
      {"--platform pc-card --placement /nonexistent.toml --out " + quoted(out), 1,
       "/nonexistent.toml"},
      {"--platform pc-card --external-kb -5 --out " + quoted(out), 2, "--external-kb"},
      {"--platform onboard --sweep-external-kb 64,abc --out " + quoted(out), 2,
       "--sweep-external-kb"},
      {"--platform onboard --sweep-external-kb 0 --out " + quoted(out), 2, "--sweep-external-kb"},
      {"--platform onboard --sweep-external-kb 64 --trace t.json --out " + quoted(out), 2,
       "neither --external-kb nor --trace"},
      {"--platform onboard --sweep-external-kb 64 --external-kb 64 --out " + quoted(out), 2,
       "neither --external-kb nor --trace"},
      {"--platform pc-card --occam-style 0 --out " + quoted(out), 2, "--occam-style"},
      {"--platform pc-card --occam-style fast --out " + quoted(out), 2, "--occam-style"},
  };
  for (const auto& c : cases) {
    const auto result = run_marsokhod("emulate " + c.arguments);
    EXPECT_EQ(result.exit_code, c.exit_code) << c.arguments << ": " << result.err;
    EXPECT_NE(result.err.find(c.message), std::string::npos) << c.arguments << ": " << result.err;
  }
}

} // namespace
