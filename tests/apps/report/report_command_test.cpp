// Tests: `marsokhod report` on the folders the commands write: recognised by their JSON, one
// self-contained page, unknown folders refused; and the paper check's precision rule.

#include "report/report_sections.hpp"
#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;
using marsokhod::testing::fresh_folder;
using marsokhod::testing::quoted;
using marsokhod::testing::run_marsokhod;
using marsokhod::testing::slurp;

// The paper writes "8 sec", "10 sec" and "1.3 min": half a unit of the last digit either side.
TEST(PaperCheck, AFigureMatchesWithinHalfAUnitOfThePapersLastDigit) {
  const auto eight = check_against_paper("the stereo reconstruction algorithm takes 8 sec", 8.4);
  ASSERT_TRUE(eight);
  EXPECT_DOUBLE_EQ(eight->low_s, 7.5);
  EXPECT_DOUBLE_EQ(eight->high_s, 8.5);
  EXPECT_TRUE(eight->pass);
  EXPECT_FALSE(check_against_paper("takes 8 sec", 8.6)->pass);
  const auto minutes = check_against_paper("versus 1.3 min in onboard processing", 23.3);
  ASSERT_TRUE(minutes);
  EXPECT_DOUBLE_EQ(minutes->low_s, 75.0);
  EXPECT_DOUBLE_EQ(minutes->high_s, 81.0);
  EXPECT_FALSE(minutes->pass);
  EXPECT_TRUE(check_against_paper("equals 10 sec", 10.4)->pass);
  EXPECT_FALSE(check_against_paper("no figure here", 1.0));
}

// A link or a source outside the page: what a browser would fetch.
bool refers_outside(const std::string& html) {
  static const std::regex kOutside(R"((src|href)\s*=\s*["']?\s*(https?:|//|/|file:))");
  return std::regex_search(html, kOutside);
}

class ReportCommand : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir_ = fresh_folder("report", "runs");
    const auto world = run_marsokhod("world --size 64 --out " + quoted(dir_ / "world"));
    ASSERT_EQ(world.exit_code, 0) << world.err;
    const auto nav =
        run_marsokhod("nav " + quoted(dir_ / "world" / "left.pgm") + " " +
                      quoted(dir_ / "world" / "right.pgm") + " --out " + quoted(dir_ / "nav"));
    ASSERT_EQ(nav.exit_code, 0) << nav.err;
    const auto traverse =
        run_marsokhod("traverse --rocks 0 --goal-m 8 --size 64 --out " + quoted(dir_ / "traverse"));
    ASSERT_EQ(traverse.exit_code, 0) << traverse.err;
    const auto sweep = run_marsokhod("eval traverse --seeds 1..2 --rocks 0,0.05 --goal-m 8 "
                                     "--size 64 --out " +
                                     quoted(dir_ / "sweep"));
    ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
    const auto campaign = run_marsokhod(
        "campaign " + quoted(fs::path(MARSOKHOD_SOURCE_DIR) / "campaigns" / "hang-power.toml") +
        " --runs 4 --seeds 2..2 --out " + quoted(dir_ / "campaign"));
    ASSERT_EQ(campaign.exit_code, 0) << campaign.err;
  }
  static fs::path dir_;
};

fs::path ReportCommand::dir_;

TEST_F(ReportCommand, OnePageHoldsEveryFolderWithItsPicturesAndFetchesNothing) {
  const fs::path page = dir_ / "report.html";
  const auto result =
      run_marsokhod("report " + quoted(dir_ / "world") + " " + quoted(dir_ / "nav") + " " +
                    quoted(dir_ / "traverse") + " --title 'A <test> run' --out " + quoted(page));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string html = slurp(page);
  EXPECT_NE(html.find("<title>A &lt;test&gt; run</title>"), std::string::npos);
  for (const char* section : {"<h2>world: ", "<h2>navigation cycle: ", "<h2>traverse: "})
    EXPECT_NE(html.find(section), std::string::npos) << section;
  // Every PNG of the folders is inside the page; nothing is fetched from anywhere.
  std::size_t pngs = 0;
  for (const char* folder : {"world", "nav", "traverse"})
    for (const auto& entry : fs::directory_iterator(dir_ / folder))
      pngs += entry.path().extension() == ".png" ? 1 : 0;
  std::size_t embedded = 0;
  for (std::size_t at = html.find("data:image/png;base64,"); at != std::string::npos;
       at = html.find("data:image/png;base64,", at + 1))
    ++embedded;
  EXPECT_EQ(embedded, pngs);
  EXPECT_FALSE(refers_outside(html));
}

// The campaign's outcomes and the sweep's success against rock cover are drawn by Chart.js,
// which the page carries itself, once.
TEST_F(ReportCommand, ChartsAreDrawnByTheChartLibraryInsideThePage) {
  const fs::path page = dir_ / "charts.html";
  const auto result = run_marsokhod("report " + quoted(dir_ / "campaign") + " " +
                                    quoted(dir_ / "sweep") + " --out " + quoted(page));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string html = slurp(page);
  const std::size_t library = html.find("Chart.js v3");
  ASSERT_NE(library, std::string::npos);
  EXPECT_EQ(html.find("Chart.js v3", library + 1), std::string::npos) << "carried once";
  for (const char* canvas : {"<canvas id=\"chart-0\">", "<canvas id=\"chart-1\">"})
    EXPECT_NE(html.find(canvas), std::string::npos) << canvas;
  EXPECT_NE(html.find("\"type\":\"line\""), std::string::npos);
  EXPECT_FALSE(refers_outside(html));
}

TEST_F(ReportCommand, AFolderNoCommandWroteIsRefusedNamingIt) {
  const fs::path empty = dir_ / "empty";
  fs::create_directories(empty);
  const auto result = run_marsokhod("report " + quoted(dir_ / "nav") + " " + quoted(empty) +
                                    " --out " + quoted(dir_ / "x.html"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find(empty.string() + ": not an output folder report knows"),
            std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.html"));
  std::ofstream(empty / "path.json") << "{ not json";
  const auto broken =
      run_marsokhod("report " + quoted(empty) + " --out " + quoted(dir_ / "y.html"));
  EXPECT_EQ(broken.exit_code, 1);
  EXPECT_NE(broken.err.find("path.json"), std::string::npos) << broken.err;
}

// A folder that lost a picture its command always writes is refused, not shown with a hole.
TEST_F(ReportCommand, AFolderMissingAPictureItsCommandWritesIsRefusedNamingIt) {
  const fs::path copy = dir_ / "traverse-copy";
  fs::remove_all(copy);
  fs::copy(dir_ / "traverse", copy, fs::copy_options::recursive);
  fs::remove(copy / "map.png");
  const auto result =
      run_marsokhod("report " + quoted(copy) + " --out " + quoted(dir_ / "holes.html"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find((copy / "map.png").string() + ": missing; traverse always writes it"),
            std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(dir_ / "holes.html"));
}

// A JSON file cut short is named with where parsing stopped.
TEST_F(ReportCommand, ATruncatedJsonIsRefusedNamingTheFile) {
  const fs::path copy = dir_ / "traverse-cut";
  fs::remove_all(copy);
  fs::copy(dir_ / "traverse", copy, fs::copy_options::recursive);
  const std::string json = slurp(copy / "traverse.json");
  std::ofstream(copy / "traverse.json", std::ios::trunc) << json.substr(0, json.size() / 2);
  const auto result =
      run_marsokhod("report " + quoted(copy) + " --out " + quoted(dir_ / "cut.html"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find((copy / "traverse.json").string()), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(dir_ / "cut.html"));
}

} // namespace
} // namespace marsokhod::apps
