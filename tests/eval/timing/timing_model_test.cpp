// The timing model's unfitted figures against an independent computation: the PC card's whole
// cycle is the cycle's nav work, counted by the native navigation, priced by the cost table at
// the fitted style, plus the two camera images over the card's host link; the stereo figure
// ends where the stereo group of processes ends; the sensitivity table's shipped rows are the
// loaded platform files' values.

#include "marsokhod/eval/timing/sensitivity.hpp"
#include "marsokhod/eval/timing/timing_model.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav_program/costs/work_costs.hpp"
#include "marsokhod/world/scene/rendered_site.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace marsokhod::eval {
namespace {

namespace emu = emulator;

/// Seconds the card's CPU spends on the nav work of world seed `seed`'s cycle: each kind's
/// units, counted natively, times the cost table's cycles for one unit on the card (rounded after
/// the style factor, as a period compiler's code takes whole cycles), at the card's clock.
double card_work_seconds(std::uint64_t seed, const emu::PlatformSpec& card, double style) {
  world::SceneDescription scene = world::default_scene(seed, 128);
  const world::RenderedFrame frame = world::render_site(scene);
  nav::NavigationOptions options;
  options.attitude = scene.placement.attitude;
  nav::CountingMeter work;
  nav::navigate(frame.images.left, frame.images.right, imaging::StereoRig(scene.rig), options,
                work);
  const emu::NodeSpec& node = card.nodes.front();
  double cycles = 0.0;
  for (std::size_t k = 0; k < nav::kWorkKinds; ++k) {
    const auto kind = static_cast<nav::Work>(k);
    const auto per_unit = static_cast<double>(
        node.cpu.costs.cycles(nav_program::work_mix(kind, 1, /*buffers_external=*/true)));
    cycles += std::round(per_unit * style) * static_cast<double>(work.count(kind));
  }
  return cycles * static_cast<double>(node.cpu.cycle) * 1e-12;
}

class TimingModelTest : public ::testing::Test {
protected:
  static void SetUpTestSuite() { model_ = new TimingModel({1}); }
  static void TearDownTestSuite() { delete model_; }
  static TimingModel* model_;
};
TimingModel* TimingModelTest::model_ = nullptr;

// The card runs every process on its one T805, so its cycle is the CPU's work plus what the CPU
// waits for: the two 128x128 images over the 10 Mbit/s host link (each byte an 11-bit data
// packet, 1.1 us), and the hand-overs between processes in memory (a few ms). Those extras are
// well under 1 % of the cycle; the model must be the work plus them, no less and little more.
TEST_F(TimingModelTest, TheCardsCycleIsItsWorkAtTheCostTablesPricePlusTheImagesOverItsLink) {
  const double style = nav_program::kOccamStyleFactor;
  const ModelFigures figures = model_->figures(model_->card(), model_->onboard(), style);
  const double work = card_work_seconds(1, model_->card(), style);
  const double images = 2.0 * 128 * 128 * 11 / 10e6;
  EXPECT_GT(figures.card_cycle.mean, work + images);
  EXPECT_NEAR(figures.card_cycle.mean, work + images, 0.01 * (work + images));
  // One scene: its spread is itself.
  EXPECT_EQ(figures.card_cycle.least, figures.card_cycle.mean);
  EXPECT_EQ(figures.card_cycle.greatest, figures.card_cycle.mean);
}

// A slower clock stretches the card's work in proportion: T805-20 (50 ns) against T805-30.
TEST_F(TimingModelTest, TheCardsWorkScalesWithItsClock) {
  emu::PlatformSpec slow = model_->card();
  for (emu::NodeSpec& node : slow.nodes)
    node.cpu.cycle = slow.speed_grades.at("T805-20");
  const double style = nav_program::kOccamStyleFactor;
  EXPECT_NEAR(card_work_seconds(1, slow, style) / card_work_seconds(1, model_->card(), style),
              50000.0 / static_cast<double>(model_->card().nodes.front().cpu.cycle), 1e-9);
}

TEST(StereoEnd, IsTheLastEndOfTheStereoGroupsStages) {
  nav_program::CycleEmulation run;
  using nav_program::StageGroup;
  run.stages = {{"acquire", StageGroup::stereo, 0, 1 * emu::kSecond},
                {"range", StageGroup::terrain, 5 * emu::kSecond, 7 * emu::kSecond},
                {"refine", StageGroup::stereo, 4 * emu::kSecond, 5 * emu::kSecond},
                {"features", StageGroup::stereo, 1 * emu::kSecond, 2 * emu::kSecond}};
  EXPECT_DOUBLE_EQ(stereo_end(run), 5.0);
}

/// The shipped platform files copied into a folder of their own, with the card's memory
/// changed to 1 MB, found through MARSOKHOD_PLATFORMS while the object lives.
class OneMegabyteCard {
public:
  OneMegabyteCard() {
    namespace fs = std::filesystem;
    folder_ = fs::temp_directory_path() / "marsokhod-sensitivity-test";
    fs::remove_all(folder_);
    fs::copy(fs::path(MARSOKHOD_SOURCE_DIR) / "platforms", folder_, fs::copy_options::recursive);
    std::ifstream in(folder_ / "pc-card.toml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t at = text.find("external_kb = 2048");
    EXPECT_NE(at, std::string::npos);
    text.replace(at, 18, "external_kb = 1024");
    std::ofstream(folder_ / "pc-card.toml") << text;
    ::setenv("MARSOKHOD_PLATFORMS", folder_.c_str(), 1);
  }
  ~OneMegabyteCard() {
    ::unsetenv("MARSOKHOD_PLATFORMS");
    std::filesystem::remove_all(folder_);
  }

private:
  std::filesystem::path folder_;
};

// Each parameter's shipped row is the value the loaded platform files give, first, then the
// period's other values: with a card file of 1 MB, 1 MB is the shipped row and 2 MB a variant.
TEST(Sensitivity, ShippedRowsComeFromTheLoadedPlatformFiles) {
  const OneMegabyteCard files;
  const TimingModel model({1});
  ASSERT_EQ(model.card().nodes.front().memory.external_bytes, 1024U * 1024U);
  const std::vector<SensitivityRow> rows =
      sensitivity(model, nav_program::kOccamStyleFactor, ModelFigures{});
  std::vector<std::pair<std::string, bool>> memory_rows;
  std::map<std::string, std::string> shipped_value;
  std::map<std::string, int> values;
  for (const SensitivityRow& row : rows) {
    ++values[row.parameter];
    if (row.shipped)
      shipped_value[row.parameter] = row.value;
    if (row.parameter == "PC card memory")
      memory_rows.emplace_back(row.value, row.shipped);
  }
  EXPECT_EQ(memory_rows, (std::vector<std::pair<std::string, bool>>{
                             {"1 MB", true}, {"2 MB", false}, {"4 MB", false}}));
  EXPECT_EQ(shipped_value["PC card speed grade"], model.card().nodes.front().speed_grade);
  EXPECT_EQ(shipped_value["link speed"],
            std::to_string(model.card().wires.front().speed_mbps) + " Mbit/s");
  EXPECT_EQ(shipped_value["onboard memory wait states"], "0 (3-cycle)");
  // Every grade the processor file lists is a row; the fitted constant at x0.9 and x1.1.
  EXPECT_EQ(values["PC card speed grade"], static_cast<int>(model.card().speed_grades.size()));
  EXPECT_EQ(values["occam style factor (fitted)"], 2);
}

} // namespace
} // namespace marsokhod::eval
