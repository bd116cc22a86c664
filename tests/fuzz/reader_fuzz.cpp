// libFuzzer target over the reader registry; the reader is chosen by -reader=NAME.
// Every input is written to a private work folder and judged like the mutation test does; a
// finding aborts, so that libFuzzer saves the input (crash-<sha1>) for replay.
#include "fuzz/reader_targets.hpp"
#include "fuzz/reader_verdict.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using namespace marsokhod::fuzz;

const ReaderTarget* g_target = nullptr;
fs::path g_input;

// The work folder goes at a normal exit; after a finding's abort it stays for inspection.
void remove_work_folder() {
  std::error_code ignored;
  fs::remove_all(g_input.parent_path().parent_path(), ignored);
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  std::string name;
  if (const char* from_environment = std::getenv("MARSOKHOD_FUZZ_READER"))
    name = from_environment;
  for (int i = 1; i < *argc; ++i) {
    const std::string_view arg = (*argv)[i];
    if (arg.starts_with("-reader="))
      name = arg.substr(8);
  }
  g_target = find_reader(name);
  if (g_target == nullptr) {
    std::fprintf(stderr, "reader_fuzz: give -reader=NAME, one of:");
    for (const ReaderTarget& target : reader_targets())
      std::fprintf(stderr, " %s", target.name.data());
    std::fprintf(stderr, "\n");
    std::exit(2);
  }
  const fs::path root = fs::temp_directory_path() /
                        ("marsokhod-reader-fuzz-" + std::to_string(static_cast<long>(getpid())));
  g_input = prepare_input(*g_target, root);
  std::atexit(remove_work_folder);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Bytes bytes(reinterpret_cast<const char*>(data), size);
  const Verdict verdict = judge_bytes(*g_target, g_input, bytes);
  if (verdict.outcome == Outcome::finding) {
    std::fprintf(stderr, "FINDING (%s): %s\n", g_target->name.data(), verdict.detail.c_str());
    std::abort();
  }
  return 0;
}
