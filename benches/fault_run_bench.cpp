// Single-fault runs of the hang-power campaign (campaigns/hang-power.toml): the host time of one
// run (an onboard cycle with its heartbeats, a fault, the failover and the restart, judged
// against the fault-free run), and of the fault-free supervised cycle it is judged against.
// Runs per minute per core are 60 s over the first; `campaign --jobs 2` prints what two workers
// reach. Target: at least 1,000 runs per minute with two jobs, so at least 500 per core.

#include "campaign_runner.hpp"

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/occam_port/navigation/navigation_program.hpp"
#include "marsokhod/overswitch/campaign_file.hpp"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

namespace {

using namespace marsokhod;

struct Campaign {
  overswitch::CampaignSpec spec;
  emulator::PlatformSpec platform;
  occam_port::Placement placement;
  std::unique_ptr<apps::CampaignRunner> runner;
};

const Campaign& campaign() {
  static const Campaign made = [] {
    Campaign c;
    c.spec = overswitch::load_campaign(std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "campaigns" /
                                       "hang-power.toml");
    c.platform = emulator::load_platform(emulator::find_platform_file("onboard.toml"));
    c.placement = occam_port::load_placement(occam_port::default_placement_file(c.platform),
                                             c.platform, occam_port::navigation_program_shape());
    return c;
  }();
  return made;
}

const apps::CampaignRunner& runner() {
  static const std::unique_ptr<apps::CampaignRunner> made = [] {
    const Campaign& c = campaign();
    return std::make_unique<apps::CampaignRunner>(c.spec, c.platform, c.placement, nullptr);
  }();
  return *made;
}

void BM_HangPowerFaultRun(benchmark::State& state) {
  const apps::CampaignRunner& r = runner();
  std::uint64_t k = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(r.run(k++, nullptr));
}
BENCHMARK(BM_HangPowerFaultRun)->Unit(benchmark::kMillisecond);

} // namespace
