// Tests: every registered file reader meets seeded mutations of its valid files cleanly.
// For each reader of the registry (reader_targets.cpp) a fixed number of mutants of its seeds
// must each be accepted (and pass the target's checks) or rejected with a runtime_error naming
// the file; every other outcome is a finding, saved under the build folder with its replay
// command. MARSOKHOD_MUTATIONS overrides the count, MARSOKHOD_FUZZ_SEED the seed.

#include "fuzz/reader_targets.hpp"
#include "fuzz/reader_verdict.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <regex>
#include <string>

namespace marsokhod::fuzz {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kDefaultMutations = 5000;
constexpr std::uint64_t kDefaultSeed = 20260522;
constexpr std::size_t kMaxSavedPerReader = 25;

std::uint64_t from_environment(const char* name, std::uint64_t fallback) {
  const char* text = std::getenv(name);
  return text != nullptr && *text != '\0' ? std::strtoull(text, nullptr, 0) : fallback;
}

// Findings that differ only in numbers or in the input's path are one finding.
std::string signature(const std::string& detail, const fs::path& input) {
  std::string text = detail;
  for (std::size_t at = text.find(input.string()); at != std::string::npos;
       at = text.find(input.string()))
    text.replace(at, input.string().size(), "<file>");
  text = std::regex_replace(text, std::regex("[0-9]+"), "N");
  return text.substr(0, 110);
}

struct Tally {
  std::uint64_t accepted = 0;
  std::uint64_t rejected = 0;
  std::uint64_t findings = 0;
  std::map<std::string, std::pair<std::uint64_t, fs::path>> distinct; ///< count, saved input
};

class ReaderMutation : public ::testing::TestWithParam<std::string> {};

TEST_P(ReaderMutation, AcceptsOrRejectsEveryMutantNamingTheFile) {
  const ReaderTarget& target = *find_reader(GetParam());
  const std::uint64_t count = from_environment("MARSOKHOD_MUTATIONS", kDefaultMutations);
  const std::uint64_t seed = from_environment("MARSOKHOD_FUZZ_SEED", kDefaultSeed);
  const fs::path work = fs::path(MARSOKHOD_FUZZ_OUTPUT) / "reader_work";
  const fs::path findings = fs::path(MARSOKHOD_FUZZ_OUTPUT) / "findings";
  const fs::path input = prepare_input(target, work);
  fs::remove_all(findings / std::string(target.name)); // only this run's findings stay
  const std::vector<Seed> seeds = target.seeds();
  ASSERT_FALSE(seeds.empty());

  HangWatchdog watchdog(std::chrono::seconds(from_environment("MARSOKHOD_FUZZ_HANG_S", 10)));
  for (const Seed& valid : seeds) {
    watchdog.arm(target, input);
    const Verdict verdict = judge_bytes(target, input, valid.bytes);
    watchdog.disarm();
    EXPECT_EQ(verdict.outcome, Outcome::accepted)
        << "seed '" << valid.label << "' is not accepted: " << verdict.detail;
  }

  // A crash leaves its input at `input`; the per-reader stream makes every mutant rebuildable.
  const MutationEngine engine(seed ^ stable_hash(target.name));
  Tally tally;
  for (std::uint64_t i = 0; i < count; ++i) {
    const Bytes bytes = engine.mutate(seeds[i % seeds.size()].bytes, target.syntax, i);
    watchdog.arm(target, input);
    const Verdict verdict = judge_bytes(target, input, bytes);
    watchdog.disarm();
    if (verdict.outcome == Outcome::accepted) {
      ++tally.accepted;
    } else if (verdict.outcome == Outcome::rejected) {
      ++tally.rejected;
    } else {
      ++tally.findings;
      auto& [seen, saved] = tally.distinct[signature(verdict.detail, input)];
      if (seen++ == 0 && tally.distinct.size() <= kMaxSavedPerReader)
        saved = save_finding(target, bytes, verdict, findings);
    }
  }

  std::printf("[ reader   ] %-12s %llu mutations (seed %llu): %llu accepted, %llu rejected, "
              "%llu findings (%zu distinct)\n",
              std::string(target.name).c_str(), static_cast<unsigned long long>(count),
              static_cast<unsigned long long>(seed),
              static_cast<unsigned long long>(tally.accepted),
              static_cast<unsigned long long>(tally.rejected),
              static_cast<unsigned long long>(tally.findings), tally.distinct.size());
  std::string report;
  for (const auto& [what, found] : tally.distinct) {
    report += "\n  " + std::to_string(found.first) + "x " + what;
    if (!found.second.empty()) {
      report += "\n     saved: " + found.second.string() +
                "\n     replay: " + replay_command(target, found.second);
    }
  }
  EXPECT_EQ(tally.findings, 0U) << "findings of reader " << target.name << ":" << report;
}

std::vector<std::string> reader_names() {
  std::vector<std::string> names;
  for (const ReaderTarget& target : reader_targets())
    names.emplace_back(target.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Registry, ReaderMutation, ::testing::ValuesIn(reader_names()),
                         [](const auto& param_info) { return param_info.param; });

} // namespace
} // namespace marsokhod::fuzz
