// Forked workers, one pipe each: a line per run, "!" and a message for a failure.

#include "marsokhod/eval/campaign/job_pool.hpp"

#include "marsokhod/eval/campaign/campaign_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <exception>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace marsokhod::eval {
namespace {

bool write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

[[noreturn]] void work(int fd, std::uint64_t first, std::uint64_t last, std::uint64_t step,
                       const std::function<std::string(std::uint64_t)>& record) {
  int status = 0;
  try {
    for (std::uint64_t k = first; k < last; k += step)
      if (!write_all(fd, fmt::format("{}\t{}\n", k, record(k))))
        break;
  } catch (const std::exception& error) {
    std::string message = error.what();
    std::replace(message.begin(), message.end(), '\n', ' ');
    write_all(fd, fmt::format("!\t{}\n", message));
    status = 1;
  }
  ::close(fd);
  ::_exit(status);
}

struct Worker {
  pid_t pid = -1;
  int fd = -1;
  std::string pending;
};

/// Takes the whole lines out of a worker's buffer into `records`.
void take_lines(Worker& worker, std::uint64_t first, std::vector<std::string>& records,
                std::uint64_t& done, std::string& failure) {
  for (std::size_t end; (end = worker.pending.find('\n')) != std::string::npos;) {
    const std::string line = worker.pending.substr(0, end);
    worker.pending.erase(0, end + 1);
    const std::size_t tab = line.find('\t');
    if (line.starts_with("!\t")) {
      failure = line.substr(2);
      continue;
    }
    const std::uint64_t k = std::stoull(line.substr(0, tab));
    records[k - first] = line.substr(tab + 1);
    ++done;
  }
}

/// Which run a worker died on (the first of its runs with no record) and how.
std::string crash_message(const std::vector<std::string>& records, std::uint64_t first,
                          std::uint64_t last, std::size_t worker, std::size_t workers, int status) {
  std::uint64_t run = first + worker;
  while (run < last && !records[run - first].empty())
    run += workers;
  const std::string how =
      WIFSIGNALED(status)
          ? fmt::format("killed by signal {} ({})", WTERMSIG(status), ::strsignal(WTERMSIG(status)))
          : fmt::format("exited with status {}", WEXITSTATUS(status));
  return fmt::format("a campaign worker stopped at run {}: {}; --replay {} runs it alone", run, how,
                     run);
}

/// Forks up to `jobs` workers for [first, last), worker j taking first + j, first + j + jobs...
std::vector<Worker> start_workers(std::uint64_t first, std::uint64_t last, int jobs,
                                  const std::function<std::string(std::uint64_t)>& record) {
  std::vector<Worker> workers;
  for (int j = 0; j < jobs && first + static_cast<std::uint64_t>(j) < last; ++j) {
    int fds[2];
    if (::pipe(fds) != 0)
      throw CampaignRunError(fmt::format("cannot start a worker: {}", std::strerror(errno)));
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0)
      throw CampaignRunError(fmt::format("cannot start a worker: {}", std::strerror(errno)));
    if (pid == 0) {
      ::close(fds[0]);
      for (const Worker& other : workers)
        ::close(other.fd);
      work(fds[1], first + static_cast<std::uint64_t>(j), last, static_cast<std::uint64_t>(jobs),
           record);
    }
    ::close(fds[1]);
    workers.push_back({pid, fds[0], {}});
  }
  return workers;
}

/// Reads every worker's lines until all have closed their pipes.
void gather(std::vector<Worker>& workers, std::uint64_t first, std::vector<std::string>& records,
            std::uint64_t& done, std::string& failure,
            const std::function<void(std::uint64_t)>& progress) {
  std::vector<pollfd> open;
  for (const Worker& w : workers)
    open.push_back({w.fd, POLLIN, 0});
  std::size_t live = workers.size();
  char buffer[65536];
  while (live > 0) {
    if (::poll(open.data(), open.size(), -1) < 0 && errno != EINTR)
      throw CampaignRunError(fmt::format("waiting for the workers: {}", std::strerror(errno)));
    for (std::size_t i = 0; i < open.size(); ++i) {
      if (open[i].fd < 0 || open[i].revents == 0)
        continue;
      const ssize_t n = ::read(open[i].fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR)
        continue;
      if (n <= 0) {
        ::close(open[i].fd);
        open[i].fd = -1;
        --live;
        continue;
      }
      workers[i].pending.append(buffer, static_cast<std::size_t>(n));
      take_lines(workers[i], first, records, done, failure);
      if (progress)
        progress(done);
    }
  }
}

/// Waits for every worker; how the first that did not exit cleanly ended, or "".
std::string reap(const std::vector<Worker>& workers, const std::vector<std::string>& records,
                 std::uint64_t first, std::uint64_t last) {
  std::string crash;
  for (std::size_t j = 0; j < workers.size(); ++j) {
    int status = 0;
    ::waitpid(workers[j].pid, &status, 0);
    if (crash.empty() && (!WIFEXITED(status) || WEXITSTATUS(status) != 0))
      crash = crash_message(records, first, last, j, workers.size(), status);
  }
  return crash;
}

} // namespace

std::vector<std::string> run_in_jobs(std::uint64_t first, std::uint64_t last, int jobs,
                                     const std::function<std::string(std::uint64_t run)>& record,
                                     const std::function<void(std::uint64_t done)>& progress) {
  std::vector<Worker> workers = start_workers(first, last, jobs, record);
  std::vector<std::string> records(last - first);
  std::uint64_t done = 0;
  std::string failure;
  gather(workers, first, records, done, failure, progress);
  const std::string crash = reap(workers, records, first, last);
  if (!failure.empty())
    throw CampaignRunError(failure);
  if (!crash.empty())
    throw CampaignRunError(crash);
  if (done != last - first)
    throw CampaignRunError(
        fmt::format("a campaign worker stopped after {} of {} runs", done, last - first));
  return records;
}

} // namespace marsokhod::eval
