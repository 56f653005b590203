// SPDX-License-Identifier: MIT
#include "app/run_jobs.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sched.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <map>
#include <thread>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "io/run_progress.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace silodem::app {
namespace {

std::atomic<int> g_stop{0};
extern "C" void on_stop_signal(int sig) {
  g_stop.store(sig);
}

using Clock = std::chrono::steady_clock;

struct Child {
  std::size_t job;
  Clock::time_point start;
};

// The environment of a child: ours, with OMP_WAIT_POLICY=passive unless it is set (children
// side by side must not spin on each other's cores).
std::vector<std::string> child_environment() {
  std::vector<std::string> env;
  bool has_wait_policy = false;
  for (char** e = environ; *e; ++e) {
    env.emplace_back(*e);
    if (std::strncmp(*e, "OMP_WAIT_POLICY=", 16) == 0) has_wait_policy = true;
  }
  if (!has_wait_policy) env.emplace_back("OMP_WAIT_POLICY=passive");
  return env;
}

std::vector<char*> pointers(std::vector<std::string>& v) {
  std::vector<char*> p;
  for (auto& s : v) p.push_back(s.data());
  p.push_back(nullptr);
  return p;
}

// Starts `args` (args[0] a name for the executable; the binary run is /proc/self/exe, this very
// build even if its file was replaced since) with stdout and stderr appended to `log`. The child
// is in its own process group (a Ctrl-C reaches only the runner, which forwards one SIGTERM) and
// dies with its parent. SIGINT, SIGTERM and SIGHUP are blocked from before the fork until the
// child has reset their handlers, so a signal forwarded at once is not swallowed by ours.
pid_t start_child(std::vector<std::string> args, std::vector<std::string> env,
                  const fs::path& log) {
  const pid_t parent = getpid();
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(fmt::format("cannot open '{}'", log.string()));
  const std::vector<char*> argv = pointers(args), envp = pointers(env);
  sigset_t block, old;
  sigemptyset(&block);
  sigaddset(&block, SIGINT), sigaddset(&block, SIGTERM), sigaddset(&block, SIGHUP);
  sigprocmask(SIG_BLOCK, &block, &old);
  const pid_t pid = fork();
  if (pid == 0) {  // only async-signal-safe calls from here to exec
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);
    const int null = open("/dev/null", O_RDONLY);
    if (null >= 0) dup2(null, STDIN_FILENO), close(null);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGHUP, SIG_DFL);
    sigprocmask(SIG_SETMASK, &old, nullptr);
    execve("/proc/self/exe", argv.data(), envp.data());
    static const char msg[] = "silodem study: could not start the run (execve failed)\n";
    [[maybe_unused]] const auto n = write(STDERR_FILENO, msg, sizeof msg - 1);
    _exit(127);
  }
  sigprocmask(SIG_SETMASK, &old, nullptr);
  close(fd);
  if (pid < 0) throw std::runtime_error("fork failed");
  return pid;
}

// The wall time a finished run used over all its sessions (summary.json), or `fallback`.
double run_wall_time(const fs::path& dir, double fallback) {
  try {
    const double w = read_run_metrics(dir).wall_time_s;
    return std::isfinite(w) ? w : fallback;
  } catch (const std::exception&) {
    return fallback;
  }
}

// The last non-empty line of a log (for an error message).
std::string last_line(const fs::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

}  // namespace

int default_threads() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, int(std::thread::hardware_concurrency()));
}

JobRunner::JobRunner(int threads, int jobs, fs::path log_dir, bool reports)
    : jobs_(std::max(1, jobs)),
      per_job_(std::max(1, threads / std::max(1, jobs))),
      log_dir_(std::move(log_dir)),
      reports_(reports) {
  g_stop.store(0);
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  std::signal(SIGHUP, on_stop_signal);
  std::signal(SIGCHLD, SIG_DFL);  // an inherited SIG_IGN would reap the children for us
}

JobRunner::~JobRunner() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  std::signal(SIGHUP, SIG_DFL);
}

bool JobRunner::interrupted() const {
  return g_stop.load() != 0;
}

void JobRunner::lock(const fs::path& dir) {
  fs::create_directories(dir);
  const fs::path file = dir / ".lock";
  // Held (never closed) until the process ends; not inherited by the children (O_CLOEXEC).
  const int fd = open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError({}, "--out", fmt::format("cannot open '{}'", file.string()));
  // Retried for a moment: `--status` (locked) holds a shared lock for an instant to test it.
  bool got = false;
  for (int tries = 0; tries < 20 && !got; ++tries) {
    got = flock(fd, LOCK_EX | LOCK_NB) == 0;
    if (!got && errno != EWOULDBLOCK) break;
    if (!got) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!got) {
    close(fd);
    throw InputError({}, "--out",
                     fmt::format("'{}' is in use by another silodem study or calibration (it "
                                 "holds {}); wait for it or stop it first",
                                 dir.string(), file.string()));
  }
}

bool JobRunner::locked(const fs::path& dir) {
  const fs::path file = dir / ".lock";
  const int fd = open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  // A shared lock is refused while a study holds its exclusive one; released by the close.
  const bool held = flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  close(fd);
  return held;
}

