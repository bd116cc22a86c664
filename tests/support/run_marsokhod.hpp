// Test support: running the built marsokhod binary and capturing its output and exit code.
#pragma once

#include <array>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace marsokhod::testing {

/// `path` in single quotes, for the argument strings run_marsokhod passes to the shell.
inline std::string quoted(const std::filesystem::path& path) {
  std::string text = "'";
  text.append(path.string());
  text.push_back('\'');
  return text;
}

/// An empty folder `name` under a root of the test file's own (`suite`) and this process:
/// ctest runs a file's tests side by side, each in its own process.
inline std::filesystem::path fresh_folder(const std::string& suite, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / (suite + "-" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The whole file's bytes (empty when it cannot be read).
inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/// What one run of the `marsokhod` binary produced.
struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs the built `marsokhod` binary with a shell-quoted argument string; stdout and stderr are
/// captured separately through temporary files so neither can block the other. A non-empty
/// `stdout_file` (e.g. /dev/full) receives stdout instead; `out` is then empty.
inline CommandResult run_marsokhod(const std::string& arguments,
                                   const std::string& stdout_file = {}) {
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() / "marsokhod-cli-tests";
  fs::create_directories(dir);
  const std::string stem = std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const fs::path out_path = dir / (stem + ".out");
  const fs::path err_path = dir / (stem + ".err");
  const std::string command = std::string("'") + MARSOKHOD_BINARY + "' " + arguments + " >'" +
                              (stdout_file.empty() ? out_path.string() : stdout_file) + "' 2>'" +
                              err_path.string() + "' </dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  auto slurp = [](const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  };
  result.out = slurp(out_path);
  result.err = slurp(err_path);
  fs::remove(out_path);
  fs::remove(err_path);
  return result;
}

/// Runs the binary with `arguments` (one element each, no shell) and its standard output the
/// write end of a pipe whose read end is already closed: every write fails with EPIPE, with no
/// race against a reader that exits. SIGPIPE is reset to its default in the child, so a binary
/// that does not ignore it dies by the signal (exit_code 128 + SIGPIPE). `out` stays empty.
inline CommandResult run_marsokhod_into_closed_pipe(const std::vector<std::string>& arguments) {
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() / "marsokhod-cli-tests";
  fs::create_directories(dir);
  const fs::path err_path =
      dir / (std::to_string(::getpid()) + "-pipe-" + std::to_string(counter++) + ".err");
  CommandResult result;
  int fds[2];
  if (::pipe(fds) != 0)
    return result;
  ::close(fds[0]);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  std::vector<std::string> words = {MARSOKHOD_BINARY};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words)
    argv.push_back(word.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned =
      posix_spawn(&pid, MARSOKHOD_BINARY, &actions, &attributes, argv.data(), environ);
  ::close(fds[1]);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0)
    return result;
  int status = 0;
  ::waitpid(pid, &status, 0);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream in(err_path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  result.err = text.str();
  fs::remove(err_path);
  return result;
}

} // namespace marsokhod::testing
