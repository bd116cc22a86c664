// The tally of hand-made run records by class, fault kind, memory region and buffer, and what an
// upset rate makes of it.

#include "marsokhod/eval/faults/campaign_tally.hpp"
#include "marsokhod/eval/faults/upset_exposure.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace marsokhod::eval {
namespace {

using Kind = overswitch::Fault::Kind;

RunRecord record(Kind kind, Outcome outcome) {
  RunRecord r;
  r.fault.kind = kind;
  r.fault.module = "module0";
  r.verdict.outcome = outcome;
  return r;
}

RunRecord upset(Outcome outcome, const std::string& region, const std::string& buffer,
                emulator::UpsetEffect edac) {
  RunRecord r = record(Kind::upset, outcome);
  r.fault.hit = MemoryHitRecord{0x80001000, 3, false, region, buffer, std::nullopt, edac};
  return r;
}

std::vector<RunRecord> campaign() {
  std::vector<RunRecord> runs;
  RunRecord hang = record(Kind::hang, Outcome::recovered);
  hang.verdict.activated = hang.verdict.detected = true;
  hang.verdict.detection_latency_s = 0.15;
  hang.verdict.path_equals_golden = true;
  runs.push_back(hang);
  RunRecord power = record(Kind::power_loss, Outcome::recovered);
  power.verdict.activated = power.verdict.detected = true;
  power.verdict.detection_latency_s = 0.12;
  power.verdict.telemetry_lost = true;
  runs.push_back(power);
  runs.push_back(upset(Outcome::masked, "external", "left image, 128 rows x 128 px x 1 B",
                       emulator::UpsetEffect::corrected));
  runs.back().verdict.detected = true; // the EDAC: detected, not activated, no latency
  runs.push_back(upset(Outcome::unsafe, "external", "left image, 64 rows x 64 px x 1 B",
                       emulator::UpsetEffect::flipped));
  runs.back().verdict.activated = true;
  runs.push_back(
      upset(Outcome::masked, "on-chip", "workspace of matching", emulator::UpsetEffect::flipped));
  // The fault-free path of this scene is unsafe already: the navigation's own error, so the
  // run is masked (its path is that one) and not judged.
  RunRecord golden_unsafe =
      upset(Outcome::masked, "external", "free", emulator::UpsetEffect::flipped);
  golden_unsafe.verdict.golden_unsafe = golden_unsafe.verdict.unsafe = true;
  runs.push_back(golden_unsafe);
  return runs;
}

TEST(CampaignTally, CountsEachRunOnceByClassAndKind) {
  const CampaignTally t = tally(campaign());
  EXPECT_EQ(t.runs, 6U);
  EXPECT_EQ(t.outcomes[Outcome::recovered], 2U);
  EXPECT_EQ(t.outcomes[Outcome::masked], 3U);
  EXPECT_EQ(t.outcomes[Outcome::unsafe], 1U);
  EXPECT_EQ(t.outcomes.total(), 6U);
  ASSERT_EQ(t.by_kind.size(), 3U);
  EXPECT_EQ(t.by_kind.at("hang")[Outcome::recovered], 1U);
  EXPECT_EQ(t.by_kind.at("power")[Outcome::recovered], 1U);
  EXPECT_EQ(t.by_kind.at("seu").total(), 4U);
}

TEST(CampaignTally, LeavesRunsOnAnUnsafeGoldenPathOutOfTheJudged) {
  const CampaignTally t = tally(campaign());
  EXPECT_EQ(t.golden_unsafe_runs, 1U);
  EXPECT_EQ(t.judged, 5U);
  EXPECT_EQ(t.unsafe, 1U);
}

TEST(CampaignTally, GroupsMemoryFaultsByRegionAndByBufferWithoutItsSize) {
  const CampaignTally t = tally(campaign());
  ASSERT_EQ(t.by_region.size(), 2U);
  EXPECT_EQ(t.by_region.at("external").total(), 3U);
  EXPECT_EQ(t.by_region.at("on-chip")[Outcome::masked], 1U);
  ASSERT_EQ(t.by_buffer.size(), 3U);
  EXPECT_EQ(t.by_buffer.at("left image")[Outcome::masked], 1U);
  EXPECT_EQ(t.by_buffer.at("left image")[Outcome::unsafe], 1U);
  EXPECT_EQ(t.by_buffer.at("free").total(), 1U);
  EXPECT_EQ(t.by_buffer.at("workspace of matching").total(), 1U);
  EXPECT_EQ(t.edac_corrected, 1U);
}

TEST(CampaignTally, CountsDetectionOverTheActivatedRuns) {
  const CampaignTally t = tally(campaign());
  EXPECT_EQ(t.activated, 3U);
  EXPECT_EQ(t.detected, 3U);
  EXPECT_EQ(t.detected_activated, 2U);
  EXPECT_EQ(t.detection_latency_s, (std::vector<double>{0.15, 0.12}));
  EXPECT_EQ(t.telemetry_lost, 1U);
  EXPECT_EQ(t.path_equals_golden, 1U);
}

TEST(BufferGroup, DropsOnlyTheSizeAfterTheLastComma) {
  EXPECT_EQ(buffer_group("left image, 128 rows x 128 px x 1 B"), "left image");
  EXPECT_EQ(buffer_group("census features, left, 128 rows x 128 px x 1 B"),
            "census features, left");
  EXPECT_EQ(buffer_group("pyramid layers 1..3, both eyes"), "pyramid layers 1..3, both eyes");
  EXPECT_EQ(buffer_group("free"), "free");
}

// 1 unsafe of 5 judged at 1e-8 per bit per day over 10^6 bits: 0.01 upsets a day, 3.6525 a
// year, 0.7305 of them unsafe; the interval is the share's Wilson interval times 3.6525.
TEST(UpsetExposure, ScalesTheUnsafeShareByTheUpsetsOfAYear) {
  const CampaignTally t = tally(campaign());
  const UpsetExposure e = upset_exposure(1e-8, 1'000'000, t);
  EXPECT_DOUBLE_EQ(e.upsets_per_day, 0.01);
  EXPECT_NEAR(e.expected_unsafe_per_year, 0.7305, 1e-12);
  const Interval share = wilson_95(1, 5);
  EXPECT_NEAR(e.expected_unsafe_per_year_ci95.low, 3.6525 * share.low, 1e-12);
  EXPECT_NEAR(e.expected_unsafe_per_year_ci95.high, 3.6525 * share.high, 1e-12);
}

} // namespace
} // namespace marsokhod::eval
