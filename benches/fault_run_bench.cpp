// Single-fault runs of the shipped campaigns: the host time of one run (an onboard cycle with its
// heartbeats, a fault and what the overswitch does about it, judged against the fault-free run)
// for the hang-power, links, seu-cruise and seu-edac campaigns; the upset campaigns twice, with
// the runs their fault cannot change skipped (as `campaign` does) and all emulated (--no-skip).
// Runs per minute per core are 60 s over the time; `campaign --jobs 2` prints what two workers
// reach. Target: at least 1,000 runs per minute with two jobs, so at least 500 per core.

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/eval/campaign/campaign_runner.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/overswitch/campaign/campaign_file.hpp"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>

namespace {

using namespace marsokhod;

struct Campaign {
  overswitch::CampaignSpec spec;
  emulator::PlatformSpec platform;
  nav_program::Placement placement;
  std::unique_ptr<eval::CampaignRunner> runner;
};

/// The campaign file `name` and its runner, made once.
const Campaign& campaign(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Campaign>> made;
  std::unique_ptr<Campaign>& c = made[name];
  if (c)
    return *c;
  c = std::make_unique<Campaign>();
  c->spec = overswitch::load_campaign(std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "campaigns" /
                                      (name + ".toml"));
  c->platform = emulator::load_platform(emulator::find_platform_file("onboard.toml"));
  c->placement = nav_program::load_program_placement(c->platform);
  c->runner = std::make_unique<eval::CampaignRunner>(c->spec, c->platform, c->placement, nullptr);
  return *c;
}

void fault_runs(benchmark::State& state, const std::string& name, bool skip) {
  const eval::CampaignRunner& r = *campaign(name).runner;
  std::uint64_t k = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(r.run(k++, nullptr, skip));
  state.counters["runs_per_minute"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * 60.0, benchmark::Counter::kIsRate);
}

void BM_HangPowerFaultRun(benchmark::State& state) {
  fault_runs(state, "hang-power", true);
}
BENCHMARK(BM_HangPowerFaultRun)->Unit(benchmark::kMillisecond);

void BM_LinkFaultRun(benchmark::State& state) {
  fault_runs(state, "links", true);
}
BENCHMARK(BM_LinkFaultRun)->Unit(benchmark::kMillisecond);

void BM_UpsetFaultRun(benchmark::State& state) {
  fault_runs(state, "seu-cruise", true);
}
BENCHMARK(BM_UpsetFaultRun)->Unit(benchmark::kMillisecond);

void BM_UpsetFaultRunEmulatingAll(benchmark::State& state) {
  fault_runs(state, "seu-cruise", false);
}
BENCHMARK(BM_UpsetFaultRunEmulatingAll)->Unit(benchmark::kMillisecond);

void BM_UpsetFaultRunUnderEdac(benchmark::State& state) {
  fault_runs(state, "seu-edac", true);
}
BENCHMARK(BM_UpsetFaultRunUnderEdac)->Unit(benchmark::kMillisecond);

} // namespace
