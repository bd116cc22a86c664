// The verdict rules of docs/testing.md: what a reader may do with a hostile input.
#include "fuzz/reader_verdict.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <array>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cxxabi.h>
#include <memory>
#include <mutex>
#include <new>
#include <system_error>
#include <thread>
#include <typeinfo>

namespace marsokhod::fuzz {
namespace {

namespace fs = std::filesystem;

std::string type_name(const std::type_info& type) {
  int status = 0;
  std::unique_ptr<char, decltype(&std::free)> name(
      abi::__cxa_demangle(type.name(), nullptr, nullptr, &status), &std::free);
  return status == 0 && name ? name.get() : type.name();
}

// Pieces of standard-library and parser messages that must not reach a user (the logic_error
// family's "stoi" and the like are caught by type before messages are looked at).
constexpr std::array<std::string_view, 11> kInternal = {
    "[json.exception",  "basic_string",   "vector::",     "map::at",     "std::",        "_M_",
    "filesystem error", "iostream error", "bad_optional", "bad_variant", "unordered_map"};

// Long messages (a 100 kB line quoted back) are cut in the middle for notes and logs.
std::string shortened(const std::string& text) {
  constexpr std::size_t kKeep = 400;
  if (text.size() <= kKeep)
    return text;
  return fmt::format("{} [... {} characters ...] {}", text.substr(0, kKeep / 2),
                     text.size() - kKeep, text.substr(text.size() - kKeep / 2));
}

Verdict found(const std::string& what) {
  return {Outcome::finding, shortened(what)};
}

Verdict judge_message(const ReaderTarget& target, const fs::path& input, const std::string& what,
                      const std::string& type) {
  // A message may quote the input: a piece the input holds itself proves nothing (libFuzzer
  // learns the pieces from the comparisons here and writes them into inputs).
  const Bytes bytes = file_bytes(input);
  for (const std::string_view piece : kInternal)
    if (what.find(piece) != std::string::npos && bytes.find(piece) == std::string::npos)
      return found(fmt::format("internal message ({}, contains '{}'): {}", type, piece, what));
  const bool names_input = what.find(input.string()) != std::string::npos;
  const bool names_other =
      !target.also_named.empty() &&
      what.find((input.parent_path() / target.also_named).string()) != std::string::npos;
  if (!names_input && !names_other)
    return found(fmt::format("message without the file name ({}): {}", type, what));
  return {Outcome::rejected, shortened(what)};
}

} // namespace

fs::path prepare_input(const ReaderTarget& target, const fs::path& root) {
  const fs::path folder = root / std::string(target.name);
  fs::create_directories(folder);
  if (target.prepare != nullptr)
    target.prepare(folder);
  return folder / std::string(target.file_name);
}

Verdict judge(const ReaderTarget& target, const fs::path& input) {
  try {
    target.read(input);
    return {};
  } catch (const Garbage& garbage) {
    return found("returned garbage: " + garbage.problem);
  } catch (const toml::parse_error& error) {
    return found("toml::parse_error escaped: " + std::string(error.what()));
  } catch (const std::logic_error& error) {
    return found(
        fmt::format("logic_error family ({}): {}", type_name(typeid(error)), error.what()));
  } catch (const std::bad_alloc& error) {
    return found(fmt::format("{}: {}", type_name(typeid(error)), error.what()));
  } catch (const std::system_error& error) {
    return found(fmt::format("system_error ({}): {}", type_name(typeid(error)), error.what()));
  } catch (const std::runtime_error& error) {
    return judge_message(target, input, error.what(), type_name(typeid(error)));
  } catch (const std::exception& error) {
    return found(
        fmt::format("not a runtime_error ({}): {}", type_name(typeid(error)), error.what()));
  } catch (...) {
    return found("an exception of no std type");
  }
}

Verdict judge_bytes(const ReaderTarget& target, const fs::path& input, const Bytes& bytes) {
  write_bytes(input, bytes);
  return judge(target, input);
}

fs::path save_finding(const ReaderTarget& target, const Bytes& bytes, const Verdict& verdict,
                      const fs::path& root) {
  const fs::path folder = root / std::string(target.name);
  fs::create_directories(folder);
  const fs::path saved = folder / fmt::format("{:016x}-{}", stable_hash(bytes), target.file_name);
  write_bytes(saved, bytes);
  write_bytes(fs::path(saved).concat(".txt"),
              fmt::format("reader: {}\nsize: {} bytes\noutcome: {}\nreplay: {}\n", target.name,
                          bytes.size(), verdict.detail, replay_command(target, saved)));
  return saved;
}

std::string replay_command(const ReaderTarget& target, const fs::path& saved) {
  return fmt::format("{} replay {} {}", MARSOKHOD_FUZZ_TOOL, target.name, saved.string());
}

// arm() and disarm() only touch the mutex; the watchdog looks once a second, so that a
// million inputs cost no thread wake-ups.
struct HangWatchdog::State {
  std::chrono::seconds limit;
  std::mutex mutex;
  std::condition_variable stopping;
  bool stop = false;
  const ReaderTarget* target = nullptr;
  fs::path input;
  std::chrono::steady_clock::time_point started;
  std::thread thread;
};

HangWatchdog::HangWatchdog(std::chrono::seconds limit) : state_(new State) {
  state_->limit = limit;
  state_->thread = std::thread([state = state_] {
    std::unique_lock lock(state->mutex);
    while (!state->stopping.wait_for(lock, std::chrono::seconds(1), [&] { return state->stop; })) {
      if (state->target != nullptr &&
          std::chrono::steady_clock::now() - state->started > state->limit) {
        std::fprintf(stderr, "FINDING (hang): reader %s ran over %llds on %s\n  replay: %s\n",
                     std::string(state->target->name).c_str(),
                     static_cast<long long>(state->limit.count()), state->input.c_str(),
                     replay_command(*state->target, state->input).c_str());
        std::fflush(stderr);
        std::_Exit(3);
      }
    }
  });
}

HangWatchdog::~HangWatchdog() {
  {
    std::lock_guard lock(state_->mutex);
    state_->stop = true;
  }
  state_->stopping.notify_all();
  state_->thread.join();
  delete state_;
}

void HangWatchdog::arm(const ReaderTarget& target, const fs::path& input) {
  std::lock_guard lock(state_->mutex);
  state_->target = &target;
  if (state_->input != input)
    state_->input = input;
  state_->started = std::chrono::steady_clock::now();
}

void HangWatchdog::disarm() {
  std::lock_guard lock(state_->mutex);
  state_->target = nullptr;
}

} // namespace marsokhod::fuzz