std::vector<JobOutcome> JobRunner::run(
    const std::vector<RunJob>& jobs, const std::function<void(std::size_t)>& on_done,
    const std::function<void(std::size_t, std::size_t, double)>& status) {
  fs::create_directories(log_dir_);
  const std::string exe = "silodem";  // argv[0]; the binary is /proc/self/exe
  const std::vector<std::string> env = child_environment();
  std::vector<JobOutcome> out(jobs.size());
  std::deque<std::size_t> pending;
  std::size_t done = 0;
  double wall_sum = 0.0;  // of the finished runs, for the ETA
  int timed = 0;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    out[i].state = run_state(jobs[i].dir);
    if (out[i].state == RunState::Finished || out[i].state == RunState::Failed) {
      ++done;
      // A failed run stopped early: its wall time says nothing about a run's length.
      const double w = out[i].state == RunState::Finished ? run_wall_time(jobs[i].dir, std::nan(""))
                                                          : std::nan("");
      if (std::isfinite(w)) wall_sum += w, ++timed;
      on_done(i);
    } else {
      pending.push_back(i);
    }
  }
  std::map<pid_t, Child> running;
  bool forwarded = false;
  std::string input_error;
  auto last_status = Clock::now() - std::chrono::seconds(10);
  // Whatever goes wrong here (a log that cannot be opened, a full disk), the running children
  // are asked to checkpoint and are waited for before the error goes up.
  try {
    while (!pending.empty() || !running.empty()) {
      if ((g_stop.load() || !input_error.empty()) && !forwarded) {
        for (const auto& [pid, c] : running) kill(-pid, SIGTERM);  // each writes its checkpoint
        forwarded = true;
        pending.clear();
      }
      while (!forwarded && running.size() < std::size_t(jobs_) && !pending.empty()) {
        const std::size_t i = pending.front();
        pending.pop_front();
        const RunJob& j = jobs[i];
        std::vector<std::string> args = {exe, "run"};
        if (out[i].state == RunState::Resumable) {
          args.insert(args.end(), {"--resume", j.dir.string()});  // the checkpoint's thread count
        } else {
          if (out[i].state == RunState::Restart) fs::remove_all(j.dir);
          args.insert(args.end(), {j.case_path, "--out", j.dir.string(), "--threads",
                                   std::to_string(per_job_)});
          for (const auto& s : j.overrides) args.insert(args.end(), {"--set", s});
        }
        if (!reports_) args.emplace_back("--no-report");
        const pid_t pid = start_child(args, env, log_dir_ / (j.name + ".log"));
        running.emplace(pid, Child{i, Clock::now()});
      }
      int wstatus = 0;
      const pid_t pid = running.empty() ? 0 : waitpid(-1, &wstatus, WNOHANG);
      if (pid > 0 && running.count(pid)) {
        const Child c = running.at(pid);
        running.erase(pid);
        const std::size_t i = c.job;
        out[i].exit_code = WIFEXITED(wstatus)
                               ? WEXITSTATUS(wstatus)
                               : 128 + (WIFSIGNALED(wstatus) ? WTERMSIG(wstatus) : 0);
        out[i].state = run_state(jobs[i].dir);
        if (out[i].exit_code == kExitInput && input_error.empty())
          input_error = fmt::format("run {} refused its input: {} (log: {})", jobs[i].name,
                                    last_line(log_dir_ / (jobs[i].name + ".log")),
                                    (log_dir_ / (jobs[i].name + ".log")).string());
        if (out[i].state == RunState::Finished || out[i].state == RunState::Failed) {
          ++done;
          if (out[i].state == RunState::Finished) {
            wall_sum += run_wall_time(
                jobs[i].dir, std::chrono::duration<double>(Clock::now() - c.start).count());
            ++timed;
          }
          on_done(i);
        }
      } else if (pid < 0 && errno == ECHILD) {
        running.clear();  // reaped behind our back: their directories tell what happened
      } else if (pid <= 0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
      if (Clock::now() - last_status > std::chrono::seconds(1)) {
        last_status = Clock::now();
        std::vector<double> left, elapsed, totals;
        for (const auto& [child_pid, c] : running) {
          const auto p = read_run_progress(jobs[c.job].dir);
          const double eta = p ? p->eta_s : std::nan("");
          left.push_back(eta);
          elapsed.push_back(p && std::isfinite(p->wall_s)
                                ? p->wall_s
                                : std::chrono::duration<double>(Clock::now() - c.start).count());
          if (std::isfinite(eta)) totals.push_back(elapsed.back() + eta);
        }
        double mean_run = std::nan("");
        if (timed > 0) {
          mean_run = wall_sum / timed;
        } else if (!totals.empty()) {
          mean_run = 0.0;
          for (double x : totals) mean_run += x / double(totals.size());
        }
        status(done, running.size(), runs_eta(left, elapsed, pending.size(), mean_run, jobs_));
      }
    }
  } catch (...) {
    for (const auto& [pid, c] : running) kill(-pid, SIGTERM);
    for (const auto& [pid, c] : running) waitpid(pid, nullptr, 0);
    throw;
  }
  if (!input_error.empty()) throw InputError({}, "", input_error);
  return out;
}

}  // namespace silodem::app
