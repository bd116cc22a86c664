// reader_corpus: lists readers, writes seeds and mutants, replays and shrinks saved findings.
// Usage (docs/testing.md):
//   reader_corpus list
//   reader_corpus seeds READER DIR            valid seeds as DIR/<n>-<file name>
//   reader_corpus mutate READER COUNT SEED DIR  DIR/<i>/READER/<file name> and companion files
//   reader_corpus replay READER FILE          judge FILE as that reader's input (exit 1: finding)
//   reader_corpus shrink READER FILE          smallest input giving the same kind of finding
#include "fuzz/reader_targets.hpp"
#include "fuzz/reader_verdict.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

namespace fs = std::filesystem;
using namespace marsokhod::fuzz;

int usage() {
  std::fputs("usage: reader_corpus list | seeds READER DIR | mutate READER COUNT SEED DIR |\n"
             "       replay READER FILE | shrink READER FILE\n",
             stderr);
  return 2;
}

const char* outcome_name(Outcome outcome) {
  switch (outcome) {
  case Outcome::accepted:
    return "accepted";
  case Outcome::rejected:
    return "rejected";
  default:
    return "FINDING";
  }
}

// The kind of a finding: its first 48 characters with digits dropped, so that shrinking keeps
// the same problem ("returned garbage: device host: links ...") while numbers change.
std::string kind_of(const Verdict& verdict) {
  std::string kind;
  for (const char c : verdict.detail.substr(0, 48))
    if (c < '0' || c > '9')
      kind += c;
  return kind;
}

fs::path replay_folder() {
  return fs::path(MARSOKHOD_FUZZ_OUTPUT) / "replay_work";
}

int replay(const ReaderTarget& target, const fs::path& file) {
  const Bytes bytes = file_bytes(file);
  const fs::path input = prepare_input(target, replay_folder());
  HangWatchdog watchdog(std::chrono::seconds(30));
  watchdog.arm(target, input);
  const Verdict verdict = judge_bytes(target, input, bytes);
  watchdog.disarm();
  std::printf("%s (reader %s, %zu bytes, copied to %s)\n  %s\n", outcome_name(verdict.outcome),
              std::string(target.name).c_str(), bytes.size(), input.c_str(),
              verdict.detail.c_str());
  return verdict.outcome == Outcome::finding ? 1 : 0;
}

// Delta debugging by deletion of chunks, halving the chunk size; a budget bounds the time.
int shrink(const ReaderTarget& target, const fs::path& file) {
  Bytes best = file_bytes(file);
  const fs::path input = prepare_input(target, replay_folder());
  const Verdict first = judge_bytes(target, input, best);
  if (first.outcome != Outcome::finding) {
    std::printf("not a finding: %s\n", first.detail.c_str());
    return 1;
  }
  const std::string kind = kind_of(first);
  int budget = 20000;
  for (std::size_t chunk = std::max<std::size_t>(best.size() / 2, 1); chunk >= 1 && budget > 0;
       chunk /= 2) {
    for (std::size_t at = 0; at < best.size() && budget > 0; --budget) {
      Bytes candidate = best;
      candidate.erase(at, chunk);
      const Verdict verdict = judge_bytes(target, input, candidate);
      if (verdict.outcome == Outcome::finding && kind_of(verdict) == kind)
        best = std::move(candidate);
      else
        at += chunk;
    }
    if (chunk == 1)
      break;
  }
  const fs::path out = fs::path(file).concat(".min");
  write_bytes(out, best);
  const Verdict last = judge_bytes(target, input, best);
  std::printf("%zu bytes -> %zu bytes: %s\n  %s\n", file_bytes(file).size(), best.size(),
              out.c_str(), last.detail.c_str());
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  const std::vector<std::string_view> args(argv + 1, argv + argc);
  if (args.size() == 1 && args[0] == "list") {
    for (const ReaderTarget& target : reader_targets())
      std::printf("%s %s\n", target.name.data(), std::string(target.file_name).c_str());
    return 0;
  }
  if (args.size() < 3)
    return usage();
  const ReaderTarget* target = find_reader(args[1]);
  if (target == nullptr) {
    std::fprintf(stderr, "reader_corpus: no reader '%s' (try: reader_corpus list)\n",
                 std::string(args[1]).c_str());
    return 2;
  }
  try {
    if (args[0] == "seeds" && args.size() == 3) {
      fs::create_directories(std::string(args[2]));
      int n = 0;
      for (const Seed& seed : target->seeds()) {
        write_bytes(fs::path(args[2]) /
                        (std::to_string(n++) + "-" + std::string(target->file_name)),
                    seed.bytes);
      }
      return 0;
    }
    if (args[0] == "mutate" && args.size() == 5) {
      const std::uint64_t count = std::strtoull(std::string(args[2]).c_str(), nullptr, 0);
      const std::uint64_t seed = std::strtoull(std::string(args[3]).c_str(), nullptr, 0);
      const std::vector<Seed> seeds = target->seeds();
      const MutationEngine engine(seed ^ stable_hash(target->name));
      for (std::uint64_t i = 0; i < count; ++i) {
        const fs::path input = prepare_input(*target, fs::path(args[4]) / std::to_string(i));
        write_bytes(input, engine.mutate(seeds[i % seeds.size()].bytes, target->syntax, i));
      }
      return 0;
    }
    if (args[0] == "replay" && args.size() == 3)
      return replay(*target, std::string(args[2]));
    if (args[0] == "shrink" && args.size() == 3)
      return shrink(*target, std::string(args[2]));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "reader_corpus: %s\n", error.what());
    return 1;
  }
  return usage();
}
